// The `pd` subcommands. Each add_*_command registers its subcommand, options and help on
// the CLI11 app and returns what runs it once parsed (returning the process exit code).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace pd::cli {

using Command = std::function<int()>;

// A path option's value must not be empty: `--out ""` is bad usage (exit 2), not "the
// default directory" nor the current one.
inline const CLI::Validator kNonEmptyPath(
    [](const std::string& value) {
      return value.empty() ? std::string("an empty path is not a directory; give one or leave the option out")
                           : std::string();
    },
    "PATH");

Command add_laws_command(CLI::App& pd);       // pd laws: the generated laws and influence functions
Command add_check_law_command(CLI::App& pd);  // pd check-law NAME: tangent vs finite differences
Command add_run_command(CLI::App& pd);        // pd run SCENE.yaml: solve a scene, write results
Command add_study_command(CLI::App& pd);      // pd study STUDY.yaml: convergence and cost study
Command add_calibrate_command(CLI::App& pd);  // pd calibrate SCENE.yaml: fit parameters to a field

}  // namespace pd::cli
