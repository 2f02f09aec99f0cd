// The `pd` subcommands. Each returns the process exit code.
#pragma once

#include <string>
#include <vector>

namespace pd::cli {

using Args = std::vector<std::string>;

int laws_command(const Args& args);       // pd laws: the generated laws and influence functions
int check_law_command(const Args& args);  // pd check-law NAME: tangent vs finite differences
int run_command(const Args& args);        // pd run SCENE.yaml: solve a scene, write results
int study_command(const Args& args);      // pd study STUDY.yaml: convergence and cost study

}  // namespace pd::cli
