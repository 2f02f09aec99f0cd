// The `output` section: directory, files, smoothing (paper 000 eq. 49), J-integral contours, stress.
#include <string>
#include <vector>

#include "input/scene_sections.hpp"
#include "input/smoothing_influence.hpp"

namespace pd {

namespace {

// output.j_integral: a list of {contour: {min, max}} (post/j_integral.hpp, paper 004).
std::vector<JContour> read_j_contours(const YamlAt& list, int dim) {
  require_list(list);
  if (dim != 2) list.fail("the J-integral is implemented in 2D only");
  std::vector<JContour> out;
  for (std::size_t i = 0; i < list.node.size(); ++i) {
    const YamlAt item = list.element(list.node[i], i);
    MapReader m(item);
    MapReader c(m.get("contour"));
    JContour j;
    j.where = item.location();
    j.min = to_point(c.get("min"), dim);
    j.max = to_point(c.get("max"), dim);
    if (!(j.min[0] < j.max[0] && j.min[1] < j.max[1])) c.at().fail("min must be below max in x and y");
    c.finish();
    m.finish();
    out.push_back(j);
  }
  return out;
}

// output.smoothing: {influence}, a bounded influence function.
std::string read_smoothing(const YamlAt& at) {
  MapReader sm(at);
  const std::string name = sm.text("influence");
  const abi::InfluenceDescriptor* inf = abi::find_influence(name);
  if (inf == nullptr)
    sm.get("influence").fail("unknown influence function '" + name + "' (pd laws lists them)");
  if (!can_smooth_with(inf->weight))
    sm.get("influence")
        .fail("'" + name +
              "' is singular at r = 0, and the smoothing (paper 000 eq. 49) weights each particle itself by "
              "w(0): choose a bounded influence function");
  sm.finish();
  return name;
}

}  // namespace

void read_output(SceneReading& r) {
  if (!r.m.has("output")) return;
  OutputSpec& out = r.s.output;
  MapReader o(r.m.get("output"));
  out.directory = o.text("directory", "out");
  out.vtu = o.boolean("vtu", true);
  out.csv = o.boolean("csv", true);
  if (o.has("smoothing")) out.smoothing_influence = read_smoothing(o.get("smoothing"));
  if (o.has("j_integral")) out.j_integral = read_j_contours(o.get("j_integral"), r.s.dim);
  out.stress = o.boolean("stress", false);
  o.finish();
}

}  // namespace pd
