// The default Effect: no force, no stiffness, nothing to do after a step.
#include "effects/effect.hpp"

namespace pd {

void Effect::add_forces(const double*, double, double*) const {}
void Effect::add_stiffness(const double*, double, const SparsityPattern&, SparseMatrix&) const {}
void Effect::add_stiffness_product(const double*, double, const double*, double*) const {}
void Effect::add_stiffness_diagonal(const double*, double, double*) const {}
long long Effect::after_step(const double*, FamilyScope) { return 0; }

}  // namespace pd
