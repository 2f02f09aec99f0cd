// The small text rules every CSV reader of the input layer shares (particle files,
// measured fields): fields split at commas and trimmed, numbers parsed whole and finite.
#pragma once

#include <string>
#include <vector>

namespace pd::csv {

// s without leading and trailing blanks, tabs and carriage returns.
std::string trim(const std::string& s);
// The comma-separated fields of one line, each trimmed (no quoting: the files hold numbers
// and names).
std::vector<std::string> split(const std::string& line);
// A finite double, the whole field (strtod would accept "1.5abc" and "nan").
bool parse_number(const std::string& s, double& v);

}  // namespace pd::csv
