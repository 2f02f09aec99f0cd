// Checks of a law's generated kernels on random families: shared by the law tests and
// `pd check-law`, so a new law is verified the same way by both.
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
  // Residual, tangent and JVP are finite (every family).
  bool finite = true;
  // Against central differences: not on a family with a collapsed bond, where the
  // regularised length has a kink far narrower than any difference step.
  bool differenced = true;
  BlockErrors tangent;
  double jvp_error = 0;       // max |jvp - M dy| / max |M dy|
  double momentum_error = 0;  // |sum of forces| / sum |forces|
  // |sum Y_k x f_k| / sum |Y_k||f_k|; judged only when the law claims the balance.
  double angular_momentum_error = 0;
};

// The families of the automatic law tests: interior, free edge and corner, each intact
// and with broken bonds; a regular lattice with bonds at r = delta exactly; and a family
// with one deformed bond collapsed to zero length.
std::vector<FamilyCheck> check_law(const abi::LawDescriptor& law, unsigned seed);

// Whether a family's results pass: the tolerances `pd check-law` and the tests apply.
struct CheckTolerances {
  double tangent = 1e-6, jvp = 1e-10, momentum = 1e-12, angular_momentum = 1e-12;
};
bool passes(const abi::LawDescriptor& law, const FamilyCheck& c, const CheckTolerances& tol = {});

}  // namespace pd::verify
