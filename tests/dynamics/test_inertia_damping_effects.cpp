// Inertia and viscous damping are effects of the model, and the prescribed motion's
// functions of time live on the model's dof map (issue 13). Checked against the
// formulas written out here, not against the code's own numbers: the mass is rho V, the
// damped and undamped Verlet half steps are docs/dynamics.md's, and the prescribed motion
// follows a ramp's closed-form integral and a sine.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "dynamics/verlet_integrator.hpp"
#include "effects/inertia.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"

namespace {
// A 10 x 5 plate of cells (spacing 0.01, particles at the cell centres): the left column
// held, the right column below the top row driven at a velocity 0.5 in x ramped over
// T = 0.2, the rest of the top row's y displacement 0.003 sin(2 pi t / 0.4).
std::string plate(const std::string& dynamics) {
  return "dimension: 2\n"
         "domain: {box: {min: [0, 0], max: [0.1, 0.05]}, spacing: 0.01}\n"
         "horizon: {ratio: 3.0}\n"
         "law: silling_plane_strain\n"
         "influence: const\n"
         "materials: [{name: m, E: 1.0, nu: 0.0, density: 2.5}]\n"
         "boundary:\n"
         "  - region: {box: {min: [-1, -1], max: [0.01, 1]}}\n"
         "    fixed: [x, y]\n"
         "  - region: {box: {min: [0.09, -1], max: [1, 0.04]}}\n"
         "    velocity: {x: 0.5}\n"
         "    time_function: {ramp: 0.2}\n"
         "  - region: {box: {min: [0.01, 0.04], max: [1, 1]}}\n"
         "    displacement: {y: 0.003}\n"
         "    time_function: {sine: {period: 0.4}}\n"
         "dynamics: {" +
         dynamics + "}\n";
}

// The same plate held on the left only; `extra`: more top-level keys.
std::string held_plate(const std::string& extra) {
  return "dimension: 2\ndomain: {box: {min: [0, 0], max: [0.1, 0.05]}, spacing: 0.01}\nhorizon: {ratio: "
         "3.0}\n"
         "law: silling_plane_strain\ninfluence: const\nmaterials: [{name: m, E: 1.0, nu: 0.0}]\n"
         "boundary:\n  - region: {box: {min: [-1, -1], max: [0.01, 1]}}\n    fixed: [x, y]\n" +
         extra;
}

pd::Model dynamic_model(const pd::Scene& s) {
  return pd::build_model(s, {.matrix = false, .threads = 1, .short_delta = std::nullopt});
}
}  // namespace

TEST(InertiaEffect, TheModelOwnsTheMassAndListsItLast) {
  const pd::Scene s =
      pd::parse_scene(plate("method: explicit, steps: 1, damping: 0.7, threads: 1"), "plate.yaml");
  const pd::Model m = dynamic_model(s);
  ASSERT_NE(m.inertia, nullptr);
  ASSERT_NE(m.damping, nullptr);
  ASSERT_GE(m.effects.size(), 2u);
  EXPECT_EQ(m.effects[m.effects.size() - 2].get(), m.inertia);
  EXPECT_EQ(m.effects.back().get(), m.damping);
  EXPECT_EQ(m.effects[m.effects.size() - 2]->name(), "inertia");
  EXPECT_EQ(m.damping->describe(), "viscous damping: a = f/m - c v, c = 0.7");
  const std::size_t N = static_cast<std::size_t>(m.particles.size()) * 2;
  ASSERT_EQ(m.inertia->mass().size(), N);
  EXPECT_EQ(m.inertia->allocated_bytes(), 2 * N * sizeof(double));  // m and 1/m
  for (int p = 0; p < m.particles.size(); ++p)
    for (int c = 0; c < 2; ++c) {
      const std::size_t i = static_cast<std::size_t>(p) * 2 + c;
      EXPECT_EQ(m.inertia->mass()[i], 2.5 * m.particles.volume[p]);
      EXPECT_EQ(m.inertia->inverse_mass()[i], 1.0 / (2.5 * m.particles.volume[p]));
    }
  EXPECT_GT(m.inertia->dt, 0.0);
  EXPECT_NEAR(m.inertia->dt, 0.8 * m.inertia->dt_stable, 1e-15 * m.inertia->dt);
}

TEST(InertiaEffect, NoDampingEffectWithoutDampingAndNoneInAStaticModel) {
  const pd::Model undamped =
      dynamic_model(pd::parse_scene(plate("method: explicit, steps: 1, threads: 1"), "plate.yaml"));
  EXPECT_NE(undamped.inertia, nullptr);
  EXPECT_EQ(undamped.damping, nullptr);
  for (const auto& e : undamped.effects) EXPECT_NE(e->name(), "viscous damping");
  const pd::Model m = dynamic_model(pd::parse_scene(held_plate(""), "still.yaml"));
  EXPECT_EQ(m.inertia, nullptr);
  for (const auto& e : m.effects) EXPECT_NE(e->name(), "inertia");
}

TEST(InertiaEffect, RelaxationsFictitiousDensityIsAQuarterOfTheRowSums) {
  const pd::Model m =
      dynamic_model(pd::parse_scene(held_plate("dynamics: {method: relaxation, steps: 10}\n"), "relax.yaml"));
  ASSERT_NE(m.inertia, nullptr);
  EXPECT_EQ(m.damping, nullptr);
  EXPECT_TRUE(m.inertia->inverse_mass().empty());
  // Row sums of |K| by a separate assembly with a matrix.
  pd::AssemblerOptions o;
  o.intact = true;
  const pd::FamilyAssembler a(m.particles, m.bonds, *m.law, m.params, o);
  pd::SparseMatrix K = a.make_matrix();
  a.stiffness(nullptr, K);
  std::vector<double> rows(static_cast<std::size_t>(K.rows()), 0.0);
  for (int c = 0; c < K.outerSize(); ++c)
    for (pd::SparseMatrix::InnerIterator it(K, c); it; ++it)
      rows[static_cast<std::size_t>(it.row())] += std::fabs(it.value());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_GT(rows[i], 0.0);
    EXPECT_NEAR(m.inertia->mass()[i], 0.25 * rows[i], 1e-12 * rows[i]) << i;
  }
}

TEST(VerletWithEffects, HalfStepsAreTheDampedAndUndampedFormulas) {
  const pd::Scene s =
      pd::parse_scene(plate("method: explicit, steps: 1, damping: 0.7, threads: 1"), "plate.yaml");
  const pd::Model m = dynamic_model(s);
  const std::vector<int>& free = m.dofs.free_dofs();
  const std::size_t N = m.inertia->mass().size();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-1, 1);
  std::vector<double> u(N), v(N), f(N), f2(N);
  for (std::size_t i = 0; i < N; ++i) u[i] = r(rng), v[i] = r(rng), f[i] = r(rng), f2[i] = r(rng);
  const double dt = 1e-3, h = 0.5 * dt, c = 0.7;
  for (const pd::ViscousDamping* damping : {m.damping, static_cast<const pd::ViscousDamping*>(nullptr)}) {
    const double cc = damping ? c : 0.0;
    std::vector<double> ue = u, ve = v, ua = u, va = v;
    for (int i : free) {
      const double minv = 1.0 / (2.5 * m.particles.volume[i / 2]);
      ve[i] = ve[i] + h * (f[i] * minv - cc * ve[i]);
      ue[i] = ue[i] + dt * ve[i];
      ve[i] = (ve[i] + h * f2[i] * minv) / (1.0 + cc * h);
    }
    const pd::VerletIntegrator verlet(*m.inertia, damping, free, dt);
    verlet.first_half(ua, va, f);
    verlet.second_half(va, f2);
    for (std::size_t i = 0; i < N; ++i) {
      EXPECT_NEAR(ua[i], ue[i], 1e-15) << i;
      EXPECT_NEAR(va[i], ve[i], 1e-13 * (1 + std::fabs(ve[i]))) << i;
    }
    for (int i : m.dofs.constrained_dofs())
      EXPECT_EQ(ua[static_cast<std::size_t>(i)], u[static_cast<std::size_t>(i)]);
  }
}

TEST(DofMapMotion, TheModelsDofMapCarriesEachConditionsFunctionOfTime) {
  const pd::Scene s = pd::parse_scene(plate("method: explicit, steps: 1, threads: 1"), "plate.yaml");
  const pd::DiscretizedBody m(s);
  const pd::DofMap& dofs = m.dofs;
  // 5 held particles (x and y), 4 driven in x (right column below the top row), 9 top-row
  // particles right of the held column with y prescribed.
  EXPECT_EQ(dofs.constrained_count(), 10 + 4 + 9);
  const std::size_t N = static_cast<std::size_t>(m.particles.size()) * 2;
  for (double t : {0.0, 0.05, 0.2, 0.37}) {
    std::vector<double> u(N, 9.0), v(N, 9.0);
    dofs.apply_motion(t, u, v);
    const double ramp = std::min(t / 0.2, 1.0);
    const double ramp_integral = t <= 0.2 ? t * t / (2 * 0.2) : 0.1 + (t - 0.2);
    const double w = 2 * std::numbers::pi / 0.4;
    for (int p = 0; p < m.particles.size(); ++p) {
      const double x = m.particles.position(p)[0], y = m.particles.position(p)[1];
      for (int c = 0; c < 2; ++c) {
        const std::size_t i = static_cast<std::size_t>(p) * 2 + c;
        if (x < 0.01) {
          EXPECT_EQ(u[i], 0.0);
          EXPECT_EQ(v[i], 0.0);
        } else if (c == 0 && x > 0.09 && y < 0.04) {
          EXPECT_NEAR(u[i], 0.5 * ramp_integral, 1e-15);
          EXPECT_NEAR(v[i], 0.5 * ramp, 1e-15);
        } else if (c == 1 && y > 0.04) {
          EXPECT_NEAR(u[i], 0.003 * std::sin(w * t), 1e-15);
          EXPECT_NEAR(v[i], 0.003 * w * std::cos(w * t), 1e-13);
        } else {
          EXPECT_EQ(u[i], 9.0);  // free: untouched
          EXPECT_EQ(v[i], 9.0);
        }
      }
    }
  }
  std::vector<double> u(N, 0.0), none;
  dofs.apply_motion(0.1, u, none);  // no velocity array (relaxation): displacements only
}
