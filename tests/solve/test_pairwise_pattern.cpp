// A law without states (bond-based) gets the one-horizon pattern: its nonzeros are the
// particle pairs one horizon apart (counted by brute force), its stiffness and the
// solution of a linear system equal those assembled into the two-horizon pattern, and
// a law with states refuses the pairwise pattern.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <set>
#include <utility>

#include "assembly/assembler.hpp"
#include "material/elastic_constants.hpp"
#include "support_grid.hpp"

namespace {
// Unordered particle pairs (and each particle with itself) coupled by some bond.
std::set<std::pair<int, int>> bonded_pairs(const pd::Bonds& B) {
  std::set<std::pair<int, int>> s;
  for (int p = 0; p < B.particle_count(); ++p) {
    s.insert({p, p});
    for (int e = B.offsets[p]; e < B.offsets[p + 1]; ++e)
      s.insert({p, B.neighbor[e]}), s.insert({B.neighbor[e], p});
  }
  return s;
}

std::unique_ptr<pd::FamilyAssembler> make_assembler(const pd::test::Body& body, const char* law_name,
                                                    std::optional<pd::Coupling> coupling) {
  const pd::abi::LawDescriptor* law = pd::abi::find_law(law_name);
  const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.25);
  pd::AssemblerOptions o;
  o.coupling = coupling;
  return std::make_unique<pd::FamilyAssembler>(
      body.particles, body.bonds, *law,
      std::vector<std::vector<double>>{pd::law_parameters(*law, m, pd::PlaneAssumption::Strain, {})}, o);
}

// (K + P) x = b with P a penalty holding the particles of the left column, so K's rigid
// modes do not make the system singular; solved by Eigen's sparse LDL^T.
Eigen::VectorXd clamped_solve(const pd::SparseMatrix& K, const pd::Particles& P) {
  pd::SparseMatrix A = K;
  const double penalty = Eigen::VectorXd(K.diagonal()).cwiseAbs().maxCoeff();
  for (int p = 0; p < P.size(); ++p)
    if (P.x[p * P.dim] < 0.05)
      for (int c = 0; c < P.dim; ++c) A.coeffRef(p * P.dim + c, p * P.dim + c) += penalty;
  Eigen::VectorXd b(K.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::cos(0.37 * static_cast<double>(i));
  Eigen::SimplicialLDLT<pd::SparseMatrix> solver(A);
  EXPECT_EQ(solver.info(), Eigen::Success);
  return solver.solve(b);
}
}  // namespace

TEST(PairwisePattern, NonzerosAreThePairsOneHorizonApart) {
  const auto body = pd::test::make_grid(2, 14, 11, 1, 3.5, 0.2);
  const auto pairs = bonded_pairs(body.bonds);
  const pd::SparsityPattern one(body.bonds, 2, pd::Coupling::pairwise),
      two(body.bonds, 2, pd::Coupling::family);
  EXPECT_EQ(one.nonzeros(), 4 * static_cast<std::int64_t>(pairs.size()));
  // Every stored particle pair is a bonded one.
  for (int b = 0; b < body.particles.size(); ++b)
    for (int a : one.column(b)) EXPECT_TRUE(pairs.count({a, b})) << a << " " << b;
  // Two horizons hold about 2^2 times the sites of one on a lattice; this small body's
  // edges bring it down, but not below 2.5.
  EXPECT_GT(static_cast<double>(two.nonzeros()) / static_cast<double>(one.nonzeros()), 2.5);
}

TEST(PairwisePattern, BondBasedStiffnessAndSolutionEqualTheTwoHorizonOnes) {
  const auto body = pd::test::make_grid(2, 12, 10, 1, 3.0, 0.2);
  const auto pairwise = make_assembler(body, "bond_based_conical_2d", std::nullopt);
  const auto family = make_assembler(body, "bond_based_conical_2d", pd::Coupling::family);
  ASSERT_EQ(pairwise->pattern().coupling(), pd::Coupling::pairwise);  // the law's own choice
  std::vector<double> u(body.particles.x.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 0.03 * std::sin(2.3 * body.particles.x[i] + 0.4 * i);
  pd::SparseMatrix K1, K2;
  pairwise->stiffness(u.data(), K1);
  family->stiffness(u.data(), K2);
  EXPECT_LT(K1.nonZeros() * 2, K2.nonZeros());
  // Same entries where both store one, exact zeros where only the two-horizon one does.
  const Eigen::MatrixXd D1(K1), D2(K2);
  EXPECT_EQ((D1 - D2).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(D1.cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd x1 = clamped_solve(K1, body.particles), x2 = clamped_solve(K2, body.particles);
  EXPECT_LT((x1 - x2).norm(), 1e-12 * x2.norm());
  EXPECT_GT(x2.norm(), 0.0);
}

TEST(PairwisePattern, LawWithStatesRefusesIt) {
  const auto body = pd::test::make_grid(2, 6, 5, 1, 2.0);
  EXPECT_THROW(make_assembler(body, "silling_plane_strain", pd::Coupling::pairwise), std::invalid_argument);
  EXPECT_EQ(make_assembler(body, "silling_plane_strain", std::nullopt)->pattern().coupling(),
            pd::Coupling::family);
}
