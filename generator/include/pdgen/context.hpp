// The arena that owns every node and symbol, and the hash-cons table that makes
// structurally equal expressions the same node (equality is id equality).
#pragma once

#include <unordered_map>
#include <vector>

#include "pdgen/node.hpp"

namespace pdgen {

class Context {
 public:
  // The process-wide context the DSL builds into. The generator is single-threaded.
  static Context& global();

  // Returns the id of the node with these fields, creating it if it is new.
  // No simplification happens here: see expr.cpp for the canonicalising builders.
  NodeId intern(Op op, double value, int symbol, std::vector<NodeId> args);

  const Node& node(NodeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return nodes_.size(); }

  int add_symbol(SymbolInfo info);
  const SymbolInfo& symbol(int index) const { return symbols_[static_cast<std::size_t>(index)]; }
  int symbol_count() const { return static_cast<int>(symbols_.size()); }

 private:
  std::vector<Node> nodes_;
  std::vector<SymbolInfo> symbols_;
  std::unordered_map<std::size_t, std::vector<NodeId>> table_;  // hash -> candidates
};

}  // namespace pdgen
