// The reproducing-space facts pdgen writes into a law's descriptor: the declared groups and
// kernel as declared, and the refusal of a kernel that contradicts the derived use of w.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "pdgen/dsl.hpp"
#include "pdgen/files.hpp"

using namespace pdgen;

namespace {
// A bond-based spring that reads w or not.
Law spring(bool reads_w) {
  Law law("facts_law", 2, "test");
  const Expr r = norm(law.xi()), l = law.deformed_length();
  const Expr c = reads_w ? law.w() * law.param("k") : law.param("k");
  law.force(c * (l - r) / r * law.Y() / l);
  return law;
}

std::string descriptor_text(const Law& law) {
  GeneratedFiles files;
  files.add_law("facts", law, {});
  return files.files().at("facts.cpp");
}
}  // namespace

TEST(LawFacts, DeclaredGroupsAndKernelAreCopiedInOrder) {
  Law law = spring(false);
  law.reproducing_terms(3, 4, 3);
  law.reproducing_terms(1, 2, 1);
  law.built_in_kernel("micromodulus 1 - r/delta", {{1.0, 0}, {-1.0, 1}});
  const std::string text = descriptor_text(law);
  EXPECT_NE(text.find("reproducing_groups[] = {{3, 4, 3}, {1, 2, 1}, };"), std::string::npos) << text;
  EXPECT_NE(text.find("d.n_reproducing_groups = 2;"), std::string::npos);
  EXPECT_NE(text.find("kernel_terms[] = {{1.0, 0}, {-1.0, 1}, };"), std::string::npos) << text;
  EXPECT_NE(text.find("d.kernel_description = \"micromodulus 1 - r/delta\";"), std::string::npos);
  EXPECT_NE(text.find("d.ignores_influence = true;"), std::string::npos);
}

TEST(LawFacts, ALawThatReadsWHasNoKernelLine) {
  Law law = spring(true);
  law.reproducing_terms(3, 4, 2);
  const std::string text = descriptor_text(law);
  EXPECT_NE(text.find("d.n_reproducing_groups = 1;"), std::string::npos) << text;
  EXPECT_EQ(text.find("kernel_terms"), std::string::npos) << text;
  // No declaration: no lines, the runtime refuses obq_space: law for it.
  EXPECT_EQ(descriptor_text(spring(true)).find("reproducing_groups"), std::string::npos);
}

TEST(LawFacts, AKernelContradictingTheUseOfWIsRefused) {
  Law reads = spring(true);
  reads.reproducing_terms(3, 4, 2);
  reads.built_in_kernel("constant", {{1.0, 0}});
  EXPECT_THROW(descriptor_text(reads), std::invalid_argument);
  Law ignores = spring(false);
  ignores.reproducing_terms(3, 4, 3);  // and no kernel
  try {
    descriptor_text(ignores);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("built_in_kernel"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("facts_law"), std::string::npos) << e.what();
  }
  EXPECT_THROW(spring(false).reproducing_terms(4, 3, 2), std::invalid_argument);
}

// A parameter's declared range is written into the descriptor in parameter order, and a
// test value outside it is refused where the law is written.
TEST(LawFacts, ParameterRangesAreCopiedInOrderAndTestValuesMustLieInThem) {
  Law law = spring(false);
  law.param("yield", 0.5, ParamRange::positive);
  law.param("hardening", 0.0, ParamRange::non_negative);
  const std::string text = descriptor_text(law);
  EXPECT_NE(text.find("ranges[] = {pd::abi::ParamRange::any, pd::abi::ParamRange::positive, "
                      "pd::abi::ParamRange::non_negative, "),
            std::string::npos)
      << text;
  EXPECT_THROW(law.param("tau", 0.0, ParamRange::positive), std::invalid_argument);
  EXPECT_THROW(law.param("weight", -1.0, ParamRange::non_negative), std::invalid_argument);
}
