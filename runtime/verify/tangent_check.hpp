// Checks of a law's generated tangent against central differences of its residual:
// shared by the law tests and `pd check-law`, so a new law is verified the same way.
#pragma once

#include <string>
#include <vector>

#include "verify/random_family.hpp"

namespace pd::verify {

// Relative error of each kind of local block: max |M - M_fd| over the kind's
// entries divided by max |M_fd| over them, so small blocks are judged on their own
// scale. center: (0,0); on_diagonal: (i,i); off_diagonal: (i,k), i != k;
// center_coupling: (0,k) and (i,0).
struct BlockErrors {
  double center = 0, on_diagonal = 0, off_diagonal = 0, center_coupling = 0;
  double worst() const;
};

BlockErrors block_errors(const TestFamily& f, const std::vector<double>& M, const std::vector<double>& Mfd);

struct FamilyCheck {
  std::string description;  // e.g. "interior", "corner, broken bonds"
  int bonds = 0;
  BlockErrors tangent;
  double jvp_error = 0;       // max |jvp - M dy| / max |M dy|
  double momentum_error = 0;  // |sum of forces| / sum |forces|
};

// Tangent blocks, JVP and momentum balance on random families of every kind.
std::vector<FamilyCheck> check_law(const abi::LawDescriptor& law, unsigned seed);

}  // namespace pd::verify
