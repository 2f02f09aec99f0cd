// The correspondence law with J2 plasticity (laws/correspondence_plastic.cpp, issue 29):
// the kernels against an independent return map written from the equations with Eigen
// (F = N K^-1, small strain, radial return with linear isotropic hardening, Silling's
// stabilisation), the stabilised elastic law far below yield, the algorithmic tangent
// against central differences of the incremental residual on yielding, unloading and
// reverse-yielding states, and non-negative plastic work over a random load path.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "history_law_cases.hpp"
#include "kernel_abi.hpp"
#include "verify/random_family.hpp"
#include "verify/tangent_check.hpp"

namespace {
using pd::test::max_abs;
using pd::test::max_diff;
using pd::test::scale_deformation;
using pd::verify::FamilyOptions;
using pd::verify::TestFamily;
using pd::verify::Truncation;
using Mat3 = Eigen::Matrix3d;

struct ReturnMap {
  std::vector<double> forces;   // [(L+1)*dim]
  std::vector<double> history;  // the particle history at the end of the step, in the law's order
  Mat3 plastic_increment;       // eps_p,n+1 - eps_p,n
  Mat3 deviator;                // s at the end of the step
  double scale = 1.0;           // 1 elastic, < 1 yielding
};

// The law's per-particle history order: xx, yy, zz, then xy (2D) or xy, xz, yz (3D), then lambda.
std::vector<std::pair<int, int>> stored(int dim) {
  std::vector<std::pair<int, int>> s{{0, 0}, {1, 1}, {2, 2}};
  for (int i = 0; i < dim; ++i)
    for (int j = i + 1; j < dim; ++j) s.emplace_back(i, j);
  return s;
}

// params: K, G, sigma_y, H, stab.
ReturnMap return_map(const TestFamily& f) {
  const int d = f.dim, L = f.bonds();
  const double Kb = f.params[0], G = f.params[1], sigma_y = f.params[2], H = f.params[3], stab = f.params[4];
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(d, d), N = Eigen::MatrixXd::Zero(d, d);
  double wv = 0, v = 0;
  for (int k = 0; k < L; ++k) {
    const Eigen::Map<const Eigen::VectorXd> xi(f.xi.data() + k * d, d), Y(f.Y.data() + k * d, d);
    const double wa = f.w[k] * f.alpha[k];
    K += wa * f.V[k] * xi * xi.transpose();
    N += wa * f.V[k] * Y * xi.transpose();
    wv += wa * f.V[k];
    v += f.alpha[k] * f.V[k];
  }
  const Eigen::MatrixXd Kinv = K.inverse(), F = N * Kinv;
  Mat3 eps = Mat3::Zero();
  eps.topLeftCorner(d, d) = 0.5 * (F + F.transpose()) - Eigen::MatrixXd::Identity(d, d);
  const auto order = stored(d);
  Mat3 ep = Mat3::Zero();
  for (std::size_t n = 0; n < order.size(); ++n)
    ep(order[n].first, order[n].second) = ep(order[n].second, order[n].first) = f.particle_history[n];
  const double lambda = f.particle_history.back();
  const double tr = eps.trace();
  const Mat3 e = eps - ep - tr / 3 * Mat3::Identity();
  const Mat3 s_tr = 2 * G * e;
  const double q = std::sqrt(1.5 * s_tr.squaredNorm()), yield_n = sigma_y + H * lambda;
  ReturnMap out;
  double d_lambda = 0;
  if (q > yield_n) {
    d_lambda = (q - yield_n) / (3 * G + H);
    out.scale = 1 - 3 * G * d_lambda / q;
  }
  out.deviator = out.scale * s_tr;
  out.plastic_increment = d_lambda * 1.5 * s_tr / q;
  const Mat3 ep_new = ep + out.plastic_increment;
  for (const auto& [i, j] : order) out.history.push_back(ep_new(i, j));
  out.history.push_back(lambda + d_lambda);
  const Eigen::MatrixXd sigma = Kb * tr * Eigen::MatrixXd::Identity(d, d) + out.deviator.topLeftCorner(d, d);
  const double c = d == 2 ? 12 * (Kb + G / 3) / (std::numbers::pi * std::pow(f.delta, 3))
                          : 18 * Kb / (std::numbers::pi * std::pow(f.delta, 4));
  const double k_stab = stab * c / (wv / v * f.delta);
  out.forces.assign(static_cast<std::size_t>((L + 1) * d), 0.0);
  for (int k = 0; k < L; ++k) {
    const Eigen::Map<const Eigen::VectorXd> xi(f.xi.data() + k * d, d), Y(f.Y.data() + k * d, d);
    const double wa = f.w[k] * f.alpha[k];
    const Eigen::VectorXd t = wa * (sigma * (Kinv * xi)) + wa * k_stab * (Y - F * xi);
    for (int c2 = 0; c2 < d; ++c2) {
      out.forces[static_cast<std::size_t>(c2)] += f.V0 * f.V[k] * t[c2];
      out.forces[static_cast<std::size_t>((k + 1) * d + c2)] -= f.V0 * f.V[k] * t[c2];
    }
  }
  return out;
}

class CorrespondencePlastic : public testing::TestWithParam<pd::test::HistoryCase> {
 protected:
  const pd::abi::LawDescriptor& law() const { return *pd::abi::find_law(GetParam().law); }
  TestFamily family(unsigned seed, double sigma_y) const {
    FamilyOptions o;
    o.dim = law().dim;
    o.horizon_ratio = o.dim == 2 ? 3.0 : 2.0;
    o.truncation = GetParam().truncation;
    o.broken_bonds = GetParam().broken;
    o.seed = seed;
    TestFamily f = pd::verify::make_family(law(), o);
    f.params[2] = sigma_y;
    return f;
  }
  // A committed plastic state: a trace-free random plastic strain of about 1% and lambda.
  static void commit_random_history(TestFamily& f, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    for (std::size_t n = 0; n + 1 < f.particle_history.size(); ++n) f.particle_history[n] = u(rng);
    const double trace = f.particle_history[0] + f.particle_history[1] + f.particle_history[2];
    for (int n = 0; n < 3; ++n) f.particle_history[static_cast<std::size_t>(n)] -= trace / 3;
    f.particle_history.back() = 0.02 + u(rng);
  }
};

TEST_P(CorrespondencePlastic, KernelsEqualAnIndependentReturnMap) {
  ASSERT_EQ(law().n_particle_history, static_cast<int>(stored(law().dim).size()) + 1);
  int yielding = 0, elastic = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    TestFamily f = family(seed, seed % 2 ? 0.01 : 10.0);
    commit_random_history(f, seed);
    const ReturnMap ref = return_map(f);
    (ref.scale < 1 ? yielding : elastic) += 1;
    EXPECT_LE(max_diff(f.forces(law().damaged), ref.forces), 1e-12 * max_abs(ref.forces)) << "seed " << seed;
    const auto particle_history = f.updated_particle_history(law().damaged);
    EXPECT_LE(max_diff(particle_history, ref.history), 1e-13) << "seed " << seed;
    if (ref.scale == 1.0) {
      EXPECT_EQ(particle_history, f.particle_history) << "an elastic step, to the bit";
    }
  }
  EXPECT_GT(yielding, 0);
  EXPECT_GT(elastic, 0);
}

// Far below yield the law is laws/correspondence.cpp's Silling-stabilised law (same K, G, stab).
TEST_P(CorrespondencePlastic, FarBelowYieldItIsTheStabilisedElasticLaw) {
  TestFamily f = family(4, 1e9);
  const std::string elastic_name =
      std::string("correspondence_silling_") + (law().dim == 2 ? "plane_strain" : "3d");
  const pd::abi::LawDescriptor& elastic = *pd::abi::find_law(elastic_name);
  TestFamily g = f;
  g.law = &elastic;
  g.params = {f.params[0], f.params[1], f.params[4]};
  g.particle_history.clear();
  g.history.clear();
  const auto a = f.forces(law().damaged), b = g.forces(elastic.damaged);
  EXPECT_LE(max_diff(a, b), 1e-13 * max_abs(b));
}

// Load past yield from a virgin state, commit, then unload elastically, unload far enough to
// yield in reverse, and reload: the tangent with the committed history fixed, in each state.
TEST_P(CorrespondencePlastic, AlgorithmicTangentMatchesDifferencesOnYieldingAndUnloadingStates) {
  TestFamily f = family(5, 0.01);
  pd::test::check_tangent_along_a_reversal(law(), f, [](const TestFamily& g) { return return_map(g).scale; });
}

// The plastic work of each step, s_n+1 : (eps_p,n+1 - eps_p,n) V0 from the kernels' update,
// is never negative over a random path of loading, unloading and reversal.
TEST_P(CorrespondencePlastic, DissipationIsNeverNegativeOverARandomPath) {
  TestFamily f = family(7, 0.01);
  const std::vector<double> y_ref = f.y;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const auto order = stored(f.dim);
  double total = 0;
  int plastic_steps = 0;
  for (int step = 0; step < 30; ++step) {
    scale_deformation(f, y_ref, u(rng));
    const ReturnMap ref = return_map(f);
    const auto updated = f.updated_particle_history(law().damaged);
    Mat3 dp = Mat3::Zero();
    for (std::size_t n = 0; n < order.size(); ++n)
      dp(order[n].first, order[n].second) = dp(order[n].second, order[n].first) =
          updated[n] - f.particle_history[n];
    const double work = f.V0 * (ref.deviator.array() * dp.array()).sum();
    EXPECT_GE(work, -1e-14 * f.V0 * ref.deviator.norm() * dp.norm()) << "step " << step;
    total += work;
    plastic_steps += ref.scale < 1;
    f.commit_update(law().damaged);
  }
  EXPECT_GT(plastic_steps, 5);
  EXPECT_GT(total, 0.0);
}

std::vector<pd::test::HistoryCase> cases() {
  std::vector<pd::test::HistoryCase> out;
  for (const char* law : {"correspondence_plastic_plane_strain", "correspondence_plastic_3d"})
    for (Truncation t : {Truncation::Interior, Truncation::Corner})
      for (bool broken : {false, true}) out.push_back({law, t, broken});
  return out;
}
INSTANTIATE_TEST_SUITE_P(J2, CorrespondencePlastic, testing::ValuesIn(cases()), pd::test::history_case_name);

}  // namespace
