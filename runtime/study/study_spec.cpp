// The study file reader (strict keys, like scenes).
#include <filesystem>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "kernel_abi.hpp"
#include "post/smoothing.hpp"
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
// One sweep's lists from a map (the study's top level, an element of `sweeps`, or
// `quick`, where every list is optional).
// `problems` are the study's scene files: a smoothed error needs their reference field.
Sweep read_sweep(MapReader& m, bool required, const std::vector<std::string>& problems) {
  Sweep w;
  w.laws = texts(m, "laws", required);
  for (const auto& l : w.laws)
    if (!abi::find_law(l)) m.get("laws").fail("unknown law '" + l + "'");
  w.influences = texts(m, "influences", required);
  for (const auto& i : w.influences)
    if (!abi::find_influence(i)) m.get("influences").fail("unknown influence function '" + i + "'");
  if (required || m.has("ratios")) w.ratios = m.numbers("ratios");
  for (double r : w.ratios)
    if (r < 1.0) m.get("ratios").fail("horizon ratios delta/h must be at least 1");
  w.counts = integers(m, "counts", required);
  w.smoothing = texts(m, "smoothing", false);
  for (const auto& name : w.smoothing) {
    const abi::InfluenceDescriptor* inf = abi::find_influence(name);
    if (inf == nullptr)
      m.get("smoothing").fail("unknown influence function '" + name + "' (pd laws lists them)");
    if (!can_smooth_with(inf->weight))
      m.get("smoothing")
          .fail("'" + name +
                "' is singular at r = 0, and the smoothing (paper 000 eq. 49) weights each particle itself "
                "by w(0): choose a bounded influence function");
  }
  if (!w.smoothing.empty())
    for (const auto& problem : problems)
      if (!read_scene(problem).reference)
        m.get("smoothing")
            .fail("the smoothed solution is measured by the field error (paper 000 eq. 48), and " + problem +
                  " has no `reference` field");
  return w;
}
}  // namespace

std::string paper_key(const std::string& problem, const std::string& law, const std::string& influence,
                      double ratio, int count, const std::string& smoothing) {
  // Appended piece by piece: `key += "|" + std::to_string(count)` made GCC 12 warn
  // (-Wrestrict, a false positive in the inlined temporary's copy).
  std::string key = problem + "|" + law + "|" + influence + "|" + std::to_string(ratio);
  if (count > 0) key.append("|").append(std::to_string(count));
  if (!smoothing.empty()) key.append("|smoothed ").append(smoothing);
  return key;
}

StudySpec read_study(const std::string& path) {
  const YAML::Node root = parse_yaml(read_input_file(path, "study"), path);
  if (!root.IsMap()) throw SceneError(path + ":1: (top level): expected a map of keys");
  const YamlAt top{root, path, ""};
  MapReader m(top);
  StudySpec s;
  s.file = path;
  const auto base = std::filesystem::path(path).parent_path();
  for (const auto& p : texts(m, "problems", true))
    s.problems.push_back((base / p).lexically_normal().string());
  if (m.has("sweeps")) {
    const YamlAt list = m.get("sweeps");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      MapReader w(list.element(list.node[i], i));
      s.sweeps.push_back(read_sweep(w, true, s.problems));
      w.finish();
    }
    if (s.sweeps.empty()) list.fail("the list is empty");
  } else {
    s.sweeps.push_back(read_sweep(m, true, s.problems));
  }
  if (m.has("quick")) {
    MapReader q(m.get("quick"));
    s.quick = read_sweep(q, false, s.problems);
    q.finish();
  }
  s.matrix_free_from_bonds = m.number("matrix_free_from_bonds", 0.0);
  if (s.matrix_free_from_bonds < 0) m.get("matrix_free_from_bonds").fail("must not be negative");
  if (m.has("time_reference")) {
    const YamlAt at = m.get("time_reference");
    MapReader r(at);
    TimeReference ref;
    const std::filesystem::path f = r.text("file");
    ref.file = f.is_absolute() ? f.string() : (std::filesystem::path(path).parent_path() / f).string();
    if (r.has("time")) ref.time = r.text("time");
    ref.value = r.text("value");
    r.finish();
    s.time_reference = ref;
  }
  s.fine_points = m.integer("fine_points", 0);
  if (s.fine_points != 0 && s.fine_points < 2) m.get("fine_points").fail("0, or at least 2 points to fit");
  if (m.has("paper")) {
    const YamlAt list = m.get("paper");
    require_list(list);
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      MapReader e(list.element(list.node[i], i));
      const int count = e.integer("count", 0);
      const std::string smoothing = e.has("smoothing") ? e.text("smoothing") : "";
      if (!smoothing.empty() && !abi::find_influence(smoothing))
        e.get("smoothing").fail("unknown influence function '" + smoothing + "'");
      const std::string key = paper_key(e.text("problem"), e.text("law"), e.text("influence"),
                                        e.number("ratio"), count, smoothing);
      PaperValues& v = s.paper[key];
      for (auto [name, slot] :
           {std::pair{"order", &v.order}, {"min_error", &v.min_error}, {"error", &v.error}})
        if (e.has(name)) *slot = e.number(name);
      if (!v.order && !v.min_error && !v.error) e.at().fail("give order, min_error or error");
      if (count > 0 && (v.order || v.min_error))
        e.at().fail("an order or a minimum error belongs to a series: drop count");
      e.finish();
    }
  }
  m.finish();
  return s;
}

}  // namespace pd
