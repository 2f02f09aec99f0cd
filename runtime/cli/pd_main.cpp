// pd: the command-line front end (CLI11). Subcommands live in runtime/cli/.
// Exit codes: 0 done, 1 the command failed, 2 bad usage or bad input; a command's
// --help lists its own.
#include <fmt/core.h>

#include <exception>
#include <map>
#include <string>

#include "cli/commands.hpp"
#include "version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"pd: peridynamic laws, scenes and studies (docs/scene_format.md describes scenes)", "pd"};
  app.set_version_flag("--version", pd::version_line(), "print the version and the git commit, then exit");
  app.require_subcommand(1);
  app.fallthrough(false);
  std::map<const CLI::App*, pd::cli::Command> commands;
  for (auto add : {pd::cli::add_laws_command, pd::cli::add_check_law_command, pd::cli::add_run_command,
                   pd::cli::add_study_command, pd::cli::add_calibrate_command}) {
    pd::cli::Command run = add(app);
    commands[app.get_subcommands({}).back()] = std::move(run);
  }
  if (argc < 2) {  // no command: the list of commands, as an error
    fmt::print(stderr, "{}", app.help());
    return 2;
  }
  std::string names;
  bool known = false;
  for (const CLI::App* c : app.get_subcommands({})) {
    names += (names.empty() ? "" : ", ") + c->get_name();
    known = known || c->get_name() == argv[1];
  }
  if (argv[1][0] != '-' && !known) {
    fmt::print(stderr, "pd: unknown command '{}' (the commands: {}; pd --help)\n", argv[1], names);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; an unknown option, a stray argument, a missing or a
    // malformed value is bad usage: CLI11 names it, and the exit code is 2 like bad input.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  const CLI::App* chosen = app.get_subcommands().front();
  try {
    return commands.at(chosen)();
  } catch (const std::exception& e) {
    fmt::print(stderr, "pd {}: error: {}\n", chosen->get_name(), e.what());
    return 1;
  }
}
