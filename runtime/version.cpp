#include "version.hpp"

#include "pd_git_commit.hpp"  // generated at build time by cmake/GitVersion.cmake

namespace pd {

const char* version() { return PD_VERSION; }
const char* git_commit() { return PD_GIT_COMMIT; }
std::string version_line() { return std::string("pd ") + version() + " (commit " + git_commit() + ")"; }

}  // namespace pd
