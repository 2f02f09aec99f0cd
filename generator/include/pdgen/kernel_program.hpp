// A kernel as the law-model stage hands it to the emitter: symbol bindings plus an
// ordered list of straight-line and per-bond segments whose statements store
// expressions into C++ lvalues. The emitter decides temporaries, hoisting and order.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "pdgen/expr.hpp"

namespace pdgen {

// How a symbol appears in C++: a variable `var`, initialised from `load` where the
// emitter first needs it (per bond inside each loop, or once per family); with an
// empty `load` the program declares the variable itself (accumulated sums).
struct Binding {
  std::string var;
  std::string load;
  bool per_bond = false;
};

enum class StoreMode { Set, SetNegated, Accumulate };

struct Store {
  std::string target;  // C++ lvalue, may use the bond index k
  Expr value;
  StoreMode mode = StoreMode::Set;
  std::string guard;  // optional condition, e.g. "forces != nullptr"
  int sum = -1;       // Accumulate into a horizon sum: its symbol (target is its variable)
};

struct Segment {
  bool loop = false;                // per bond (k = 0..L-1) or once per family
  std::vector<int> accumulators;    // sum symbols declared as zero before the segment
  std::vector<std::string> before;  // raw lines emitted before the segment, after those
  std::vector<Store> stores;
};

struct KernelProgram {
  std::string name;  // function name
  std::string return_type = "void";
  std::vector<std::string> params;  // "const pd::abi::Family& fam", ...
  std::vector<std::string> param_names;
  std::map<int, Binding> bindings;  // by symbol index
  std::vector<Segment> segments;
  std::vector<std::string> epilogue;
};

struct EmitCounts {
  int adds = 0, muls = 0, divs = 0, calls = 0;
};

struct EmittedKernel {
  std::string code;          // the function definition, headed by its op counts
  std::string declaration;   // the prototype
  EmitCounts per_bond;       // summed over the kernel's bond loops
  EmitCounts per_family;     // outside the loops
  int scratch_per_bond = 0;  // doubles per bond the kernel keeps in fam.scratch
};

EmittedKernel emit_kernel(const KernelProgram& program);

// C++ spelling of a double that parses back to the same value.
std::string cpp_double(double v);

}  // namespace pdgen
