// Reading a measured displacement field from CSV (measured_field.hpp).
#include "input/measured_field.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "input/csv_text.hpp"
#include "input/yaml_keys.hpp"  // SceneError

namespace pd {

MeasuredField read_measured_field(const std::string& path, int dim) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the measured field");
  const std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_measured_field(contents, path, dim);
}

MeasuredField parse_measured_field(const std::string& contents, const std::string& path, int dim) {
  static const char* position[] = {"x", "y", "z"};
  static const char* displacement[] = {"u_x", "u_y", "u_z"};
  MeasuredField f;
  f.path = path;
  f.dim = dim;
  f.measured.assign(static_cast<std::size_t>(dim), false);
  auto fail = [&](int line, const std::string& message) {
    throw SceneError(fmt::format("{}:{}: {}", path, line, message));
  };
  std::istringstream in(contents);
  std::map<std::string, int> column;
  std::size_t columns = 0;
  std::string text;
  int line = 0, header_line = 0;
  while (std::getline(in, text)) {
    ++line;
    const std::string t = csv::trim(text);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> fields = csv::split(t);
    if (header_line == 0) {
      header_line = line;
      columns = fields.size();
      for (std::size_t k = 0; k < fields.size(); ++k)
        if (!column.emplace(fields[k], static_cast<int>(k)).second)
          fail(line, fmt::format("column '{}' given twice", fields[k]));
      if (dim == 2 && (column.count("z") || column.count("u_z"))) fail(line, "a z column in a 2D scene");
      for (int c = 0; c < dim; ++c) {
        if (!column.count(position[c])) fail(line, fmt::format("no column '{}'", position[c]));
        f.measured[static_cast<std::size_t>(c)] = column.count(displacement[c]) > 0;
      }
      bool any = false;
      for (bool m : f.measured) any = any || m;
      if (!any) fail(line, fmt::format("no displacement column (u_x, u_y{})", dim == 3 ? ", u_z" : ""));
      continue;
    }
    const int row = f.size() + 1;
    if (fields.size() != columns)
      fail(line, fmt::format("row {}: {} values for {} columns", row, fields.size(), columns));
    auto number = [&](const char* name) {
      double v = 0;
      const std::string& s = fields[static_cast<std::size_t>(column.at(name))];
      if (!csv::parse_number(s, v))
        fail(line, fmt::format("row {}: {}: '{}' is not a finite number", row, name, s));
      return v;
    };
    for (int c = 0; c < dim; ++c) f.x.push_back(number(position[c]));
    for (int c = 0; c < dim; ++c)
      f.value.push_back(f.measured[static_cast<std::size_t>(c)] ? number(displacement[c]) : 0.0);
    f.line.push_back(line);
  }
  if (header_line == 0)
    throw SceneError(path + ": the measured field is empty (a header line x,y[,z],u_x,u_y[,u_z] is needed)");
  if (f.size() == 0) fail(header_line, "the measured field has a header but no rows");
  return f;
}

}  // namespace pd
