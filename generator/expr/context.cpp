// Arena and hash-consing of expression nodes.
#include "pdgen/context.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace pdgen {

Context& Context::global() {
  static Context ctx;
  return ctx;
}

namespace {
std::size_t mix(std::size_t h, std::size_t v) {
  return h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}

std::size_t hash_fields(Op op, double value, int symbol, const std::vector<NodeId>& args) {
  std::size_t h = static_cast<std::size_t>(op);
  h = mix(h, std::bit_cast<std::uint64_t>(value));
  h = mix(h, static_cast<std::size_t>(symbol + 1));
  for (NodeId a : args) h = mix(h, static_cast<std::size_t>(a));
  return h;
}

bool same_fields(const Node& n, Op op, double value, int symbol, const std::vector<NodeId>& args) {
  // Bitwise comparison of the value keeps 0.0 and -0.0 apart and makes NaN equal to itself.
  return n.op == op && std::bit_cast<std::uint64_t>(n.value) == std::bit_cast<std::uint64_t>(value) &&
         n.symbol == symbol && n.args == args;
}
}  // namespace

NodeId Context::intern(Op op, double value, int symbol, std::vector<NodeId> args) {
  if (value == 0.0) value = 0.0;  // fold -0.0
  const std::size_t h = hash_fields(op, value, symbol, args);
  auto& bucket = table_[h];
  for (NodeId id : bucket)
    if (same_fields(nodes_[static_cast<std::size_t>(id)], op, value, symbol, args)) return id;
  const auto id = static_cast<NodeId>(nodes_.size());
  nodes_.push_back(Node{op, value, symbol, std::move(args), h});
  bucket.push_back(id);
  return id;
}

int Context::add_symbol(SymbolInfo info) {
  symbols_.push_back(std::move(info));
  return static_cast<int>(symbols_.size()) - 1;
}

}  // namespace pdgen
