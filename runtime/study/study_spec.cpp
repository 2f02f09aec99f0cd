// The study file reader (strict keys, like scenes).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "input/yaml_keys.hpp"
#include "kernel_abi.hpp"
#include "study/study.hpp"

namespace pd {

namespace {
std::vector<std::string> texts(MapReader& m, const std::string& key, bool required) {
  std::vector<std::string> out;
  if (!required && !m.has(key)) return out;
  const YamlAt at = m.get(key);
  require_list(at);
  for (std::size_t i = 0; i < at.node.size(); ++i) out.push_back(as_text(at.element(at.node[i], i)));
  if (required && out.empty()) at.fail("the list is empty");
  return out;
}
std::vector<int> integers(MapReader& m, const std::string& key, bool required) {
  std::vector<int> out;
  if (!required && !m.has(key)) return out;
  const YamlAt at = m.get(key);
  for (double v : as_numbers(at)) {
    if (v < 2 || v != static_cast<int>(v)) at.fail("counts are integers >= 2");
    out.push_back(static_cast<int>(v));
  }
  return out;
}
}  // namespace

StudySpec read_study(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open the study file");
  std::ostringstream text;
  text << in.rdbuf();
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw SceneError(path + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  const YamlAt top{root, path, ""};
  MapReader m(top);
  StudySpec s;
  s.file = path;
  const auto base = std::filesystem::path(path).parent_path();
  for (const auto& p : texts(m, "problems", true)) s.problems.push_back((base / p).lexically_normal().string());
  s.laws = texts(m, "laws", true);
  for (const auto& l : s.laws)
    if (!abi::find_law(l)) m.get("laws").fail("unknown law '" + l + "'");
  s.influences = texts(m, "influences", true);
  for (const auto& i : s.influences)
    if (!abi::find_influence(i)) m.get("influences").fail("unknown influence function '" + i + "'");
  s.ratios = m.numbers("ratios");
  for (double r : s.ratios)
    if (r < 1.0) m.get("ratios").fail("horizon ratios delta/h must be at least 1");
  s.counts = integers(m, "counts", true);
  if (m.has("quick")) {
    MapReader q(m.get("quick"));
    s.quick_laws = texts(q, "laws", false);
    s.quick_influences = texts(q, "influences", false);
    if (q.has("ratios")) s.quick_ratios = q.numbers("ratios");
    s.quick_counts = integers(q, "counts", false);
    q.finish();
  }
  if (m.has("paper")) {
    const YamlAt list = m.get("paper");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      MapReader e(list.element(list.node[i], i));
      const std::string key = e.text("problem") + "|" + e.text("law") + "|" + e.text("influence") + "|" +
                              std::to_string(e.number("ratio"));
      s.paper_orders[key] = e.number("order");
      e.finish();
    }
  }
  m.finish();
  return s;
}

}  // namespace pd
