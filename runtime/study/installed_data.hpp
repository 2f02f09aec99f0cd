// Where pd finds the data files it ships (the study plot script): beside the binary, in
// ../share/pdgen/, the layout of both the build tree and an installed tree, so a pd that
// is installed or moved with its share/ directory needs no source checkout.
#pragma once

#include <filesystem>
#include <string>

namespace pd {

// <directory of the running executable>/../share/pdgen/<name>, whether or not it exists.
std::filesystem::path installed_data_file(const std::string& name);

}  // namespace pd
