// Generated source files: one header/source pair per law file, and the law table.
#pragma once

#include <map>
#include <string>

namespace pdgen {

// File name -> content for every file pdgen emits, from the registered laws and
// influence functions. Deterministic: the same registry gives the same bytes.
std::map<std::string, std::string> generate_all_files();

}  // namespace pdgen
