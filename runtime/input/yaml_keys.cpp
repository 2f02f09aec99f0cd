// Strict YAML map reading with file:line:key messages.
#include "input/yaml_keys.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace pd {

std::string YamlAt::location() const {
  const int line = node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
  return file + ":" + (line > 0 ? std::to_string(line) : std::string("?")) + ": " +
         (path.empty() ? std::string("(top level)") : path);
}

void YamlAt::fail(const std::string& message) const { throw SceneError(location() + ": " + message); }

YamlAt YamlAt::child(const YAML::Node& n, const std::string& key) const {
  return {n, file, path.empty() ? key : path + "." + key};
}

YamlAt YamlAt::element(const YAML::Node& n, std::size_t i) const {
  return {n, file, path + "[" + std::to_string(i) + "]"};
}

namespace {
int line_of(const YAML::Node& n) { return n.Mark().line >= 0 ? n.Mark().line + 1 : 0; }

// yaml-cpp keeps every entry of a map with a repeated key but looks up only the first,
// so `E: 1` followed by `E: 2` would silently mean 1: refuse it, naming both lines.
void reject_duplicate_keys(const YamlAt& at) {
  std::map<std::string, int> first_line;
  for (auto it = at.node.begin(); it != at.node.end(); ++it) {
    if (!it->first.IsScalar()) continue;
    const std::string key = it->first.Scalar();
    const auto [seen, fresh] = first_line.emplace(key, line_of(it->first));
    if (!fresh)
      at.child(it->first, key)
          .fail("duplicate key '" + key + "' (first given on line " + std::to_string(seen->second) +
                "; a key may appear once in a map)");
  }
}
}  // namespace

MapReader::MapReader(const YamlAt& at) : at_(at) {
  if (!at.node.IsMap()) at.fail("expected a map of keys");
  reject_duplicate_keys(at);
}

bool MapReader::has(const std::string& key) const { return static_cast<bool>(at_.node[key]); }

YamlAt MapReader::get(const std::string& key) {
  used_.insert(key);
  const YAML::Node n = at_.node[key];
  if (!n) at_.fail("missing required key '" + key + "'");
  return at_.child(n, key);
}

std::string read_input_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw SceneError(path + ": no such " + what + " file");
  if (std::filesystem::is_directory(status))
    throw SceneError(path + ": is a directory, not a " + what + " file (give the .yaml file itself)");
  if (!std::filesystem::is_regular_file(status))
    throw SceneError(path + ": not a regular file, cannot read it as a " + what + " file");
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open the " + what + " file (permissions?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path + ": cannot read the " + what + " file");
  return text.str();
}

YAML::Node parse_yaml(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw SceneError(file + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
}

double as_number(const YamlAt& at) {
  if (!at.node.IsScalar()) at.fail("expected a number");
  double v = 0;
  try {
    v = at.node.as<double>();
  } catch (const YAML::Exception&) {
    at.fail("expected a number, got '" + at.node.Scalar() + "'");
  }
  if (!std::isfinite(v)) at.fail("expected a finite number, got '" + at.node.Scalar() + "'");
  return v;
}

std::vector<double> as_numbers(const YamlAt& at) {
  if (!at.node.IsSequence()) at.fail("expected a list of numbers");
  std::vector<double> v;
  for (std::size_t i = 0; i < at.node.size(); ++i) v.push_back(as_number(at.element(at.node[i], i)));
  return v;
}

std::string as_text(const YamlAt& at) {
  if (!at.node.IsScalar()) at.fail("expected a string");
  return at.node.Scalar();
}

void require_list(const YamlAt& at) {
  if (!at.node.IsSequence()) at.fail("expected a list");
}

double MapReader::number(const std::string& key) { return as_number(get(key)); }
double MapReader::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : (used_.insert(key), fallback);
}

int MapReader::integer(const std::string& key, int fallback) {
  if (!has(key)) return used_.insert(key), fallback;
  const YamlAt a = get(key);
  const double v = as_number(a);
  if (v != std::floor(v) || std::fabs(v) > 1e9) a.fail("expected an integer");
  return static_cast<int>(v);
}

bool MapReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return used_.insert(key), fallback;
  const YamlAt a = get(key);
  try {
    return a.node.as<bool>();
  } catch (const YAML::Exception&) {
    a.fail("expected true or false");
  }
}

std::string MapReader::text(const std::string& key) { return as_text(get(key)); }
std::string MapReader::text(const std::string& key, const std::string& fallback) {
  return has(key) ? text(key) : (used_.insert(key), fallback);
}

std::string MapReader::choice(const std::string& key, const std::string& fallback,
                              const std::vector<std::string>& allowed) {
  const std::string v = text(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    get(key).fail("'" + v + "' is not one of: " + list);
  }
  return v;
}

std::vector<double> MapReader::numbers(const std::string& key) { return as_numbers(get(key)); }

void MapReader::finish() const {
  for (auto it = at_.node.begin(); it != at_.node.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (!used_.count(key)) at_.child(it->first, key).fail("unknown key '" + key + "'");
  }
}

}  // namespace pd
