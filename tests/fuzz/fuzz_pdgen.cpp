// Fuzz target for the law DSL front end and the generator behind it: the input is a
// small stack program that builds a random force state from the DSL's leaves (K, G, |xi|,
// the deformed length, w, alpha, V, constants, earlier horizon sums) and operations (+ - *
// /, powers, sqrt, exp, log, abs, sign, select, max, min, a horizon sum of the top); the
// law t = top * Y / |Y| (and, when the program asks, an energy) then goes through every
// stage pdgen runs for a registered law, damaged and intact. It must emit kernels or refuse
// the law with a message (std::invalid_argument, or NonFiniteConstant for a constant that
// folds to NaN or infinity) -- never crash, hang, throw an internal error (std::logic_error
// and the rest are not caught: libFuzzer reports them) or emit a non-finite constant.
//
// Built with clang as `fuzz_pdgen` (PD_FUZZ); without libFuzzer the same entry point
// replays tests/fuzz/corpus/pdgen/ as a ctest (replay_main.cpp).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_verdict.hpp"
#include "pdgen/dsl.hpp"
#include "pdgen/files.hpp"

namespace {
using namespace pdgen;

constexpr std::size_t kMaxOps = 48, kMaxStack = 12, kMaxSums = 4;

// The leaf `k` of the law (constants from the next byte).
Expr leaf(Law& law, const Expr& K, const Expr& G, const std::vector<Expr>& sums, int k, std::uint8_t next) {
  switch (k % 9) {
    case 0:
      return K;
    case 1:
      return G;
    case 2:
      return norm(law.xi());
    case 3:
      return law.deformed_length();
    case 4:
      return law.w();
    case 5:
      return law.alpha();
    case 6:
      return law.V();
    case 7:
      return Expr((static_cast<int>(next) - 128) / 16.0);
    default:
      return sums.empty() ? Expr(1.0) : sums[next % sums.size()];
  }
}

// Runs the program; the law's force is the top of the stack times the unit bond.
Law build(const std::uint8_t* data, std::size_t size) {
  Law law("fuzz_law", 2 + (size > 0 ? data[0] & 1 : 0), "a random law");
  const Expr K = law.param("K", 3.0), G = law.param("G", 1.5);
  std::vector<Expr> stack, sums;
  bool energy = false;
  for (std::size_t i = 1, ops = 0; i < size && ops < kMaxOps; ++i, ++ops) {
    const std::uint8_t op = data[i], next = i + 1 < size ? data[i + 1] : 0;
    const auto pop = [&] {
      const Expr e = stack.back();
      stack.pop_back();
      return e;
    };
    const int code = op % 20;
    if (code < 3 || stack.empty()) {  // leaves are the commonest word
      if (stack.size() < kMaxStack) stack.push_back(leaf(law, K, G, sums, op / 20, next));
      if ((op / 20) % 9 == 7) ++i;  // a constant consumed its byte
      continue;
    }
    if (code >= 14 && code <= 17 && stack.size() < 2) continue;  // binary needs two
    switch (code) {
      case 3:
        stack.push_back(sqrt(pop()));
        break;
      case 4:
        stack.push_back(exp(pop()));
        break;
      case 5:
        stack.push_back(log(pop()));
        break;
      case 6:
        stack.push_back(abs(pop()));
        break;
      case 7:
        stack.push_back(sign(pop()));
        break;
      case 8:
        stack.push_back(pow(pop(), (static_cast<int>(next % 9) - 4) / 2.0)), ++i;
        break;
      case 9:
        stack.push_back(-pop());
        break;
      case 10:
        if (sums.size() < kMaxSums) {
          sums.push_back(law.sum("s" + std::to_string(sums.size()), pop()));
          stack.push_back(sums.back());
        }
        break;
      case 11:
        if (stack.size() >= 3) {
          const Expr b = pop(), a = pop(), c = pop();
          stack.push_back(select(c, a, b));
        }
        break;
      case 12:
        energy = true;
        break;
      case 13:
        stack.push_back(stack.back());
        break;
      case 14: {
        const Expr b = pop(), a = pop();
        stack.push_back(a + b);
      } break;
      case 15: {
        const Expr b = pop(), a = pop();
        stack.push_back(a * b);
      } break;
      case 16: {
        const Expr b = pop(), a = pop();
        stack.push_back(a / b);
      } break;
      case 17: {
        const Expr b = pop(), a = pop();
        stack.push_back(op & 0x80 ? max(a, b) : min(a, b));
      } break;
      default: {
        if (stack.size() >= 2) {
          const Expr b = pop(), a = pop();
          stack.push_back(a - b);
        }
      } break;
    }
  }
  const Expr t = stack.empty() ? law.w() : stack.back();
  law.force(t * law.Y() / law.deformed_length());
  if (energy && stack.size() >= 2) law.energy(stack[stack.size() - 2]);
  return law;
}

// A literal the emitter must never write: NaN or infinity spelled in any way C++ reads.
const std::regex kNonFinite(R"(\b(nan|NAN|inf|INFINITY|HUGE_VAL|numeric_limits)\b)");

void check_code(const EmittedVariant& v) {
  for (const NamedKernel& k : v.kernels)
    if (std::regex_search(k.emitted.code, kNonFinite)) std::abort();
}
}  // namespace

// PD_FUZZ_VERBOSE=1 prints what became of each input (a corpus's reach, at a glance).
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool verbose = std::getenv("PD_FUZZ_VERBOSE") != nullptr;
  law_under_construction().clear();
  try {
    const Law law = build(data, size);
    const EmittedVariant damaged = emit_variant(law, "damaged");
    check_code(damaged);
    check_code(emit_variant(law.with_alpha_folded(), "intact"));
    pdfuzz::accepted = true;
    if (verbose)
      std::printf("emitted %zu kernels, %d sums\n", damaged.kernels.size(),
                  damaged.n_moments + damaged.n_states);
  } catch (const std::invalid_argument& e) {
    if (verbose) std::printf("refused: %s\n", e.what());
  } catch (const NonFiniteConstant& e) {
    if (verbose) std::printf("refused: %s\n", e.what());
  }
  return 0;
}
