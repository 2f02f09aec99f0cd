// A 2D spring-grid problem for the solver tests: left edge clamped, right edge pulled.
#pragma once

#include <memory>

#include "assembly/assembler.hpp"
#include "constraints/dof_map.hpp"
#include "run/peridynamic_system.hpp"
#include "support_grid.hpp"
#include "support_spring_law.hpp"

namespace pd::test {

struct GridProblem {
  Body body;
  std::unique_ptr<FamilyAssembler> assembler;
  DofMap dofs;
  Eigen::VectorXd external;
  // Left column clamped (both components); the right column pulled by `pull` in x as
  // a prescribed displacement, or loaded by force `load` in x when pull == 0.
  GridProblem(const abi::LawDescriptor& law, std::vector<double> params, int nx, int ny, double pull,
              double load, double jitter = 0.2) {
    body = make_grid(2, nx, ny, 1, 2.1, jitter);
    assembler = std::make_unique<FamilyAssembler>(body.particles, body.bonds, law,
                                                  std::vector<std::vector<double>>{std::move(params)});
    const int n = body.particles.size();
    std::vector<int> c;
    std::vector<double> v;
    external = Eigen::VectorXd::Zero(2 * n);
    for (int p = 0; p < n; ++p) {
      const int i = p % nx;
      if (i == 0) c.insert(c.end(), {2 * p, 2 * p + 1}), v.insert(v.end(), {0.0, 0.0});
      if (i == nx - 1) {
        if (pull != 0)
          c.push_back(2 * p), v.push_back(pull);
        else
          external[2 * p] = load;
      }
    }
    dofs = DofMap::from_list(2 * n, c, v);
  }
  PeridynamicSystem system() {
    loads =
        make_nodal_forces(std::vector<double>(external.data(), external.data() + external.size()), "pull");
    return PeridynamicSystem(*assembler, {loads.get()});
  }
  std::unique_ptr<Effect> loads;
};

}  // namespace pd::test
