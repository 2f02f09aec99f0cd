// Strict reading of YAML maps: every key is looked up by name with a default or as
// required, values are type-checked, and keys nobody asked for are errors. Every error
// names the file, the line and the key path (e.g. "scene.yaml:12: boundary[1].fixed: ...").
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace pd {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A YAML node with its location, for messages.
struct YamlAt {
  YAML::Node node;
  std::string file;
  std::string path;  // key path, e.g. "boundary[2].region"

  [[noreturn]] void fail(const std::string& message) const;
  std::string location() const;  // "file:line: path"
  YamlAt child(const YAML::Node& n, const std::string& key) const;
  YamlAt element(const YAML::Node& n, std::size_t i) const;
};

// Reads one map. Call finish() after the last lookup: it reports unknown keys.
class MapReader {
 public:
  explicit MapReader(const YamlAt& at);
  bool has(const std::string& key) const;
  YamlAt get(const std::string& key);  // required
  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  int integer(const std::string& key, int fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string text(const std::string& key);
  std::string text(const std::string& key, const std::string& fallback);
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed);
  std::vector<double> numbers(const std::string& key);  // a list of numbers
  void finish() const;
  const YamlAt& at() const { return at_; }

 private:
  YamlAt at_;
  std::set<std::string> used_;
};

// The text of a scene or study file; `what` ("scene", "study") names it in the errors:
// a missing, unreadable or non-regular file (a directory) is a SceneError naming the path.
std::string read_input_file(const std::string& path, const std::string& what);
// Parses YAML text, turning a syntax error into "file:line: YAML syntax error: ...".
YAML::Node parse_yaml(const std::string& text, const std::string& file);

double as_number(const YamlAt& at);
std::vector<double> as_numbers(const YamlAt& at);
std::string as_text(const YamlAt& at);
void require_list(const YamlAt& at);

}  // namespace pd
