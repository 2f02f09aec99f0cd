// Calibration: the material parameters that make a static scene's displacement fit a
// measured field (input/measured_field.hpp) in least squares,
//   min_p  1/2 sum_k (u_c(x_k; p) - m_kc)^2   subject to  lower <= p <= upper,
// over every measurement point k (matched to the particle within h/2 of it) and measured
// component c. Ceres' Levenberg-Marquardt trust region minimises it: Ceres takes bounds
// natively (its projected steps; Eigen's unsupported LevenbergMarquardt has none, and a
// change of variables would distort the confidence intervals), and the Jacobian du/dp is
// exact -- one factorisation of the tangent and one solve per parameter at each point
// (sensitivity/equilibrium_sensitivity.hpp), no finite differences.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "input/measured_field.hpp"
#include "input/scene.hpp"
#include "sensitivity/equilibrium_sensitivity.hpp"

namespace pd {

class Simulation;

struct FitParameter {
  SceneParameter parameter;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

// How the Levenberg-Marquardt steps get their Jacobian: exact (the sensitivities), or
// central differences of the whole solve (Ceres' numeric differentiation: 2 solves per
// parameter per Jacobian), the route without this toolkit's sensitivities, for comparison.
enum class JacobianMethod { exact, central_differences };

struct CalibrationOptions {
  int max_iterations = 50;
  double tolerance = 1e-12;  // Ceres' function, gradient and parameter tolerances
  JacobianMethod jacobian = JacobianMethod::exact;
};

// The least-squares problem: the residuals u_c(x_k; p) - m_kc of one static solve at p and
// their exact Jacobian. calibrate() hands it to Ceres; the calibration study
// (bench/calibration_study.cpp) to other methods as well. Throws as calibrate() does.
class CalibrationProblem {
 public:
  CalibrationProblem(const Scene& scene, std::vector<FitParameter> parameters, const MeasuredField& data);
  ~CalibrationProblem();
  CalibrationProblem(const CalibrationProblem&) = delete;
  CalibrationProblem& operator=(const CalibrationProblem&) = delete;
  int residual_count() const { return static_cast<int>(dofs_.size()); }
  int parameter_count() const { return static_cast<int>(parameters_.size()); }
  const std::vector<FitParameter>& parameters() const { return parameters_; }
  const std::vector<double>& start() const { return start_; }
  // r [residuals] at p; J (null: not wanted) row-major [residuals x parameters]. False when
  // the material refuses a value (nu >= 1/2) or Newton does not converge.
  bool evaluate(const double* p, double* r, double* J);
  int forward_solves = 0;  // nonlinear static solves
  int linear_solves = 0;   // sensitivity solves
  const Scene& scene() const { return scene_; }

 private:
  const Scene& scene_;
  std::vector<FitParameter> parameters_;
  std::vector<SceneParameter> names_;
  std::vector<double> start_;
  std::vector<int> dofs_;  // the global dof of each residual
  std::vector<double> measured_;
  // The last solve, kept for a Jacobian asked at the same point.
  std::unique_ptr<Simulation> last_;
  std::vector<double> last_p_, last_J_;
  Scene last_scene_;
};

struct CalibrationResult {
  std::vector<FitParameter> parameters;
  std::vector<double> initial, fitted;
  // One standard deviation of each fitted value from the Gauss-Newton covariance
  // s^2 (J^T J)^-1, s^2 = 2 cost / (residuals - parameters); NaN with no more residuals
  // than parameters.
  std::vector<double> standard_error;
  int residuals = 0;                      // measured components matched to particles
  int iterations = 0;                     // Ceres' successful and unsuccessful steps
  int forward_solves = 0;                 // nonlinear static solves (each a Newton run)
  int linear_solves = 0;                  // sensitivity solves (one per parameter per Jacobian)
  double initial_rms = 0, final_rms = 0;  // sqrt(sum r^2 / residuals)
  bool converged = false;
  std::string message;  // Ceres' termination message
  Scene fitted_scene;
};

// Throws SceneError naming the field's file and line for a measurement point with no
// particle within h/2, std::invalid_argument for bounds that exclude the start (or are
// empty) and for fewer residuals than parameters, and what the sensitivities refuse.
CalibrationResult calibrate(const Scene& scene, const std::vector<FitParameter>& parameters,
                            const MeasuredField& data, const CalibrationOptions& options = {},
                            const std::function<void(const std::string&)>& log = {});

}  // namespace pd
