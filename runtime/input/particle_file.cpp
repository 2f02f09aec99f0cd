// Reading a point cloud from CSV.
#include "input/particle_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "input/csv_text.hpp"
#include "input/particle_vtu.hpp"

namespace pd {

namespace {
using csv::parse_number;
using csv::split;
using csv::trim;

bool is_vtu_path(const std::string& path) {
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".vtu") == 0;
}
}  // namespace

ParticleFile read_particle_file(const std::string& path, int dim) {
  if (is_vtu_path(path)) return read_particle_vtu(path, dim);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the particle file");
  const std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_particle_csv(contents, path, dim);
}

ParticleFile parse_particle_csv(const std::string& contents, const std::string& path, int dim) {
  std::istringstream in(contents);
  ParticleFile f;
  f.path = path;
  f.dim = dim;
  auto fail = [&](int line, const std::string& message) {
    throw SceneError(fmt::format("{}:{}: {}", path, line, message));
  };
  std::map<std::string, int> column;
  std::string text;
  int line = 0, header_line = 0;
  std::set<std::vector<double>> seen;
  while (std::getline(in, text)) {
    ++line;
    const std::string t = trim(text);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> fields = split(t);
    if (header_line == 0) {
      header_line = line;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        const std::string& name = fields[k];
        if (name != "x" && name != "y" && name != "z" && name != "volume" && name != "material")
          fail(line, fmt::format("unknown column '{}' (the columns: x, y{}, volume, material)", name,
                                 dim == 3 ? ", z" : ""));
        if (name == "z" && dim == 2) fail(line, "a z column in a 2D scene");
        if (!column.emplace(name, static_cast<int>(k)).second)
          fail(line, fmt::format("column '{}' given twice", name));
      }
      for (const char* need : {"x", "y", "z", "volume"})
        if ((dim == 3 || std::string(need) != "z") && !column.count(need))
          fail(line, fmt::format("no column '{}'", need));
      continue;
    }
    const int row = f.size() + 1;
    if (fields.size() != column.size())
      fail(line, fmt::format("row {}: {} values for {} columns", row, fields.size(), column.size()));
    auto number = [&](const char* name) {
      double v = 0;
      const std::string& s = fields[static_cast<std::size_t>(column.at(name))];
      if (!parse_number(s, v))
        fail(line, fmt::format("row {}: {}: '{}' is not a finite number", row, name, s));
      return v;
    };
    std::vector<double> x;
    for (const char* c : {"x", "y", "z"})
      if (c[0] != 'z' || dim == 3) x.push_back(number(c));
    const double volume = number("volume");
    if (!(volume > 0)) fail(line, fmt::format("row {}: volume must be positive (got {})", row, volume));
    if (!seen.insert(x).second)
      fail(line, fmt::format("row {}: a second particle at the same position", row));
    f.x.insert(f.x.end(), x.begin(), x.end());
    f.volume.push_back(volume);
    f.material.push_back(column.count("material") ? fields[static_cast<std::size_t>(column.at("material"))]
                                                  : "");
    f.line.push_back(line);
  }
  if (header_line == 0)
    throw SceneError(path +
                     ": the particle file is empty (a header line x,y[,z],volume[,material] is needed)");
  if (f.size() == 0) fail(header_line, "the particle file has a header but no particle rows");
  return f;
}

std::vector<int> particle_materials(const ParticleFile& f, const std::vector<std::string>& names) {
  std::vector<int> out(static_cast<std::size_t>(f.size()), 0);
  for (int i = 0; i < f.size(); ++i) {
    const std::string& m = f.material[static_cast<std::size_t>(i)];
    if (m.empty()) continue;
    int index = -1;
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == m) index = static_cast<int>(k);
    if (index < 0) {
      const char* end = m.data() + m.size();
      int k = -1;
      const auto r = std::from_chars(m.data(), end, k);
      if (r.ec == std::errc() && r.ptr == end && k >= 0 && k < static_cast<int>(names.size())) index = k;
    }
    if (index < 0)
      throw SceneError(fmt::format("{}:{}: {}: unknown material '{}' (the scene's materials: {})", f.path,
                                   f.line[i], f.item(i), m, fmt::join(names, ", ")));
    out[static_cast<std::size_t>(i)] = index;
  }
  return out;
}

}  // namespace pd
