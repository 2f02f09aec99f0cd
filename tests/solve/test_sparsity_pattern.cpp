// Sparsity pattern against the brute-force union of family blocks; slots address the
// entries they claim; the family colouring never puts two families sharing a particle
// in one colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "assembly/family_colouring.hpp"
#include "assembly/sparsity_pattern.hpp"
#include "support_grid.hpp"

namespace {
std::set<std::pair<int, int>> brute_force_entries(const pd::Bonds& B, int dim) {
  std::set<std::pair<int, int>> s;
  for (int p = 0; p < B.particle_count(); ++p) {
    std::vector<int> members{p};
    for (int e = B.offsets[p]; e < B.offsets[p + 1]; ++e) members.push_back(B.neighbor[e]);
    for (int a : members)
      for (int b : members)
        for (int r = 0; r < dim; ++r)
          for (int q = 0; q < dim; ++q) s.insert({a * dim + r, b * dim + q});
  }
  return s;
}

void check_pattern(int dim, int nx, int ny, int nz, double ratio) {
  const auto body = pd::test::make_grid(dim, nx, ny, nz, ratio, 0.3);
  const pd::SparsityPattern pat(body.bonds, dim);
  const pd::SparseMatrix K = pat.matrix();
  std::set<std::pair<int, int>> got;
  for (int j = 0; j < K.outerSize(); ++j)
    for (pd::SparseMatrix::InnerIterator it(K, j); it; ++it) got.insert({static_cast<int>(it.row()), j});
  EXPECT_EQ(static_cast<long long>(got.size()), K.nonZeros()) << "duplicate entries";
  EXPECT_EQ(got, brute_force_entries(body.bonds, dim));
  EXPECT_EQ(pat.nonzeros(), K.nonZeros());
  // Every family slot: block (a, b) entry (r, q) is at row qa*dim+r, column qb*dim+q.
  const auto& B = body.bonds;
  for (int p = 0; p < B.particle_count(); ++p) {
    const int L = B.family_size(p);
    const auto slots = pat.family_slots(p);
    ASSERT_EQ(static_cast<int>(slots.size()), (L + 1) * (L + 1));
    for (int a = 0; a <= L; ++a)
      for (int b = 0; b <= L; ++b) {
        const int qa = a == 0 ? p : B.neighbor[B.offsets[p] + a - 1];
        const int qb = b == 0 ? p : B.neighbor[B.offsets[p] + b - 1];
        for (int r = 0; r < dim; ++r)
          for (int q = 0; q < dim; ++q) {
            const int s = slots[b * (L + 1) + a] + q * pat.column_stride(qb) + r;  // column-major slots
            const int col = qb * dim + q;
            ASSERT_GE(s, K.outerIndexPtr()[col]);
            ASSERT_LT(s, K.outerIndexPtr()[col + 1]);
            ASSERT_EQ(K.innerIndexPtr()[s], qa * dim + r);
          }
      }
  }
}
}  // namespace

TEST(SparsityPattern, EqualsBruteForceUnion2D) { check_pattern(2, 9, 7, 1, 2.5); }
TEST(SparsityPattern, EqualsBruteForceUnion3D) { check_pattern(3, 4, 4, 3, 1.6); }

TEST(SparsityPattern, BlockBaseRejectsUncoupledParticles) {
  const auto body = pd::test::make_grid(2, 12, 3, 1, 1.5);
  const pd::SparsityPattern pat(body.bonds, 2);
  EXPECT_THROW((void)pat.block_base(0, 11), std::out_of_range);
  EXPECT_NO_THROW((void)pat.block_base(0, 2));  // two horizons apart: share the family of particle 1
}

TEST(FamilyColouring, FamiliesOfOneColourShareNoParticle) {
  const auto body = pd::test::make_grid(2, 23, 17, 1, 3.0, 0.2);
  const auto& B = body.bonds;
  for (int chunk : {0, 1, 5, 40}) {
    const pd::FamilyColouring col(body.particles, B, chunk);
    std::vector<int> seen_families(static_cast<std::size_t>(B.particle_count()), 0);
    for (int c = 0; c < col.colours(); ++c) {
      std::vector<int> owner(static_cast<std::size_t>(B.particle_count()), -1);
      for (int i = col.colour_start(c); i < col.colour_start(c + 1); ++i) {
        const int ch = col.chunk_id(i);
        for (int j = col.chunk_begin(ch); j < col.chunk_end(ch); ++j) {
          const int p = col.family(j);
          ++seen_families[p];
          auto claim = [&](int q) {
            ASSERT_TRUE(owner[q] == -1 || owner[q] == ch)
                << "particle " << q << " in two chunks of colour " << c;
            owner[q] = ch;
          };
          claim(p);
          for (int e = B.offsets[p]; e < B.offsets[p + 1]; ++e) claim(B.neighbor[e]);
        }
      }
    }
    for (int v : seen_families) ASSERT_EQ(v, 1) << "every family exactly once";
    EXPECT_LT(col.colours(), B.particle_count()) << "colouring should group chunks";
  }
}

TEST(FamilyColouring, DefaultChunksAreTilesTwoHorizonsWide) {
  const auto body = pd::test::make_grid(2, 30, 24, 1, 2.5, 0.2);  // h = 0.1: tiles 0.5 wide
  const pd::FamilyColouring col(body.particles, body.bonds);
  EXPECT_GT(col.chunks(), 12);
  for (int ch = 0; ch < col.chunks(); ++ch) {
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
    for (int j = col.chunk_begin(ch); j < col.chunk_end(ch); ++j)
      for (int c = 0; c < 2; ++c) {
        const double x = body.particles.x[col.family(j) * 2 + c];
        lo[c] = std::min(lo[c], x), hi[c] = std::max(hi[c], x);
      }
    for (int c = 0; c < 2; ++c) EXPECT_LE(hi[c] - lo[c], 2 * 0.25 + 1e-12) << "chunk " << ch;
  }
}
