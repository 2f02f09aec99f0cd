// The manufactured-solution solve of paper 001 §4 (manufactured_solve.hpp).
#include "fields/manufactured_solve.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "assembly/assembler.hpp"
#include "assembly/collocation.hpp"
#include "discretize/discretization.hpp"
#include "discretize/obq_weights.hpp"
#include "solve/linear_solver.hpp"

namespace pd {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The lattice of the square, with `collar` more rows of the same spacing around it.
Particles square_cloud(const ManufacturedSetup& s, double collar) {
  Scene scene;
  scene.dim = 2;
  scene.lo = {s.lo - collar, s.lo - collar, 0};
  scene.hi = {s.hi + collar, s.hi + collar, 0};
  scene.h = (s.hi - s.lo) / s.n;
  scene.perturbation = s.perturbation;
  scene.seed = s.seed;
  scene.materials.resize(1);
  return discretize(scene);
}

// The families whose forces reach a solved particle: the solved ones and their neighbours.
std::vector<char> families_reaching(const Bonds& bonds, const std::vector<char>& solved) {
  std::vector<char> needed = solved;
  for (int p = 0; p < bonds.particle_count(); ++p)
    if (solved[p])
      for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b) needed[bonds.neighbor[b]] = 1;
  return needed;
}
}  // namespace

ManufacturedResult solve_manufactured(const ManufacturedField& field, const ManufacturedSetup& s) {
  const abi::LawDescriptor* law = abi::find_law(s.law);
  const abi::InfluenceDescriptor* influence = abi::find_influence(s.influence);
  if (!law || law->dim != 2 || law->n_params != 2)
    throw std::invalid_argument("solve_manufactured: law '" + s.law + "' is not a 2D law of (lambda, mu)");
  if (!influence) throw std::invalid_argument("solve_manufactured: no influence function '" + s.influence + "'");
  auto law_params = [&](double lambda, double mu) {
    std::vector<double> v(2);
    for (int i = 0; i < 2; ++i) v[i] = std::string(law->param_names[i]) == "lambda" ? lambda : mu;
    return v;
  };
  std::vector<std::vector<double>> params{law_params(s.lambda, s.mu)};
  if (s.inclusion_radius > 0) params.push_back(law_params(s.inclusion_lambda, s.inclusion_mu));

  const double h = (s.hi - s.lo) / s.n, delta = s.horizon_ratio * h;
  const double collar = s.collar_outside ? std::ceil(s.layer_horizons * delta / h - 1e-9) * h : 0;
  const double layer = s.collar_outside ? 0 : s.layer_horizons * delta;
  Particles P = square_cloud(s, collar);
  for (int p = 0; p < P.size() && s.inclusion_radius > 0; ++p) {
    const double* x = P.position(p);
    P.material[p] = std::hypot(x[0] - s.inclusion_centre[0], x[1] - s.inclusion_centre[1]) < s.inclusion_radius ? 1 : 0;
  }
  // A particle's own (lambda, mu), for the body force.
  auto lame = [&](int p) { return P.material[p] == 1 ? std::array<double, 2>{s.inclusion_lambda, s.inclusion_mu} : std::array<double, 2>{s.lambda, s.mu}; };
  // Distance of a point from the boundary of the square (negative in an outside collar).
  auto depth = [&](const double* x) { return std::min({x[0] - s.lo, s.hi - x[0], x[1] - s.lo, s.hi - x[1]}); };
  const Bonds B = find_bonds(P, delta, influence->weight);
  const int n = P.size();
  std::vector<char> solved(n);
  ManufacturedResult r;
  r.particles = n;
  for (int p = 0; p < n; ++p) {
    const double* x = P.position(p);
    solved[p] = depth(x) >= layer;
    r.solved += solved[p];
  }

  auto t0 = std::chrono::steady_clock::now();
  Collocation collocation;
  AssemblerOptions options;
  options.intact = true;
  if (s.obq) {
    collocation = make_collocation(P, B, obq_weights(P, B, s.odd_terms ? paper001_odd_space(2) : paper001_space(2),
                                                  families_reaching(B, solved)));
    options.collocation = &collocation;
  }
  r.weights_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  const FamilyAssembler assembler(P, B, *law, params, options);
  SparseMatrix K = assembler.make_matrix();
  assembler.stiffness(nullptr, K);  // linear law: K u = b
  // Reduced system on the solved dofs: K_II u_I = b_I - K_ID u_D.
  std::vector<int> index(2 * n, -1);
  int unknowns = 0;
  for (int p = 0; p < n; ++p)
    if (solved[p]) index[2 * p] = unknowns++, index[2 * p + 1] = unknowns++;
  std::vector<double> exact(2 * n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  for (int p = 0; p < n; ++p) {
    const double* x = P.position(p);
    const auto u = field.displacement(x[0], x[1]);
    exact[2 * p] = u[0], exact[2 * p + 1] = u[1];
    if (solved[p]) {
      const auto b = field.body_force(x[0], x[1], lame(p)[0], lame(p)[1]);
      rhs[index[2 * p]] = P.volume[p] * b[0];
      rhs[index[2 * p + 1]] = P.volume[p] * b[1];
    }
  }
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int row = index[it.row()];
      if (row < 0) continue;
      if (index[col] >= 0) triplets.emplace_back(row, index[col], it.value());
      else rhs[row] -= it.value() * exact[col];
    }
  SparseMatrix A(unknowns, unknowns);
  A.setFromTriplets(triplets.begin(), triplets.end());
  r.assembly_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  auto solver = make_sparse_solver(assembler.symmetric() ? LinearMethod::cholmod : LinearMethod::umfpack, {});
  solver->analyse(A);
  if (!solver->factor(A)) throw std::runtime_error("solve_manufactured: " + solver->failure());
  Eigen::VectorXd u(unknowns);
  solver->solve(rhs, u);
  r.solve_seconds = seconds_since(t0);

  double sum = 0, component_sum[2] = {0, 0};
  const double margin = s.error_margin;
  for (int p = 0; p < n; ++p) {
    const double* x = P.position(p);
    if (!solved[p] || depth(x) < margin) continue;
    for (int c = 0; c < 2; ++c) component_sum[c] += std::pow(u[index[2 * p + c]] - exact[2 * p + c], 2);
    ++r.measured;
  }
  if (s.keep_solution) {
    r.x.resize(2 * n), r.u.resize(2 * n);
    r.exact = exact;
    for (int p = 0; p < n; ++p)
      for (int c = 0; c < 2; ++c) {
        r.x[2 * p + c] = P.position(p)[c];
        r.u[2 * p + c] = solved[p] ? u[index[2 * p + c]] : exact[2 * p + c];
      }
  }
  if (r.measured == 0) throw std::invalid_argument("solve_manufactured: no solved particle inside the error margin");
  sum = component_sum[0] + component_sum[1];
  r.rms_error = std::sqrt(sum / r.measured);
  for (int c = 0; c < 2; ++c) r.rms_component[c] = std::sqrt(component_sum[c] / r.measured);
  return r;
}

}  // namespace pd
