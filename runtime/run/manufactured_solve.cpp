// The manufactured-solution solve of paper 001 §4 (manufactured_solve.hpp).
#include "run/manufactured_solve.hpp"

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

// Distance of a point from the boundary of the square (negative in an outside collar).
double depth_in_square(const ManufacturedSetup& s, const double* x) {
  return std::min({x[0] - s.lo, s.hi - x[0], x[1] - s.lo, s.hi - x[1]});
}

// The square's own cloud (the one square_cloud(s, 0) makes, the same perturbed
// positions) and around it `collar` more rows, perturbed as the lattice of the larger
// square perturbs them: the square's particles do not move when the collar is added.
Particles square_cloud_with_collar(const ManufacturedSetup& s, double collar) {
  Particles P = square_cloud(s, 0);
  ManufacturedSetup lattice = s;
  lattice.perturbation = 0;
  const Particles grid = square_cloud(lattice, collar), perturbed = square_cloud(s, collar);
  for (int p = 0; p < grid.size(); ++p) {
    if (depth_in_square(s, grid.position(p)) > 0) continue;  // a lattice site of the square
    for (int c = 0; c < 2; ++c) P.x.push_back(perturbed.position(p)[c]);
    P.volume.push_back(perturbed.volume[p]);
    P.material.push_back(perturbed.material[p]);
  }
  return P;
}

// The families whose forces reach a solved particle: the solved ones and their neighbours.
std::vector<char> families_reaching(const Bonds& bonds, const std::vector<char>& solved) {
  std::vector<char> needed = solved;
  for (int p = 0; p < bonds.particle_count(); ++p)
    if (solved[p])
      for (int b = bonds.offsets[p]; b < bonds.offsets[p + 1]; ++b) needed[bonds.neighbor[b]] = 1;
  return needed;
}

// Whether the segment xa-xb meets the circle |x - c| = R: its nearest point to c lies
// within R and its farthest point (an end) beyond R.
bool meets_circle(const double* xa, const double* xb, const double* c, double R) {
  const double d[2] = {xb[0] - xa[0], xb[1] - xa[1]}, f[2] = {xa[0] - c[0], xa[1] - c[1]};
  const double t = std::clamp(-(f[0] * d[0] + f[1] * d[1]) / (d[0] * d[0] + d[1] * d[1]), 0.0, 1.0);
  const double nearest = std::hypot(f[0] + t * d[0], f[1] + t * d[1]);
  const double farthest = std::max(std::hypot(f[0], f[1]), std::hypot(xb[0] - c[0], xb[1] - c[1]));
  return nearest <= R && farthest >= R;
}
// The families outside the hole that lost bonds to it: new weights over their intact
// bonds, exact for the space over the part of the ball the centre sees past the disk
// (ball_disk_shadow_moment_2d). A family left with too few intact bonds for the space
// keeps its whole-ball weights and is counted. Every broken bond then weighs 0 in both
// directions (collocation needs a pair's two weights zero together; a broken bond
// carries no force whatever its weight).
void reweigh_cut_families(const Particles& P, const Bonds& B, const ReproducingSpace& space,
                          const std::vector<char>& needed, const ManufacturedSetup& s, std::vector<double>& w,
                          ManufacturedResult& r) {
  for (std::size_t b = 0; b < w.size(); ++b)
    if (B.alpha[b] == 0) w[b] = 0;
  for (int p = 0; p < P.size(); ++p) {
    const double* x = P.position(p);
    if (!needed[p] || std::hypot(x[0] - s.hole_center[0], x[1] - s.hole_center[1]) <= s.hole_radius) continue;
    std::vector<double> xi;
    std::vector<int> intact;
    for (int b = B.offsets[p]; b < B.offsets[p + 1]; ++b)
      if (B.alpha[b] != 0) {
        intact.push_back(b);
        xi.insert(xi.end(), B.xi.begin() + 2 * b, B.xi.begin() + 2 * b + 2);
      }
    if (static_cast<int>(intact.size()) == B.family_size(p)) continue;
    const double delta = B.delta[p];
    const double unit_x[2] = {x[0] / delta, x[1] / delta},
                 unit_c[2] = {s.hole_center[0] / delta, s.hole_center[1] / delta};
    try {
      const std::vector<double> v = obq_family_weights_over(
          space, xi.data(), static_cast<int>(intact.size()), delta, p, x, [&](const BondMonomial& f) {
            return ball_disk_shadow_moment_2d(f, 1.0, unit_x, unit_c, s.hole_radius / delta);
          });
      for (std::size_t k = 0; k < intact.size(); ++k) w[intact[k]] = v[k];
      ++r.cut_weight_families;
    } catch (const NotUnisolventError&) {
      ++r.cut_weight_fallbacks;
    }
  }
}

// The law's parameters for (lambda, mu), in the order the law names them.
std::vector<double> law_parameters(const abi::LawDescriptor& law, double lambda, double mu) {
  std::vector<double> v(2);
  for (int i = 0; i < 2; ++i) v[i] = std::string(law.param_names[i]) == "lambda" ? lambda : mu;
  return v;
}

// The particles inside the inclusion take material 1, the others 0 (none without an inclusion).
void mark_inclusion(Particles& P, const ManufacturedSetup& s) {
  for (int p = 0; p < P.size() && s.inclusion_radius > 0; ++p) {
    const double* x = P.position(p);
    P.material[p] =
        std::hypot(x[0] - s.inclusion_centre[0], x[1] - s.inclusion_centre[1]) < s.inclusion_radius ? 1 : 0;
  }
}

// The solved particles: at least `layer` inside the square and not in the hole (counted in r.solved).
std::vector<char> solved_particles(const Particles& P, const ManufacturedSetup& s, double layer,
                                   ManufacturedResult& r) {
  const int n = P.size();
  std::vector<char> solved(n);
  for (int p = 0; p < n; ++p) {
    const double* x = P.position(p);
    const bool in_hole =
        s.hole_radius > 0 && std::hypot(x[0] - s.hole_center[0], x[1] - s.hole_center[1]) < s.hole_radius;
    solved[p] = depth_in_square(s, x) >= layer && !in_hole;
    r.solved += solved[p];
  }
  return solved;
}

// Breaks every bond whose segment meets the hole's circle (counted in r.broken_bonds).
void break_hole_bonds(const Particles& P, Bonds& B, const ManufacturedSetup& s, ManufacturedResult& r) {
  for (int p = 0; p < P.size(); ++p)
    for (int b = B.offsets[p]; b < B.offsets[p + 1]; ++b)
      if (meets_circle(P.position(p), P.position(B.neighbor[b]), s.hole_center, s.hole_radius)) {
        B.alpha[b] = 0;
        ++r.broken_bonds;
      }
}

// The linear system reduced to the solved dofs, K_II u_I = b_I - K_ID u_D, with the map
// from model dofs to its unknowns (-1: imposed) and the exact displacement of every dof.
struct ReducedSystem {
  std::vector<int> index;
  int unknowns = 0;
  std::vector<double> exact;
  Eigen::VectorXd rhs;
  SparseMatrix A;
};

ReducedSystem reduce_to_solved(const SparseMatrix& K, const Particles& P, const std::vector<char>& solved,
                               const ManufacturedField& field, const ManufacturedSetup& s) {
  // A particle's own (lambda, mu), for the body force.
  auto lame = [&](int p) {
    return P.material[p] == 1 ? std::array<double, 2>{s.inclusion_lambda, s.inclusion_mu}
                              : std::array<double, 2>{s.lambda, s.mu};
  };
  const int n = P.size();
  ReducedSystem sys;
  sys.index.assign(2 * n, -1);
  for (int p = 0; p < n; ++p)
    if (solved[p]) sys.index[2 * p] = sys.unknowns++, sys.index[2 * p + 1] = sys.unknowns++;
  sys.exact.resize(2 * n);
  sys.rhs = Eigen::VectorXd::Zero(sys.unknowns);
  for (int p = 0; p < n; ++p) {
    const double* x = P.position(p);
    const auto u = field.displacement(x[0], x[1]);
    sys.exact[2 * p] = u[0], sys.exact[2 * p + 1] = u[1];
    if (solved[p]) {
      const auto b = field.body_force(x[0], x[1], lame(p)[0], lame(p)[1]);
      sys.rhs[sys.index[2 * p]] = P.volume[p] * b[0];
      sys.rhs[sys.index[2 * p + 1]] = P.volume[p] * b[1];
    }
  }
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int row = sys.index[it.row()];
      if (row < 0) continue;
      if (sys.index[col] >= 0)
        triplets.emplace_back(row, sys.index[col], it.value());
      else
        sys.rhs[row] -= it.value() * sys.exact[col];
    }
  sys.A.resize(sys.unknowns, sys.unknowns);
  sys.A.setFromTriplets(triplets.begin(), triplets.end());
  return sys;
}

// Factors A (CHOLMOD when symmetric, UMFPACK otherwise) and solves for the unknowns.
Eigen::VectorXd solve_reduced(const ReducedSystem& sys, bool symmetric) {
  auto solver = make_sparse_solver(symmetric ? LinearMethod::cholmod : LinearMethod::umfpack, {});
  solver->analyse(sys.A);
  if (!solver->factor(sys.A)) throw std::runtime_error("solve_manufactured: " + solver->failure());
  Eigen::VectorXd u(sys.unknowns);
  solver->solve(sys.rhs, u);
  return u;
}

// The RMS error of §4 (and per component) over the solved particles outside the error
// margins; with keep_solution, every particle's position, computed and exact displacement.
void record_errors(const Particles& P, const std::vector<char>& solved, const ReducedSystem& sys,
                   const Eigen::VectorXd& u, const ManufacturedSetup& s, ManufacturedResult& r) {
  const int n = P.size();
  const std::vector<int>& index = sys.index;
  const std::vector<double>& exact = sys.exact;
  double sum = 0, component_sum[2] = {0, 0};
  const double margin = s.error_margin;
  for (int p = 0; p < n; ++p) {
    const double* x = P.position(p);
    if (!solved[p] || depth_in_square(s, x) < margin) continue;
    if (s.hole_error_margin > 0 &&
        std::hypot(x[0] - s.hole_center[0], x[1] - s.hole_center[1]) < s.hole_radius + s.hole_error_margin)
      continue;
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
  if (r.measured == 0)
    throw std::invalid_argument("solve_manufactured: no solved particle inside the error margin");
  sum = component_sum[0] + component_sum[1];
  r.rms_error = std::sqrt(sum / r.measured);
  for (int c = 0; c < 2; ++c) r.rms_component[c] = std::sqrt(component_sum[c] / r.measured);
}
}  // namespace

ManufacturedResult solve_manufactured(const ManufacturedField& field, const ManufacturedSetup& s) {
  const abi::LawDescriptor* law = abi::find_law(s.law);
  const abi::InfluenceDescriptor* influence = abi::find_influence(s.influence);
  if (!law || law->dim != 2 || law->n_params != 2)
    throw std::invalid_argument("solve_manufactured: law '" + s.law + "' is not a 2D law of (lambda, mu)");
  if (!influence)
    throw std::invalid_argument("solve_manufactured: no influence function '" + s.influence + "'");
  std::vector<std::vector<double>> params{law_parameters(*law, s.lambda, s.mu)};
  if (s.inclusion_radius > 0) params.push_back(law_parameters(*law, s.inclusion_lambda, s.inclusion_mu));

  const double h = (s.hi - s.lo) / s.n, delta = s.horizon_ratio * h;
  const bool add_collar = s.collar_outside || s.whole_layer_families;
  const double collar = add_collar ? std::ceil(s.layer_horizons * delta / h - 1e-9) * h : 0;
  const double layer = s.collar_outside ? 0 : s.layer_horizons * delta;
  Particles P =
      s.collar_outside || !add_collar ? square_cloud(s, collar) : square_cloud_with_collar(s, collar);
  mark_inclusion(P, s);
  Bonds B = find_bonds(P, delta, influence->weight);
  const int n = P.size();
  ManufacturedResult r;
  r.particles = n;
  const std::vector<char> solved = solved_particles(P, s, layer, r);

  auto t0 = std::chrono::steady_clock::now();
  Collocation collocation;
  AssemblerOptions options;
  options.intact = true;
  std::vector<double> w;
  const ReproducingSpace space = s.odd_terms ? paper001_odd_space(2) : paper001_space(2);
  const std::vector<char> needed = families_reaching(B, solved);
  if (s.obq) w = obq_weights(P, B, space, needed);
  r.weights_seconds = seconds_since(t0);
  if (s.hole_radius > 0) {  // the weights above saw the whole cloud (§4: "before bonds are broken")
    break_hole_bonds(P, B, s, r);
    options.intact = r.broken_bonds == 0;
  }
  if (s.obq && s.hole_radius > 0 && s.hole_cut_weights) {
    t0 = std::chrono::steady_clock::now();
    reweigh_cut_families(P, B, space, needed, s, w, r);
    r.weights_seconds += seconds_since(t0);
  }
  if (s.obq) {
    if (s.symmetric_weights) w = symmetric_pair_weights(P, B, w);
    collocation = make_collocation(P, B, std::move(w));
    options.collocation = &collocation;
  }

  t0 = std::chrono::steady_clock::now();
  const FamilyAssembler assembler(P, B, *law, params, options);
  SparseMatrix K = assembler.make_matrix();
  assembler.stiffness(nullptr, K);  // linear law: K u = b
  const ReducedSystem reduced = reduce_to_solved(K, P, solved, field, s);
  r.assembly_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  // Cholesky needs a symmetric K: collocation and pair jumps make it non-symmetric, and so
  // does a law with no energy (Oterkus, lps_paper_corrected_*) on any quadrature.
  r.symmetric_matrix = assembler.has_energy();
  const Eigen::VectorXd u = solve_reduced(reduced, r.symmetric_matrix);
  r.solve_seconds = seconds_since(t0);

  record_errors(P, solved, reduced, u, s, r);
  return r;
}

}  // namespace pd
