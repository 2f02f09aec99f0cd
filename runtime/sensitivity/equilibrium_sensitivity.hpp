// Sensitivities of a static equilibrium to the material parameters (issue 33): at a
// converged displacement u of r(u, p) = f_int(u, p) + f_ext = 0 on the free dofs, with the
// prescribed dofs and the loads independent of p,
//   forward:  K_ff du_f/dp = (df/dp)_f, one solve per parameter (K = -dr/du, the run's tangent);
//   adjoint:  K_ff^T lambda = (dJ/du)_f, one solve for a scalar objective J(u), and then
//             dJ/dp = lambda . (df/dp)_f for every parameter at once.
// df/dp comes from the generated sensitivity kernels (FamilyAssembler::parameter_sensitivities)
// and the closed-form chain from a material's (E, nu) to the law's parameters
// (material/elastic_constants.hpp, law_parameter_derivative).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"

namespace pd {

class SparseSolver;

// A parameter of one of the scene's materials: `key` is E, nu or a name under the
// material's `parameters`.
struct SceneParameter {
  std::string material;  // a material's name in the scene
  std::string key;
  std::string label() const { return material + "." + key; }
};

// "name.key", or "key" for the body's material (the scene's first). Throws
// std::invalid_argument naming the material when the scene has none of that name.
SceneParameter parse_scene_parameter(const Scene& scene, const std::string& text);

// The value of a scene parameter, and a copy of the scene with it set (E or nu rebuild the
// material's elastic constants; std::invalid_argument on a value they refuse).
double parameter_value(const Scene& scene, const SceneParameter& p);
Scene with_parameter(const Scene& scene, const SceneParameter& p, double value);

class EquilibriumSensitivity {
 public:
  // model: the scene's model with a matrix pattern (ModelPlan::matrix); u: its converged
  // displacement at load factor `load`. Throws std::invalid_argument on what the
  // derivation above does not cover: a law with memory (a path's gradient needs the
  // history's own sensitivity), bonds that can break (damage), Gauss-point quadrature,
  // tied dofs (a fictitious layer), surface correction, a model without a matrix.
  EquilibriumSensitivity(const Model& model, const Scene& scene, std::vector<SceneParameter> params,
                         const std::vector<double>& u, double load = 1.0);
  ~EquilibriumSensitivity();
  EquilibriumSensitivity(const EquilibriumSensitivity&) = delete;
  EquilibriumSensitivity& operator=(const EquilibriumSensitivity&) = delete;

  int parameter_count() const { return static_cast<int>(params_.size()); }
  const std::vector<SceneParameter>& parameters() const { return params_; }
  // df_int/dp: [dofs x parameters].
  const Eigen::MatrixXd& force_sensitivity() const { return dfdp_; }
  // du/dp [dofs x parameters] by the forward route (zero on the prescribed dofs).
  Eigen::MatrixXd displacement_sensitivity();
  // dJ/dp [parameters] of an objective whose gradient in u is dJdu [dofs] (its explicit
  // dependence on p is zero): one solve with the transposed reduced tangent.
  Eigen::VectorXd adjoint_gradient(const Eigen::VectorXd& dJdu);
  // The linear solves made so far (forward: one per parameter; adjoint: one per call).
  int solves() const { return solves_; }

 private:
  SparseSolver& solver(bool transposed);

  const Model& model_;
  std::vector<SceneParameter> params_;
  Eigen::MatrixXd dfdp_;
  SparseMatrix Kff_;
  bool symmetric_ = false;
  std::unique_ptr<SparseSolver> forward_, transposed_;
  int solves_ = 0;
};

}  // namespace pd
