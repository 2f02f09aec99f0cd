// Calibration by Ceres' Levenberg-Marquardt with exact Jacobians (calibration.hpp).
#include "sensitivity/calibration.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "input/yaml_keys.hpp"  // SceneError
#include "run/simulation.hpp"

namespace pd {

namespace {
// For each measured component, its global dof: the particle within h/2 of the point.
std::vector<int> match_dofs(const Particles& particles, double h, const MeasuredField& data) {
  const int d = particles.dim;
  const auto key = [&](const double* x, const int* offset) {
    long long k = 0;
    for (int c = 0; c < d; ++c) k = k * 2000003LL + static_cast<long long>(std::floor(x[c] / h)) + offset[c];
    return k;
  };
  const int zero[3] = {0, 0, 0};
  std::unordered_map<long long, std::vector<int>> bins;
  for (int p = 0; p < particles.size(); ++p)
    bins[key(&particles.x[static_cast<std::size_t>(p) * d], zero)].push_back(p);
  std::vector<int> dofs;
  for (int k = 0; k < data.size(); ++k) {
    const double* x = &data.x[static_cast<std::size_t>(k) * d];
    int best = -1;
    double best_r2 = 0.25 * h * h;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int l = (d == 3 ? -1 : 0); l <= (d == 3 ? 1 : 0); ++l) {
          const int offset[3] = {i, j, l};
          auto it = bins.find(key(x, offset));
          if (it == bins.end()) continue;
          for (int p : it->second) {
            double r2 = 0;
            for (int c = 0; c < d; ++c) {
              const double dx = particles.x[static_cast<std::size_t>(p) * d + c] - x[c];
              r2 += dx * dx;
            }
            if (r2 <= best_r2) best = p, best_r2 = r2;
          }
        }
    if (best < 0)
      throw SceneError(
          fmt::format("{}:{}: row {}: no particle within h/2 = {:g} of the point: the field "
                      "reaches beyond the body",
                      data.path, data.line[static_cast<std::size_t>(k)], k + 1, 0.5 * h));
    for (int c = 0; c < d; ++c)
      if (data.measured[static_cast<std::size_t>(c)]) dofs.push_back(best * d + c);
  }
  return dofs;
}

// CalibrationProblem to Ceres, with its exact Jacobian.
class ExactMisfit final : public ceres::CostFunction {
 public:
  explicit ExactMisfit(CalibrationProblem& problem) : problem_(problem) {
    set_num_residuals(problem.residual_count());
    mutable_parameter_block_sizes()->push_back(problem.parameter_count());
  }
  bool Evaluate(double const* const* p, double* r, double** J) const override {
    return problem_.evaluate(p[0], r, J ? J[0] : nullptr);
  }

 private:
  CalibrationProblem& problem_;
};

// The residuals alone, for Ceres' central differences.
struct ResidualsOnly {
  CalibrationProblem* problem;
  bool operator()(double const* const* p, double* r) const { return problem->evaluate(p[0], r, nullptr); }
};
}  // namespace

CalibrationProblem::CalibrationProblem(const Scene& scene, std::vector<FitParameter> parameters,
                                       const MeasuredField& data)
    : scene_(scene), parameters_(std::move(parameters)) {
  if (parameters_.empty()) throw std::invalid_argument("calibration: no parameter to fit");
  if (data.dim != scene.dim)
    throw std::invalid_argument("calibration: the measured field's dimension is not the scene's");
  for (const FitParameter& f : parameters_) {
    const double v = parameter_value(scene, f.parameter);
    if (!(f.lower <= v && v <= f.upper))
      throw std::invalid_argument(
          fmt::format("calibration: {} starts at {:g}, outside its bounds [{:g}, {:g}]", f.parameter.label(),
                      v, f.lower, f.upper));
    start_.push_back(v);
    names_.push_back(f.parameter);
  }
  {  // the particles, from the scene as it is (the parameters do not move them)
    const DiscretizedBody body(scene);
    dofs_ = match_dofs(body.particles, scene.h, data);
  }
  for (int k = 0; k < data.size(); ++k)
    for (int c = 0; c < data.dim; ++c)
      if (data.measured[static_cast<std::size_t>(c)])
        measured_.push_back(data.value[static_cast<std::size_t>(k) * data.dim + c]);
  if (residual_count() < parameter_count())
    throw std::invalid_argument(fmt::format("calibration: {} measured values cannot determine {} parameters",
                                            residual_count(), parameter_count()));
}

bool CalibrationProblem::evaluate(const double* p, double* r, double* J) {
  // Ceres asks for the residuals at a trial point, then for the Jacobian at the same point
  // once the step is accepted: the last solve is kept, so that costs no second solve.
  if (!last_ || !std::equal(p, p + parameter_count(), last_p_.begin())) {
    last_.reset();
    try {
      last_scene_ = scene_;
      for (std::size_t j = 0; j < parameters_.size(); ++j)
        last_scene_ = with_parameter(last_scene_, parameters_[j].parameter, p[j]);
    } catch (const std::invalid_argument&) {
      return false;  // a value the material refuses (nu >= 1/2): the optimiser shrinks its step
    }
    auto sim = std::make_unique<Simulation>(last_scene_, [](const std::string&) {});
    ++forward_solves;
    if (!sim->run(false).newton.converged) return false;
    last_ = std::move(sim);
    last_p_.assign(p, p + parameter_count());
    last_J_.clear();
  }
  const std::vector<double>& u = last_->displacement();
  for (std::size_t k = 0; k < dofs_.size(); ++k) r[k] = u[static_cast<std::size_t>(dofs_[k])] - measured_[k];
  if (J && last_J_.empty()) {
    EquilibriumSensitivity sens(last_->model(), last_scene_, names_, u);
    const Eigen::MatrixXd dudp = sens.displacement_sensitivity();
    linear_solves += sens.solves();
    const std::size_t np = parameters_.size();
    last_J_.resize(dofs_.size() * np);
    for (std::size_t k = 0; k < dofs_.size(); ++k)
      for (std::size_t j = 0; j < np; ++j) last_J_[k * np + j] = dudp(dofs_[k], static_cast<Eigen::Index>(j));
  }
  if (J) std::copy(last_J_.begin(), last_J_.end(), J);
  return true;
}

CalibrationProblem::~CalibrationProblem() = default;

CalibrationResult calibrate(const Scene& scene, const std::vector<FitParameter>& parameters,
                            const MeasuredField& data, const CalibrationOptions& options,
                            const std::function<void(const std::string&)>& log) {
  CalibrationProblem misfit(scene, parameters, data);
  CalibrationResult result;
  result.parameters = parameters;
  result.initial = misfit.start();
  result.residuals = misfit.residual_count();
  std::vector<double> p = result.initial;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ExactMisfit exact(misfit);
  ceres::DynamicNumericDiffCostFunction<ResidualsOnly, ceres::CENTRAL> differences(
      new ResidualsOnly{&misfit});
  differences.AddParameterBlock(misfit.parameter_count());
  differences.SetNumResiduals(misfit.residual_count());
  problem.AddResidualBlock(
      options.jacobian == JacobianMethod::exact ? static_cast<ceres::CostFunction*>(&exact) : &differences,
      nullptr, p.data());
  for (std::size_t j = 0; j < parameters.size(); ++j) {
    if (std::isfinite(parameters[j].lower))
      problem.SetParameterLowerBound(p.data(), static_cast<int>(j), parameters[j].lower);
    if (std::isfinite(parameters[j].upper))
      problem.SetParameterUpperBound(p.data(), static_cast<int>(j), parameters[j].upper);
  }
  ceres::Solver::Options o;
  o.minimizer_type = ceres::TRUST_REGION;
  o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = options.max_iterations;
  o.function_tolerance = options.tolerance;
  o.gradient_tolerance = options.tolerance;
  o.parameter_tolerance = options.tolerance;
  o.logging_type = ceres::SILENT;
  o.num_threads = 1;  // each evaluation is a whole solve, threaded on its own
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  result.iterations = static_cast<int>(summary.iterations.size()) - 1;
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  result.message = summary.message;
  result.initial_rms = std::sqrt(2 * summary.initial_cost / result.residuals);
  result.final_rms = std::sqrt(2 * summary.final_cost / result.residuals);
  result.fitted = p;

  // The covariance at the fit, from its exact Jacobian.
  const int m = result.residuals, n = static_cast<int>(p.size());
  result.forward_solves = misfit.forward_solves;  // the fit's, not the covariance's below
  result.linear_solves = misfit.linear_solves;
  std::vector<double> r(static_cast<std::size_t>(m)), J(static_cast<std::size_t>(m) * n);
  result.standard_error.assign(p.size(), std::numeric_limits<double>::quiet_NaN());
  if (misfit.evaluate(p.data(), r.data(), J.data()) && m > n) {
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Jm(
        J.data(), m, n);
    const double s2 = Eigen::Map<const Eigen::VectorXd>(r.data(), m).squaredNorm() / (m - n);
    const Eigen::MatrixXd cov = s2 * (Jm.transpose() * Jm).inverse();
    for (int j = 0; j < n; ++j) result.standard_error[static_cast<std::size_t>(j)] = std::sqrt(cov(j, j));
  }
  result.fitted_scene = scene;
  for (std::size_t j = 0; j < p.size(); ++j)
    result.fitted_scene = with_parameter(result.fitted_scene, parameters[j].parameter, p[j]);
  if (log)
    log(fmt::format(
        "calibration: {} after {} iterations ({} solves, {} sensitivity solves); rms misfit {:.3e} -> {:.3e}",
        result.converged ? "converged" : "stopped", result.iterations, result.forward_solves,
        result.linear_solves, result.initial_rms, result.final_rms));
  return result;
}

}  // namespace pd
