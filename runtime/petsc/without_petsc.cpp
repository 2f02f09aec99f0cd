// The distributed backend in a build without PETSc: every entry point says so.
#include <cstdlib>
#include <stdexcept>

#include "petsc/rank_steps_factory.hpp"
#include "solve/distributed_backend.hpp"

namespace pd {

namespace {
[[noreturn]] void refuse() {
  throw std::runtime_error(
      "this pd was built without PETSc (solver.backend: petsc needs it): install petsc-dev "
      "(scripts/install_deps.sh) and configure again with -DPD_WITH_PETSC=ON");
}
}  // namespace

bool distributed_backend_available() { return false; }

DistributedSession::DistributedSession(const std::vector<std::string>&) { refuse(); }
DistributedSession::~DistributedSession() = default;
const DistributedSession* DistributedSession::current() { return nullptr; }

NewtonResult solve_distributed(const DistributedProblem&, Eigen::VectorXd&,
                               const std::function<void(const std::string&)>&) {
  refuse();
}

std::unique_ptr<StepExecutor> make_rank_steps(StepState) { refuse(); }

}  // namespace pd
