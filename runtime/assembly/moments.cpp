// Moments for every particle, in parallel (each particle writes its own slice).
#include "assembly/moments.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pd {

void compute_moments(FamilyInputs& inputs, const abi::LawDescriptor& law, const abi::KernelVariant& variant) {
  const int n = inputs.size(), nm = law.n_moments;
  inputs.n_moments = nm;
  inputs.moments.assign(static_cast<std::size_t>(n) * nm, 0.0);
  if (nm == 0) return;
  if (variant.moments == nullptr)
    throw std::invalid_argument(std::string("law ") + law.name + " has moments but no moments kernel");
  int bad = -1;
#pragma omp parallel
  {
    FamilyGather g(inputs);
#pragma omp for schedule(static)
    for (int p = 0; p < n; ++p) {
      const abi::Family f = g.gather(p, nullptr);
      // A family cut free by damage keeps zero moments: its kernels are not evaluated
      // (has_intact_bond). A particle without bonds at set-up is refused before this.
      if (!has_intact_bond(f)) continue;
      double* m = inputs.moments.data() + static_cast<std::ptrdiff_t>(p) * nm;
      variant.moments(f, m);
      for (int i = 0; i < nm; ++i)
        if (!std::isfinite(m[i])) {
#pragma omp critical(pd_moments_bad)
          if (bad < 0 || p < bad) bad = p;
        }
    }
  }
  if (bad >= 0)
    throw std::runtime_error("moments: non-finite value at particle " + std::to_string(bad) + " (law " +
                             law.name + ")");
}

}  // namespace pd
