// Straightforward recursive evaluation with a per-call memo (the DAG is shared).
#include "pdgen/eval.hpp"

#include <cmath>
#include <stdexcept>

namespace pdgen {

namespace {
double eval_id(NodeId id, const std::unordered_map<int, double>& values,
               std::unordered_map<NodeId, double>& memo) {
  if (auto it = memo.find(id); it != memo.end()) return it->second;
  const Node& n = Context::global().node(id);
  auto a = [&](std::size_t i) { return eval_id(n.args[i], values, memo); };
  double v = 0.0;
  switch (n.op) {
    case Op::Const:
      v = n.value;
      break;
    case Op::Symbol: {
      auto it = values.find(n.symbol);
      if (it == values.end())
        throw std::invalid_argument("evaluate: no value for symbol " +
                                    Context::global().symbol(n.symbol).name);
      v = it->second;
      break;
    }
    case Op::Add:
      for (std::size_t i = 0; i < n.args.size(); ++i) v += a(i);
      break;
    case Op::Mul:
      v = 1.0;
      for (std::size_t i = 0; i < n.args.size(); ++i) v *= a(i);
      break;
    case Op::Pow:
      v = std::pow(a(0), n.value);
      break;
    case Op::Exp:
      v = std::exp(a(0));
      break;
    case Op::Log:
      v = std::log(a(0));
      break;
    case Op::Abs:
      v = std::fabs(a(0));
      break;
    case Op::Sign: {
      const double x = a(0);
      v = x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
      break;
    }
    case Op::Select:
      v = a(0) > 0.0 ? a(1) : a(2);
      break;
  }
  memo[id] = v;
  return v;
}
}  // namespace

double evaluate(Expr e, const std::unordered_map<int, double>& values) {
  std::unordered_map<NodeId, double> memo;
  return eval_id(e.id(), values, memo);
}

}  // namespace pdgen
