// Kernels keep no hidden state: their per-bond cache is the caller's Family::scratch, of
// the size the descriptor declares. A kernel must write the scratch before reading it
// and stay inside L * scratch_per_bond doubles.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "law_list.hpp"
#include "verify/random_family.hpp"

namespace {
class KernelScratch : public testing::TestWithParam<const pd::abi::LawDescriptor*> {};
}  // namespace

TEST_P(KernelScratch, KernelsUseOnlyTheDeclaredScratchAndWriteItBeforeReading) {
  const auto& law = *GetParam();
  pd::verify::FamilyOptions o;
  o.dim = law.dim;
  o.horizon_ratio = law.dim == 2 ? 3.0 : 2.0;
  pd::verify::TestFamily f = pd::verify::make_family(law, o);
  const auto reference = f.forces(law.damaged);
  const auto reference_tangent = f.tangent_matrix(law.damaged);
  const std::size_t used = static_cast<std::size_t>(f.bonds() * law.scratch_per_bond), guard = 64;
  const double nan = std::numeric_limits<double>::quiet_NaN(), marker = -12345.0;
  std::vector<double> scratch(used + guard, marker);
  std::fill(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(used),
            nan);  // stale contents: NaN
  pd::abi::Family fam = f.view();
  fam.scratch = scratch.data();
  std::vector<double> forces(reference.size());
  law.damaged.residual(fam, forces.data());
  for (std::size_t i = 0; i < forces.size(); ++i) EXPECT_EQ(forces[i], reference[i]) << i;
  pd::TangentScratch ts;
  const auto fac = ts.view(f.dim, law.n_states, f.bonds());
  std::fill(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(used), nan);
  law.damaged.tangent(fam, nullptr, fac);
  std::vector<double> M(reference_tangent.size());
  pd::form_local_matrix(f.dim, law.n_states, fam, fac, M.data());
  for (std::size_t i = 0; i < M.size(); ++i) ASSERT_EQ(M[i], reference_tangent[i]) << i;
  std::vector<double> dy(reference.size(), 0.25), df(reference.size());
  law.damaged.jvp(fam, dy.data(), df.data());
  law.intact.jvp(fam, dy.data(), df.data());
  for (double v : df) EXPECT_TRUE(std::isfinite(v));
  for (std::size_t i = used; i < scratch.size(); ++i)
    EXPECT_EQ(scratch[i], marker) << "wrote past the declared scratch";
}

INSTANTIATE_TEST_SUITE_P(AllLaws, KernelScratch, testing::ValuesIn(pd::test::all_law_descriptors()),
                         pd::test::law_name);

TEST(KernelScratch, NoGeneratedSourceHoldsThreadLocalOrStaticState) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(PD_GENERATED_DIR)) {
    if (entry.path().extension() != ".cpp") continue;
    std::ifstream in(entry.path());
    std::ostringstream s;
    s << in.rdbuf();
    ++files;
    EXPECT_EQ(s.str().find("thread_local"), std::string::npos) << entry.path().filename();
    EXPECT_EQ(s.str().find("std::vector"), std::string::npos) << entry.path().filename();
  }
  EXPECT_GT(files, 3);
  int with_scratch = 0;
  for (const auto& law : pd::abi::all_laws()) with_scratch += law.scratch_per_bond > 0;
  EXPECT_GT(with_scratch, 0);  // the cache exists: the size test above is not vacuous
}
