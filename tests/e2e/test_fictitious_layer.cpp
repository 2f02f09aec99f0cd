// Fictitious boundary layers (paper 003 section 3.3, eqs. 29-35; discretize/fictitious_layer.hpp)
// on the unit square [0, 1]^2, h = 0.1, delta = 3h, with a layer 2 delta deep on every side:
// rollers on the left (x odd, y even mirror) and bottom (y odd, x even), traction sigma on
// the right, a free top (traction 0); corners resolve through two layers.
// * The ties reproduce every linear field that satisfies the conditions exactly in the layer.
// * The body's residual under the uniaxial-stress field is zero (the patch test through the
//   layer), while the layer's own rows are not: the symmetric reduction P^T r would put them
//   on the body, which is why the DofMap eliminates ties by collocation (S K P).
// * The reduced tangent S K P equals central differences of the reduced residual, and the
//   JVP path (expand_free, jvp, restrict_free) gives the same product.
// * `pd run`'s static solve on the scene gives the uniaxial-stress solution u_x = sigma x / E,
//   u_y = -nu sigma y / E (plane stress) at every body particle.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <string>

#include "constraints/constraints.hpp"
#include "discretize/discretization.hpp"
#include "discretize/fictitious_layer.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "model/model.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/peridynamic_system.hpp"
#include "run/simulation.hpp"

namespace {
constexpr double kE = 1.0, kNu = 0.25, kSigma = 1e-3;

std::string square_scene(const std::string& law, const std::string& right = "traction: [0.001, 0]") {
  return "dimension: 2\n"
         "domain: {box: {min: [-0.6, -0.6], max: [1.6, 1.6]}, spacing: 0.1}\n"
         "horizon: {ratio: 3}\n"
         "law: " +
         law +
         "\n"
         "materials:\n"
         "  - {E: 1, nu: 0.25, plane: stress" +
         (law.rfind("correspondence", 0) == 0 ? ", parameters: {stab: 1.0}" : "") +
         "}\n"
         "boundary:\n"
         "  - {region: {box: {min: [-1, -1], max: [0, 2]}}, method: fictitious_layer, face: {point: [0, 0], "
         "normal: [-1, 0]}, fixed: [x]}\n"
         "  - {region: {box: {min: [0, -1], max: [2, 0]}}, method: fictitious_layer, face: {point: [0, 0], "
         "normal: [0, -1]}, fixed: [y]}\n"
         "  - {region: {box: {min: [1, 0], max: [2, 2]}}, method: fictitious_layer, face: {point: [1, 0], "
         "normal: [1, 0]}, " +
         right +
         "}\n"
         "  - {region: {box: {min: [0, 1], max: [1, 2]}}, method: fictitious_layer, face: {point: [0, 1], "
         "normal: [0, 1]}, traction: [0, 0]}\n"
         "solver: {tolerance: 1.0e-12}\n";
}

bool in_body(const double* x) { return x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1; }

std::array<double, 2> uniaxial(const double* x) { return {kSigma * x[0] / kE, -kNu * kSigma * x[1] / kE}; }
}  // namespace

TEST(FictitiousLayer, DisplacementMirrorReproducesAnyLinearFieldExactly) {
  // Paper eq. 29 on all four faces with U* = the linear field itself: u_f = 2 U*(x*) - u(x).
  const pd::Scene scene = pd::parse_scene(square_scene("silling_plane_strain"), "square.yaml");
  const pd::Particles p = pd::discretize(scene);
  const double A[2][2] = {{1.3e-3, -0.7e-3}, {0.4e-3, -2.1e-3}}, b[2] = {0.01, -0.02};
  auto field = [&](const double* x) {
    return std::array<double, 3>{A[0][0] * x[0] + A[0][1] * x[1] + b[0],
                                 A[1][0] * x[0] + A[1][1] * x[1] + b[1], 0.0};
  };
  struct Face {
    double xmin, xmax, ymin, ymax, px, py, nx, ny;
  };
  const Face faces[] = {{-1, 0, -1, 2, 0, 0, -1, 0},
                        {0, 2, -1, 0, 0, 0, 0, -1},
                        {1, 2, 0, 2, 1, 0, 1, 0},
                        {0, 1, 1, 2, 0, 1, 0, 1}};
  std::vector<char> layer_of(static_cast<std::size_t>(p.size()), 0);
  std::vector<pd::TiedDof> ties;
  for (const Face& f : faces) {
    std::vector<int> layer;
    std::vector<char> target(static_cast<std::size_t>(p.size()), 1);
    for (int i = 0; i < p.size(); ++i) {
      const double* x = p.position(i);
      if (x[0] > f.xmin && x[0] < f.xmax && x[1] > f.ymin && x[1] < f.ymax && !layer_of[i])
        layer.push_back(i), layer_of[i] = 1, target[i] = 0;
    }
    pd::LayerCondition c;
    c.face.point = {f.px, f.py, 0};
    c.face.normal = {f.nx, f.ny, 0};
    c.prescribed = {true, true, false};
    c.value = field;
    const auto t = pd::fictitious_layer_ties(p, layer, target, c);
    ties.insert(ties.end(), t.begin(), t.end());
  }
  pd::compose_ties(ties, 2 * p.size());
  int tied_particles = 0;
  for (const auto& t : ties) {
    double v = t.offset;
    for (std::size_t k = 0; k < t.masters.size(); ++k) {
      const int m = t.masters[k];
      EXPECT_TRUE(in_body(p.position(m / 2)))
          << "master " << m << " of dof " << t.dof << " is not a body dof";
      v += t.coefficients[k] * field(p.position(m / 2))[m % 2];
    }
    EXPECT_NEAR(v, field(p.position(t.dof / 2))[t.dof % 2], 1e-15) << "dof " << t.dof;
    tied_particles += t.dof % 2 == 0;
  }
  EXPECT_EQ(tied_particles, 22 * 22 - 10 * 10);  // every particle outside the body
}

TEST(FictitiousLayer, TractionLayersReproduceTheUniaxialStressFieldAndHoldThePatchTest) {
  for (const std::string law : {"oterkus_plane_strain", "correspondence_silling_plane_strain"}) {
    SCOPED_TRACE(law);
    const pd::Scene scene = pd::parse_scene(square_scene(law), "square.yaml");
    const pd::Model model =
        pd::build_model(scene, {.matrix = true, .threads = 0, .short_delta = std::nullopt});
    const pd::DofMap dofs = pd::scene_constraints(scene, model.particles);
    const pd::Particles& p = model.particles;
    EXPECT_EQ(dofs.tied_count(), 2 * (22 * 22 - 10 * 10));
    EXPECT_EQ(dofs.free_count(), 2 * 100);
    // The body at the exact field; the layer from the ties.
    Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * p.size());
    for (int i = 0; i < p.size(); ++i)
      if (in_body(p.position(i)))
        u[2 * i] = uniaxial(p.position(i))[0], u[2 * i + 1] = uniaxial(p.position(i))[1];
    dofs.apply_prescribed(u, 1.0);
    for (int i = 0; i < p.size(); ++i)
      for (int c = 0; c < 2; ++c)
        EXPECT_NEAR(u[2 * i + c], uniaxial(p.position(i))[c], 1e-16) << "particle " << i;
    pd::PeridynamicSystem sys(*model.assembler, {});
    Eigen::VectorXd r;
    sys.residual(u, 1.0, r);
    const double scale = r.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    double body = 0, galerkin = 0;
    Eigen::VectorXd pt_r = dofs.restrict_free(r);  // P^T r: the free rows plus coefficient x the tied rows
    for (const auto& t : dofs.ties())
      for (std::size_t k = 0; k < t.masters.size(); ++k)
        if (dofs.free_index(t.masters[k]) >= 0)
          pt_r[dofs.free_index(t.masters[k])] += t.coefficients[k] * r[t.dof];
    body = dofs.restrict_free(r).cwiseAbs().maxCoeff();
    galerkin = pt_r.cwiseAbs().maxCoeff();
    EXPECT_LT(body, 1e-10 * scale);
    EXPECT_GT(galerkin, 1e-2 * scale);
  }
}

TEST(FictitiousLayer, ReducedTangentAndJvpEqualFiniteDifferences) {
  // Silling's law is geometrically nonlinear: at a displacement of a tenth of the spacing
  // the tangent differs from the linear one, so FD checks the real S K(u) P.
  const pd::Scene scene = pd::parse_scene(square_scene("silling_plane_strain"), "square.yaml");
  const pd::Model model = pd::build_model(scene, {.matrix = true, .threads = 0, .short_delta = std::nullopt});
  const pd::DofMap dofs = pd::scene_constraints(scene, model.particles);
  pd::PeridynamicSystem sys(*model.assembler, {});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-0.01, 0.01);
  Eigen::VectorXd uf(dofs.free_count());
  for (int i = 0; i < uf.size(); ++i) uf[i] = U(rng);
  auto full = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(sys.size());
    dofs.expand_free(x, u);
    dofs.apply_prescribed(u, 1.0);
    return u;
  };
  auto reduced_residual = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd r;
    sys.residual(full(x), 1.0, r);
    return Eigen::VectorXd(dofs.restrict_free(r));
  };
  pd::SparseMatrix K;
  sys.tangent(full(uf), 1.0, K, nullptr);
  pd::ReducedSystem red(dofs, K);
  red.update(K);
  const Eigen::MatrixXd Kff(red.Kff());
  const double eps = 1e-7;
  double worst = 0, largest = Kff.cwiseAbs().maxCoeff();
  // Every free column: the ones next to the faces carry the ties' columns.
  for (int j = 0; j < dofs.free_count(); ++j) {
    Eigen::VectorXd xp = uf, xm = uf;
    xp[j] += eps;
    xm[j] -= eps;
    const Eigen::VectorXd fd = -(reduced_residual(xp) - reduced_residual(xm)) / (2 * eps);  // K = -dr/du
    worst = std::max(worst, (fd - Kff.col(j)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-6 * largest);
  // The JVP path of the matrix-free step: restrict_free(J expand_free(v)) = Kff v.
  Eigen::VectorXd v(dofs.free_count()), v_full = Eigen::VectorXd::Zero(sys.size()), Kv;
  for (int i = 0; i < v.size(); ++i) v[i] = std::sin(0.3 * i + 1);
  dofs.expand_free(v, v_full);
  sys.jvp(full(uf), 1.0, v_full, Kv);
  EXPECT_LT((dofs.restrict_free(Kv) - Kff * v).cwiseAbs().maxCoeff(),
            1e-12 * (Kff * v).cwiseAbs().maxCoeff());
}

TEST(FictitiousLayer, StaticSolveGivesTheUniaxialStressSolution) {
  for (const std::string solver : {"", "  linear: matrix_free\n  preconditioner: diagonal\n"}) {
    for (const std::string law : {"oterkus_plane_strain", "correspondence_silling_plane_strain"}) {
      SCOPED_TRACE(law + " " + solver);
      std::string text = square_scene(law);
      if (!solver.empty())
        text.replace(text.find("solver: {tolerance: 1.0e-12}\n"), std::string::npos,
                     "solver:\n  tolerance: 1.0e-12\n" + solver);
      pd::Simulation sim(pd::parse_scene(text, "square.yaml"), [](const std::string&) {});
      const pd::RunSummary s = sim.run(false);
      ASSERT_TRUE(s.newton.converged) << s.newton.message;
      const pd::Particles& p = sim.particles();
      double worst = 0;
      for (int i = 0; i < p.size(); ++i)
        for (int c = 0; c < 2; ++c)
          worst = std::max(worst, std::abs(sim.displacement()[2 * i + c] - uniaxial(p.position(i))[c]));
      EXPECT_LT(worst, 1e-8 * kSigma / kE);
    }
  }
}

TEST(FictitiousLayer, SceneErrorsNameTheCondition) {
  // A face whose mirror images fall outside the domain (the layer deeper than the body).
  std::string text = square_scene("silling_plane_strain");
  const std::string left = "face: {point: [0, 0], normal: [-1, 0]}";
  text.replace(text.find(left), left.size(), "face: {point: [0.8, 0], normal: [-1, 0]}");
  try {
    const pd::Scene scene = pd::parse_scene(text, "square.yaml");
    pd::scene_constraints(scene, pd::discretize(scene));
    ADD_FAILURE() << "no error";
  } catch (const pd::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("square.yaml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("boundary[0]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      pd::parse_scene(square_scene("silling_plane_strain")
                          .replace(square_scene("silling_plane_strain").find("method: fictitious_layer"), 24,
                                   "method: mirror"),
                      "square.yaml"),
      pd::SceneError);
}

TEST(FictitiousLayer, RelaxationAndExplicitDynamicsApplyTheMapEachStep) {
  // Relaxation from u = 0: the layer must follow the body at every iteration to reach the
  // uniaxial-stress solution (a layer frozen at its first values would give another answer).
  {
    std::string text = square_scene("oterkus_plane_strain");
    text +=
        "dynamics: {method: relaxation, tolerance: 1.0e-9, steps: 200000, output_every: 1000, "
        "progress_seconds: 0}\n";
    pd::DynamicSimulation sim(pd::parse_scene(text, "square.yaml"), [](const std::string&) {});
    const pd::RunSummary s = sim.run(false);
    ASSERT_TRUE(s.dynamics && s.dynamics->converged);
    double worst = 0;
    for (int i = 0; i < sim.particles().size(); ++i)
      for (int c = 0; c < 2; ++c)
        worst = std::max(worst,
                         std::abs(sim.displacement()[2 * i + c] - uniaxial(sim.particles().position(i))[c]));
    EXPECT_LT(worst, 1e-5 * kSigma / kE);
  }
  // Explicit: the body starts at the static solution at rest, the layer from the ties at
  // t = 0; an equilibrium, so nothing moves over 200 steps.
  {
    std::string text = square_scene("oterkus_plane_strain");
    text +=
        "dynamics:\n  method: explicit\n  steps: 200\n  output_every: 200\n  progress_seconds: 0\n"
        "  initial:\n    - {region: {box: {min: [0, 0], max: [1, 1]}}, gradient: [[0.001, 0], [0, "
        "-0.00025]], origin: [0, 0]}\n";
    text.replace(text.find("materials:\n  - {E: 1,"), 22, "materials:\n  - {density: 1, E: 1,");
    pd::DynamicSimulation sim(pd::parse_scene(text, "square.yaml"), [](const std::string&) {});
    sim.run(false);
    double worst = 0;
    for (int i = 0; i < sim.particles().size(); ++i)
      for (int c = 0; c < 2; ++c)
        worst = std::max(worst,
                         std::abs(sim.displacement()[2 * i + c] - uniaxial(sim.particles().position(i))[c]));
    EXPECT_LT(worst, 1e-9 * kSigma / kE);  // rounding: the patch-test residual is 1e-10 of the forces
  }
}
