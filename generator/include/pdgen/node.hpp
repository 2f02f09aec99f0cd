// Expression nodes: immutable, interned in an arena, addressed by a small id.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pdgen {

enum class Op : std::uint8_t {
#define PD_OP(name, doc) name,
#include "pdgen/ops.def"
#undef PD_OP
};

using NodeId = std::int32_t;

// What a symbol stands for; decides where a value lives in a kernel.
enum class SymbolKind : std::uint8_t {
  Free,           // a plain variable (tests, influence functions: r, delta)
  BondInput,      // per-bond input: xi, Y, w, alpha, V, direction dY
  ParticleInput,  // per-particle input: V0, delta
  Param,          // material parameter
  Sum,            // a horizon sum (moment or state) or a per-particle value defined by one
};

struct SymbolInfo {
  std::string name;
  SymbolKind kind = SymbolKind::Free;
};

struct Node {
  Op op = Op::Const;
  double value = 0.0;        // Const: the value; Pow: the exponent
  int symbol = -1;           // Symbol: index into the symbol table
  std::vector<NodeId> args;  // operands (canonical order for Add/Mul)
  std::size_t hash = 0;
};

}  // namespace pdgen
