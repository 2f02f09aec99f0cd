// Smoothing by influence-weighted family averages (paper 000 eq. 49): hand-computed
// values, constants everywhere, linear fields in the interior, cracks respected, and
// the scene key's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "discretize/discretization.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "kernel_abi.hpp"
#include "post/smoothing.hpp"

namespace {
pd::Scene box_scene(double perturbation) {
  pd::Scene s;
  s.dim = 2;
  s.lo = {0, 0, 0};
  s.hi = {2, 1.5, 0};
  s.h = 0.1;
  s.perturbation = perturbation;
  s.seed = 5;
  s.materials.resize(1);
  return s;
}
pd::InfluenceWeight influence(const char* name) { return pd::abi::find_influence(name)->weight; }
}  // namespace

TEST(Smoothing, ThreeParticlesInARowByHand) {
  // x = 0, 1, 2; delta = 2, linear influence: w(0) = 1, w(1) = 1/2, w(2) = 0.
  pd::Particles p;
  p.dim = 2;
  p.x = {0, 0, 1, 0, 2, 0};
  p.volume = {1, 2, 1};
  p.material = {0, 0, 0};
  const pd::Bonds b = pd::find_bonds(p, 2.0, influence("linear"));
  const std::vector<double> u{1, 10, 2, 20, 4, 40};  // two components
  const auto s = pd::smooth_field(p, b, influence("linear"), u, 2);
  EXPECT_NEAR(s[0], (1 * 1 + 0.5 * 2 * 2) / (1 + 0.5 * 2), 1e-15);
  EXPECT_NEAR(s[2], (1 * 2 * 2 + 0.5 * 1 + 0.5 * 4) / (2 + 0.5 + 0.5), 1e-15);
  EXPECT_NEAR(s[5], (40 + 0.5 * 2 * 20) / (1 + 0.5 * 2), 1e-13);
}

TEST(Smoothing, ConstantsAreReproducedEverywhere) {
  const pd::Scene scene = box_scene(0.3);
  const pd::Particles p = pd::discretize(scene);
  for (const char* w : {"const", "linear", "cubic", "quarticA"}) {
    pd::Bonds b = pd::find_bonds(p, 0.3, influence(w));
    pd::Crack crack;
    crack.points = {pd::Point{0.5, 0.75, 0}, pd::Point{1.5, 0.75, 0}};
    pd::cut_bonds({crack}, p, b);
    std::vector<double> u(static_cast<std::size_t>(p.size()) * 2);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = i % 2 ? -2.5 : 7.0;
    const auto s = pd::smooth_field(p, b, influence(w), u, 2);
    for (std::size_t i = 0; i < u.size(); ++i) ASSERT_NEAR(s[i], u[i], 1e-14 * 7) << w << " at " << i / 2;
  }
}

TEST(Smoothing, LinearFieldsAreReproducedInTheInteriorOnly) {
  // On the unperturbed lattice a full family is symmetric (sum w xi V = 0), so an
  // affine field is its own average; a family cut by the boundary is one-sided.
  const pd::Scene scene = box_scene(0.0);
  const pd::Particles p = pd::discretize(scene);
  const double delta = 0.3;
  for (const char* w : {"const", "linear", "cubic"}) {
    const pd::Bonds b = pd::find_bonds(p, delta, influence(w));
    std::vector<double> u(static_cast<std::size_t>(p.size()) * 2);
    for (int i = 0; i < p.size(); ++i) {
      const double* x = p.position(i);
      u[2 * i] = 0.3 + 2 * x[0] - x[1];
      u[2 * i + 1] = -1 + 0.5 * x[0] + 3 * x[1];
    }
    const auto s = pd::smooth_field(p, b, influence(w), u, 2);
    double interior = 0, corner = 0;
    for (int i = 0; i < p.size(); ++i) {
      const double* x = p.position(i);
      const double err = std::hypot(s[2 * i] - u[2 * i], s[2 * i + 1] - u[2 * i + 1]);
      if (x[0] > delta && x[0] < 2 - delta && x[1] > delta && x[1] < 1.5 - delta)
        interior = std::max(interior, err);
      if (x[0] < 0.1 && x[1] < 0.1) corner = err;
    }
    EXPECT_LT(interior, 1e-13) << w;
    EXPECT_GT(corner, 1e-2) << w;  // the one-sided average pulls the corner inwards
  }
}

TEST(Smoothing, BrokenBondsDoNotAverageAcrossACrack) {
  pd::Particles p;
  p.dim = 2;
  p.x = {0, 0, 1, 0};
  p.volume = {1, 1};
  p.material = {0, 0};
  pd::Bonds b = pd::find_bonds(p, 1.5, influence("const"));
  pd::Crack crack;
  crack.points = {pd::Point{0.5, -1, 0}, pd::Point{0.5, 1, 0}};
  pd::cut_bonds({crack}, p, b);
  const auto s = pd::smooth_field(p, b, influence("const"), {1, 0, 3, 0}, 2);
  EXPECT_EQ(s[0], 1.0);
  EXPECT_EQ(s[2], 3.0);
}

TEST(Smoothing, SingularInfluenceIsRejected) {
  EXPECT_FALSE(pd::can_smooth_with(influence("inv")));
  EXPECT_FALSE(pd::can_smooth_with(influence("rational_a1_n2")));
  EXPECT_TRUE(pd::can_smooth_with(influence("cubic")));
  pd::Particles p;
  p.dim = 2;
  p.x = {0, 0, 1, 0};
  p.volume = {1, 1};
  p.material = {0, 0};
  const pd::Bonds b = pd::find_bonds(p, 1.5, influence("inv"));
  EXPECT_THROW(pd::smooth_field(p, b, influence("inv"), {1, 0, 3, 0}, 2), std::invalid_argument);
}

TEST(Smoothing, SceneKeyErrorsNameTheLine) {
  const std::string base =
      "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 1]}, count: 4}\nlaw: silling_plane_strain\n"
      "materials: [{E: 1, nu: 0.2}]\n";
  const auto message = [&](const std::string& output) {
    try {
      pd::parse_scene(base + output, "s.yaml");
    } catch (const pd::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(pd::parse_scene(base + "output: {smoothing: {influence: linear}}\n", "s.yaml")
                .output.smoothing_influence,
            "linear");
  EXPECT_TRUE(std::regex_search(
      message("output:\n  smoothing: {influence: inv}\n"),
      std::regex(R"(^s\.yaml:6: output\.smoothing\.influence: 'inv' is singular at r = 0)")))
      << message("output:\n  smoothing: {influence: inv}\n");
  EXPECT_TRUE(std::regex_search(
      message("output: {smoothing: {influence: wobbly}}\n"),
      std::regex(R"(^s\.yaml:5: output\.smoothing\.influence: unknown influence function 'wobbly')")));
  EXPECT_TRUE(std::regex_search(message("output: {smoothing: {influence: linear, radius: 2}}\n"),
                                std::regex(R"(^s\.yaml:5: output\.smoothing\.radius: unknown key)")));
}
