// The version of pd and the git commit it was built from (for --version, the log and summary.json).
#pragma once

#include <string>

namespace pd {

const char* version();       // the project version, e.g. "0.1.0"
const char* git_commit();    // e.g. "570cb2a1b2c3", "570cb2a1b2c3-dirty", or "unknown" outside git
std::string version_line();  // "pd 0.1.0 (commit 570cb2a1b2c3)"

}  // namespace pd
