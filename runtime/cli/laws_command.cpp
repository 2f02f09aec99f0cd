// `pd laws` lists what the generator built; `pd check-law NAME` verifies one law's
// generated tangent and tangent-vector product against central finite differences.
#include <fmt/core.h>

#include <cmath>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "kernel_abi.hpp"
#include "verify/tangent_check.hpp"

namespace pd::cli {

namespace {
void print_ops(const char* what, const abi::OpCounts& c) {
  fmt::print("      {:<9} per bond: {:3} add {:3} mul {:3} div {:2} call\n", what, c.adds, c.muls, c.divs,
             c.calls);
}

int list_laws(bool verbose) {
  fmt::print("Laws ({}):\n", abi::all_laws().size());
  for (const auto& law : abi::all_laws()) {
    std::string params;
    for (int i = 0; i < law.n_params; ++i) params += (i ? ", " : "") + std::string(law.param_names[i]);
    fmt::print("  {:<28} {}D  params: {:<16} moments: {}  states: {}  energy: {}\n", law.name, law.dim,
               params, law.n_moments, law.n_states, law.damaged.energy ? "yes" : "no");
    fmt::print("      {}\n", law.summary);
    if (verbose) {
      print_ops("residual", law.intact.residual_ops);
      print_ops("tangent", law.intact.tangent_ops);
      print_ops("jvp", law.intact.jvp_ops);
      print_ops("sensitivity", law.intact.sensitivity_ops);
    }
  }
  fmt::print("Influence functions ({}):\n", abi::all_influences().size());
  for (const auto& inf : abi::all_influences()) fmt::print("  {:<16} w = {}\n", inf.name, inf.formula);
  return 0;
}

int check_law(const std::string& name, unsigned seed) {
  const abi::LawDescriptor* law = abi::find_law(name);
  if (law == nullptr) {
    fmt::print(stderr, "pd check-law: no law named '{}' (pd laws lists them)\n", name);
    return 2;
  }
  const verify::CheckTolerances tol;
  fmt::print(
      "Checking {} ({}D) on random families, seed {}: generated tangent vs central differences\n"
      "of the generated residual (relative error per block kind; pass <= {:g}), JVP (<= {:g}), momentum\n"
      "(<= {:g}), angular momentum (<= {:g}, {}), and finite everywhere.\n\n",
      law->name, law->dim, seed, tol.tangent, tol.jvp, tol.momentum, tol.angular_momentum,
      law->balances_angular_momentum ? "the law claims it" : "not claimed: shown, not judged");
  fmt::print("  {:<24} {:>5} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "family", "bonds", "center",
             "on-diag", "off-diag", "coupling", "jvp", "momentum", "angular");
  bool ok = true;
  for (const auto& c : verify::check_law(*law, seed)) {
    const bool pass = verify::passes(*law, c, tol);
    ok = ok && pass;
    if (c.differenced)
      fmt::print("  {:<24} {:>5} {:>10.2e} {:>10.2e} {:>10.2e} {:>10.2e} {:>10.2e}", c.description, c.bonds,
                 c.tangent.center, c.tangent.on_diagonal, c.tangent.off_diagonal, c.tangent.center_coupling,
                 c.jvp_error);
    else
      fmt::print("  {:<24} {:>5} {:>54}", c.description, c.bonds, "(no differences at a collapsed bond)");
    fmt::print(" {:>10.2e} {:>10.2e}  {}{}\n", c.momentum_error, c.angular_momentum_error,
               pass ? "ok" : "FAIL", c.finite ? "" : " (NaN or Inf)");
  }
  fmt::print("\n{}\n", ok ? "All checks passed." : "Some checks FAILED.");
  return ok ? 0 : 1;
}
}  // namespace

Command add_laws_command(CLI::App& pd) {
  CLI::App* cmd = pd.add_subcommand("laws", "list the generated laws and influence functions");
  auto verbose = std::make_shared<bool>(false);
  cmd->add_flag("-v,--verbose", *verbose, "also the operation counts per bond of each kernel");
  return [verbose] { return list_laws(*verbose); };
}

Command add_check_law_command(CLI::App& pd) {
  CLI::App* cmd = pd.add_subcommand("check-law", "verify a law's tangent against finite differences");
  cmd->footer("Exit codes: 0 every check passed, 1 some check failed, 2 bad usage or no such law.\n");
  auto name = std::make_shared<std::string>();
  auto seed = std::make_shared<unsigned>(1);
  cmd->add_option("NAME", *name, "the law (pd laws lists them)")->required();
  cmd->add_option("--seed", *seed, "seed of the random families")->capture_default_str();
  return [name, seed] { return check_law(*name, *seed); };
}

}  // namespace pd::cli
