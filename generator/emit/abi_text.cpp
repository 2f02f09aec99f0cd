// The kernel ABI's spelling; must agree with runtime/kernel_abi.hpp.
#include "emit/abi_text.hpp"

#include <sstream>

#include "pdgen/kernel_program.hpp"

namespace pdgen::abi_text {

namespace {
std::string str(int i) { return std::to_string(i); }
const char* kFamily = "const pd::abi::Family& fam";
}  // namespace

Signature signature(Kernel k) {
  switch (k) {
    case Kernel::Moments:
      return {"void", {kFamily, "double* moments"}, {"fam", "moments"}};
    case Kernel::Residual:
      return {"void", {kFamily, "double* forces"}, {"fam", "forces"}};
    case Kernel::Tangent:
      return {"void",
              {kFamily, "double* forces", "const pd::abi::TangentFactors& factors"},
              {"fam", "forces", "factors"}};
    case Kernel::Jvp:
      return {"void", {kFamily, "const double* dy", "double* df"}, {"fam", "dy", "df"}};
    case Kernel::Sensitivity:
      return {"void", {kFamily, "double* dfdp"}, {"fam", "dfdp"}};
    case Kernel::Form:
      return {
          "void", {kFamily, "const pd::abi::TangentFactors& factors", "double* M"}, {"fam", "factors", "M"}};
    case Kernel::Energy:
      return {"double", {kFamily}, {"fam"}};
    case Kernel::Outputs:
      return {"void", {kFamily, "double* outputs"}, {"fam", "outputs"}};
    case Kernel::Update:
      return {"void",
              {kFamily, "double* history_out", "double* particle_history_out"},
              {"fam", "history_out", "particle_history_out"}};
    case Kernel::Influence:
      return {"double", {"double r", "double delta"}, {"r", "delta"}};
  }
  return {};
}

std::string bond_vector(const std::string& field, int dim, int c) {
  return "fam." + field + "[k * " + str(dim) + " + " + str(c) + "]";
}
std::string bond_scalar(const std::string& field) { return "fam." + field + "[k]"; }
std::string optional_bond_scalar(const std::string& field) {
  return "(fam." + field + " ? fam." + field + "[k] : 1.0)";
}
std::string family_scalar(const std::string& field) { return "fam." + field; }
std::string param(int i) { return "fam.params[" + str(i) + "]"; }
std::string pair_param(int i, int n_params, const std::string& mean) {
  return "(fam.nbr_params != nullptr ? pd::abi::" + mean + "(" + param(i) + ", fam.nbr_params[k * " +
         str(n_params) + " + " + str(i) + "]) : " + param(i) + ")";
}
std::string moment_input(int i) { return "fam.moments[" + str(i) + "]"; }
std::string history_input(int i, int n_history, double initial) {
  return "(fam.history != nullptr ? fam.history[k * " + str(n_history) + " + " + str(i) +
         "] : " + cpp_double(initial) + ")";
}
std::string history_output(int i, int n_history) {
  return "history_out[k * " + str(n_history) + " + " + str(i) + "]";
}
std::string particle_history_input(int i, double initial) {
  return "(fam.particle_history != nullptr ? fam.particle_history[" + str(i) + "] : " + cpp_double(initial) +
         ")";
}
std::string particle_history_output(int i) { return "particle_history_out[" + str(i) + "]"; }
std::string bond_count() { return "fam.n_bonds"; }
std::string scratch() { return "fam.scratch"; }

std::string center_component(const std::string& array, int c) { return array + "[" + str(c) + "]"; }
std::string neighbour_component(const std::string& array, int dim, int c) {
  return array + "[(k + 1) * " + str(dim) + " + " + str(c) + "]";
}
std::string bond_increment(int dim, int c) {
  return neighbour_component("dy", dim, c) + " - " + center_component("dy", c);
}
std::string sensitivity_column(int dim, int i) {
  return i == 0 ? "dfdp" : "(dfdp + " + str(i) + " * (" + bond_count() + " + 1) * " + str(dim) + ")";
}
std::string forces_requested() { return "forces != nullptr"; }
std::string factor_direct(int dim, int r, int c) {
  return "factors.direct[k * " + str(dim * dim) + " + " + str(r * dim + c) + "]";
}
std::string factor_left(int dim, int n_states, int s, int r) {
  return "factors.left[(k * " + str(n_states) + " + " + str(s) + ") * " + str(dim) + " + " + str(r) + "]";
}
std::string factor_right(int dim, int n_states, int s, int c) {
  return "factors.right[(k * " + str(n_states) + " + " + str(s) + ") * " + str(dim) + " + " + str(c) + "]";
}
std::string factor_at(const std::string& which, const std::string& bond, int per_bond, int index) {
  return "factors." + which + "[" + bond + " * " + str(per_bond) + " + " + str(index) + "]";  // bond: a name
}
std::string bond_volume(const std::string& bond) { return "fam.V[" + bond + "]"; }
std::string center_volume() { return "fam.V0"; }
std::string moment_output(int i) { return "moments[" + str(i) + "]"; }
std::string output(int i) { return "outputs[" + str(i) + "]"; }

std::string abi_include() { return "#include \"kernel_abi.hpp\"\n"; }
std::string law_descriptor_type() { return "pd::abi::LawDescriptor"; }
std::string param_range_type() { return "pd::abi::ParamRange"; }
std::string monomial_group_type() { return "pd::abi::MonomialGroup"; }
std::string radial_term_type() { return "pd::abi::RadialTerm"; }

std::string law_table(const std::vector<std::string>& descriptors,
                      const std::vector<std::string>& influences) {
  std::ostringstream table;
  table << "namespace pd::abi {\n\nstd::span<const LawDescriptor> all_laws() {\n  static const LawDescriptor "
           "table[] = {\n";
  for (auto& d : descriptors) table << "      " << d << ",\n";
  if (descriptors.empty()) table << "      LawDescriptor{},\n";
  table << "  };\n  return std::span<const LawDescriptor>(table, " << descriptors.size() << ");\n}\n\n";
  table << "std::span<const InfluenceDescriptor> all_influences() {\n  using namespace pd::generated;\n"
        << "  static const InfluenceDescriptor table[] = {\n";
  for (auto& i : influences) table << "      " << i << ",\n";
  if (influences.empty()) table << "      InfluenceDescriptor{},\n";
  table << "  };\n  return std::span<const InfluenceDescriptor>(table, " << influences.size() << ");\n}\n\n";
  table << "const LawDescriptor* find_law(std::string_view name) {\n  for (const LawDescriptor& d : "
           "all_laws())\n"
        << "    if (name == d.name) return &d;\n  return nullptr;\n}\n\n"
        << "const InfluenceDescriptor* find_influence(std::string_view name) {\n  for (const "
           "InfluenceDescriptor& d : all_influences())\n"
        << "    if (name == d.name) return &d;\n  return nullptr;\n}\n\n}  // namespace pd::abi\n";
  return table.str();
}

}  // namespace pdgen::abi_text
