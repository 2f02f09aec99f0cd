// The emitter: temporaries for shared nodes, one call per distinct sqrt/pow, powers as products.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

#include "pdgen/kernel_program.hpp"

using namespace pdgen;

namespace {
KernelProgram scalar_program(const std::vector<std::pair<Expr, std::string>>& vars, Expr value) {
  KernelProgram p;
  p.name = "f";
  p.return_type = "double";
  for (auto& [sym, name] : vars) {
    p.params.push_back("double " + name);
    p.param_names.push_back(name);
    p.bindings[symbol_index(sym)] = {name, "", false};
  }
  Segment s;
  s.stores.push_back({"const double out", value, StoreMode::Set, ""});
  p.segments.push_back(s);
  p.epilogue.push_back("return out;");
  return p;
}
}  // namespace

TEST(Emit, SharedSqrtIsComputedOnce) {
  const Expr x = symbol("x"), y = symbol("y");
  const Expr r = sqrt(x * x + y * y);
  const auto k =
      emit_kernel(scalar_program({{x, "x"}, {y, "y"}}, x / r + y / pow(r, 3) + pow(x * x + y * y, 1.5)));
  std::regex call(R"(std::sqrt\([^;]*)");
  EXPECT_EQ(std::distance(std::sregex_iterator(k.code.begin(), k.code.end(), call), std::sregex_iterator()),
            1)
      << k.code;
  EXPECT_EQ(k.code.find("std::pow"), std::string::npos) << k.code;
}

TEST(Emit, SmallIntegerPowersAreProducts) {
  const Expr x = symbol("x");
  const auto k = emit_kernel(scalar_program({{x, "x"}}, pow(x, 3) + pow(x, -2)));
  EXPECT_EQ(k.code.find("pow"), std::string::npos) << k.code;
  EXPECT_NE(k.code.find("x * x"), std::string::npos) << k.code;
}

TEST(Emit, KernelHeaderCarriesOperationCounts) {
  const Expr x = symbol("x"), y = symbol("y");
  const auto k = emit_kernel(scalar_program({{x, "x"}, {y, "y"}}, x * y + x / y + exp(x)));
  // The header's counts are those of the emitted body.
  const std::string body = k.code.substr(k.code.find('{'));
  auto occurrences = [&](const std::string& op) {
    int n = 0;
    for (std::size_t at = body.find(op); at != std::string::npos; at = body.find(op, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(k.per_family.muls, occurrences(" * ")) << k.code;
  EXPECT_EQ(k.per_family.divs, occurrences(" / ")) << k.code;
  EXPECT_EQ(k.per_family.adds, occurrences(" + ") + occurrences(" - ")) << k.code;
  EXPECT_EQ(k.per_family.calls, 1) << k.code;
  EXPECT_EQ(k.per_family.divs, 1) << k.code;
  EXPECT_NE(k.code.find("// f: per bond 0 add, 0 mul, 0 div, 0 call; per family " +
                        std::to_string(k.per_family.adds) + " add, " + std::to_string(k.per_family.muls) +
                        " mul, 1 div, 1 call"),
            std::string::npos)
      << k.code;
}

// Every quotient by the same base shares one reciprocal: three quotients, one division.
TEST(Emit, DivisionsByTheSameBaseShareOneReciprocal) {
  const Expr x = symbol("x"), y = symbol("y"), r = symbol("r");
  const auto k = emit_kernel(scalar_program({{x, "x"}, {y, "y"}, {r, "r"}}, x / r + y / r + x * y / (r * r)));
  EXPECT_EQ(k.per_family.divs, 1) << k.code;
}

TEST(Emit, NodeUsedTwiceBecomesATemporary) {
  const Expr x = symbol("x"), y = symbol("y");
  const Expr s = x + y;
  const auto k = emit_kernel(scalar_program({{x, "x"}, {y, "y"}}, exp(s) * s));
  EXPECT_NE(k.code.find("const double p0 = x + y;"), std::string::npos) << k.code;
}

TEST(Emit, DoublesRoundTrip) {
  for (double v : {0.1, 1.0 / 3.0, 1e-300, 6.02214076e23, 2.0}) EXPECT_EQ(std::stod(cpp_double(v)), v);
  EXPECT_EQ(cpp_double(2.0), "2.0");
}
