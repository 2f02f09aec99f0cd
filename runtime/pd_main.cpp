// pd: the command-line front end. Subcommands live in runtime/cli/.
#include <fmt/core.h>

#include <exception>
#include <functional>
#include <map>
#include <string>

#include "cli/commands.hpp"

namespace {
const std::map<std::string, std::pair<std::function<int(const pd::cli::Args&)>, const char*>>& commands() {
  static const std::map<std::string, std::pair<std::function<int(const pd::cli::Args&)>, const char*>> table{
      {"laws", {pd::cli::laws_command, "list the generated laws and influence functions (-v: op counts)"}},
      {"check-law", {pd::cli::check_law_command, "NAME: verify a law's tangent against finite differences"}},
      {"run", {pd::cli::run_command, "SCENE.yaml [--out DIR]: solve a scene and write its results"}},
      {"study", {pd::cli::study_command, "STUDY.yaml [--out DIR] [--quick]: convergence and cost study"}},
  };
  return table;
}

int usage(int code) {
  fmt::print(code ? stderr : stdout, "usage: pd COMMAND [ARGS]\n\ncommands:\n");
  for (const auto& [name, entry] : commands()) fmt::print(code ? stderr : stdout, "  {:<12} {}\n", name, entry.second);
  return code;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(2);
  const std::string cmd = argv[1];
  if (cmd == "-h" || cmd == "--help" || cmd == "help") return usage(0);
  const auto it = commands().find(cmd);
  if (it == commands().end()) {
    fmt::print(stderr, "pd: unknown command '{}'\n", cmd);
    return usage(2);
  }
  try {
    return it->second.first(pd::cli::Args(argv + 2, argv + argc));
  } catch (const std::exception& e) {
    fmt::print(stderr, "pd {}: error: {}\n", cmd, e.what());
    return 1;
  }
}
