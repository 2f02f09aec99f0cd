// Forward and adjoint sensitivities of a static equilibrium (equilibrium_sensitivity.hpp).
#include "sensitivity/equilibrium_sensitivity.hpp"

#include <cmath>
#include <stdexcept>

#include "constraints/dof_map.hpp"
#include "material/elastic_constants.hpp"
#include "run/peridynamic_system.hpp"
#include "solve/linear_solver.hpp"

namespace pd {

namespace {
int material_index(const Scene& scene, const std::string& name) {
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == name) return static_cast<int>(m);
  std::string known;
  for (const MaterialSpec& m : scene.materials) known += (known.empty() ? "" : ", ") + m.name;
  throw std::invalid_argument("no material '" + name + "' in " + scene.file + " (materials: " + known + ")");
}

void refuse(bool bad, const std::string& why) {
  if (bad) throw std::invalid_argument("parameter sensitivities: " + why);
}
}  // namespace

SceneParameter parse_scene_parameter(const Scene& scene, const std::string& text) {
  refuse(scene.materials.empty(), "the scene has no material");
  const std::size_t dot = text.rfind('.');
  SceneParameter p{dot == std::string::npos ? scene.materials.front().name : text.substr(0, dot),
                   dot == std::string::npos ? text : text.substr(dot + 1)};
  refuse(p.key.empty(), "'" + text + "' names no parameter (E, nu or a material parameter)");
  material_index(scene, p.material);
  return p;
}

double parameter_value(const Scene& scene, const SceneParameter& p) {
  const MaterialSpec& m = scene.materials[static_cast<std::size_t>(material_index(scene, p.material))];
  if (p.key == "E") return m.elastic.E;
  if (p.key == "nu") return m.elastic.nu;
  auto it = m.parameters.find(p.key);
  refuse(it == m.parameters.end(), "material '" + p.material + "' has no parameter '" + p.key + "'");
  return it->second;
}

Scene with_parameter(const Scene& scene, const SceneParameter& p, double value) {
  Scene s = scene;
  MaterialSpec& m = s.materials[static_cast<std::size_t>(material_index(scene, p.material))];
  if (p.key == "E") {
    m.elastic = IsotropicElastic::from_E_nu(value, m.elastic.nu);
  } else if (p.key == "nu") {
    m.elastic = IsotropicElastic::from_E_nu(m.elastic.E, value);
  } else {
    refuse(!m.parameters.count(p.key), "material '" + p.material + "' has no parameter '" + p.key + "'");
    m.parameters[p.key] = value;
  }
  return s;
}

EquilibriumSensitivity::EquilibriumSensitivity(const Model& model, const Scene& scene,
                                               std::vector<SceneParameter> params,
                                               const std::vector<double>& u, double load)
    : model_(model), params_(std::move(params)) {
  refuse(params_.empty(), "no parameter given");
  refuse(model.has_history(), "law " + std::string(model.law->name) +
                                  " carries history: the gradient of a load path needs the history's own "
                                  "sensitivity, which is not derived yet");
  refuse(model.damage != nullptr,
         "the scene's damage can break bonds, and a broken bond's force is not "
         "differentiable in the parameters");
  refuse(model.dofs.tied_count() > 0, "tied dofs (a fictitious layer) are not covered");
  const FamilyAssembler& families = bond_families(*model.assembler, "parameter sensitivities");
  refuse(!families.options().matrix,
         "the run's solver plan is matrix-free (the body is above solver.direct_max_nonzeros, or "
         "solver.linear: matrix_free): the sensitivities solve with the assembled tangent; give "
         "solver.linear: cholmod or umfpack");
  refuse(static_cast<int>(u.size()) != model.assembler->dofs(), "u has the wrong size");
  // d f / d (law parameter), chained to each scene parameter.
  const Eigen::MatrixXd dfdq = families.parameter_sensitivities(u.data());
  const int nq = model.law->n_params;
  dfdp_ = Eigen::MatrixXd::Zero(dfdq.rows(), static_cast<Eigen::Index>(params_.size()));
  for (std::size_t j = 0; j < params_.size(); ++j) {
    const int m = material_index(scene, params_[j].material);
    const MaterialSpec& mat = scene.materials[static_cast<std::size_t>(m)];
    const std::vector<double> dq =
        law_parameter_derivative(*model.law, mat.elastic, mat.plane, mat.parameters, params_[j].key);
    for (int i = 0; i < nq; ++i)
      if (dq[static_cast<std::size_t>(i)] != 0.0)
        dfdp_.col(static_cast<Eigen::Index>(j)) += dq[static_cast<std::size_t>(i)] * dfdq.col(m * nq + i);
  }
  // The run's tangent at u, the effects' stiffness included, reduced to the free dofs.
  std::vector<const Effect*> effects;
  for (const auto& e : model.effects) effects.push_back(e.get());
  PeridynamicSystem system(*model.assembler, effects);
  SparseMatrix K = model.assembler->make_matrix();
  const Eigen::Map<const Eigen::VectorXd> uv(u.data(), static_cast<Eigen::Index>(u.size()));
  system.tangent(uv, load, K, nullptr);
  ReducedSystem reduced(model.dofs, K);
  reduced.update(K);
  Kff_ = reduced.Kff();
  symmetric_ = system.symmetric();
}

EquilibriumSensitivity::~EquilibriumSensitivity() = default;

SparseSolver& EquilibriumSensitivity::solver(bool transposed) {
  std::unique_ptr<SparseSolver>& s = (transposed && !symmetric_) ? transposed_ : forward_;
  if (!s) {
    // A direct factorisation: the sensitivities are as exact as the solve.
    s = make_sparse_solver(symmetric_ ? LinearMethod::cholmod : LinearMethod::umfpack, LinearSolverOptions{});
    const SparseMatrix A = (transposed && !symmetric_) ? SparseMatrix(Kff_.transpose()) : Kff_;
    s->analyse(A);
    if (!s->factor(A)) throw std::runtime_error("parameter sensitivities: the tangent at u: " + s->failure());
  }
  return *s;
}

Eigen::MatrixXd EquilibriumSensitivity::displacement_sensitivity() {
  const DofMap& dofs = model_.dofs;
  Eigen::MatrixXd dudp = Eigen::MatrixXd::Zero(dfdp_.rows(), dfdp_.cols());
  for (Eigen::Index j = 0; j < dfdp_.cols(); ++j) {
    Eigen::VectorXd x;
    solver(false).solve(dofs.restrict_free(dfdp_.col(j)), x);
    ++solves_;
    Eigen::VectorXd full = Eigen::VectorXd::Zero(dfdp_.rows());
    dofs.expand_free(x, full);
    dudp.col(j) = full;
  }
  return dudp;
}

Eigen::VectorXd EquilibriumSensitivity::adjoint_gradient(const Eigen::VectorXd& dJdu) {
  refuse(dJdu.size() != dfdp_.rows(), "the objective's gradient has the wrong size");
  const DofMap& dofs = model_.dofs;
  Eigen::VectorXd lambda;
  solver(true).solve(dofs.restrict_free(dJdu), lambda);
  ++solves_;
  Eigen::VectorXd g(dfdp_.cols());
  for (Eigen::Index j = 0; j < dfdp_.cols(); ++j) g[j] = lambda.dot(dofs.restrict_free(dfdp_.col(j)));
  for (Eigen::Index j = 0; j < g.size(); ++j)
    if (!std::isfinite(g[j])) throw std::runtime_error("parameter sensitivities: a non-finite gradient");
  return g;
}

}  // namespace pd
