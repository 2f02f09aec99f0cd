// Every error path of the scene reader: each bad edit of a valid scene must stop with
// "file:line: key.path: message". The expected line is found by searching the edited
// text for a marker, so no line number here comes from the reader under test.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"

namespace {

// A valid 2D scene that uses every section, so each key can be broken in place.
const char* kScene2 = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [4, 2]}
  spacing: 0.5
  placement: cell
  perturbation: {amplitude: 0.1, seed: 3}
  holes:
    - circle: {center: [1, 1], radius: 0.3}
  inclusions:
    - polygon: [[2, 0.5], [3, 0.5], [3, 1.5]]
      material: soft
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: const
materials:
  - name: rock
    E: 1000
    nu: 0.25
    plane: strain
  - {name: soft, K: 100, G: 50}
boundary:
  - region: {side: bottom}
    fixed: [x, y]
  - region: {side: top, thickness: 0.5}
    traction: [0, -0.001]
  - region: {box: {min: [0, 0], max: [0.5, 2]}}
    displacement: {x: 0.01}
  - region: {outside: {min: [0.2, 0.2], max: [3.8, 1.8]}}
    field: {solution: uniaxial, traction: -0.001}
    components: [y]
  - region: {all: true}
    body_force: [0, -1]
cracks:
  - segment: [[1.5, 1.1], [2.5, 1.1]]
    pressure: 0.1
solver: {linear: auto, load_steps: 1, tolerance: 1.0e-10, max_iterations: 30}
output: {directory: out/t, vtu: true, csv: false}
probes:
  - name: top
    region: {side: top}
    component: y
    reference: {solution: uniaxial, traction: -0.001}
reference: {solution: westergaard, pressure: 0.1, half_length: 0.5}
)";

const char* kScene3 = R"(dimension: 3
domain:
  box: {min: [0, 0, 0], max: [1, 1, 1]}
  spacing: 0.25
  holes:
    - sphere: {center: [0.5, 0.5, 0.5], radius: 0.2}
law: lps_3d
materials:
  - {E: 1, nu: 0.25}
boundary:
  - region: {side: front}
    fixed: [x, y, z]
cracks:
  - polygon: [[0, 0, 0.5], [1, 0, 0.5], [1, 1, 0.5]]
)";

struct Case {
  Case(std::string f, std::string t, std::string p, std::string m, std::string k = "")
      : from(std::move(f)),
        to(std::move(t)),
        path(std::move(p)),
        message(std::move(m)),
        marker(std::move(k)) {}
  std::string from, to;  // the edit
  std::string path;      // expected key path
  std::string message;   // expected start of the message (plain text)
  std::string marker;    // text on the expected line; empty: the first line of `to`
};

std::string edit(std::string s, const Case& c) {
  const auto p = s.find(c.from);
  EXPECT_NE(p, std::string::npos) << "bad test case, not found: " << c.from;
  if (p == std::string::npos) return s;
  return s.replace(p, c.from.size(), c.to);
}

int line_of(const std::string& text, const std::string& marker) {
  const auto p = text.find(marker);
  EXPECT_NE(p, std::string::npos) << "bad test case, marker not found: " << marker;
  int line = 1;
  for (std::size_t i = 0; i < p && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

std::string quote(const std::string& s) {
  return std::regex_replace(s, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
}

std::string error_of(const std::string& yaml) {
  try {
    pd::parse_scene(yaml, "scene.yaml");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

void check(const char* base, const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    const std::string text = edit(base, c);
    const std::string marker = c.marker.empty() ? c.to.substr(0, c.to.find('\n')) : c.marker;
    const std::string expect = "^scene\\.yaml:" + std::to_string(line_of(text, marker)) + ": " +
                               quote(c.path) + ": " + quote(c.message);
    const std::string msg = error_of(text);
    EXPECT_TRUE(std::regex_search(msg, std::regex(expect)))
        << "edit: " << c.from << " -> " << c.to << "\n  got:      " << msg << "\n  expected: " << expect;
  }
}

}  // namespace

TEST(SceneErrors, TheBaseScenesAreValid) {
  EXPECT_EQ(error_of(kScene2), "(no error)");
  EXPECT_EQ(error_of(kScene3), "(no error)");
}

TEST(SceneErrors, TopLevelAndDomain) {
  check(
      kScene2,
      {
          {"dimension: 2", "dimension: 4", "dimension", "dimension must be 2 or 3"},
          {"dimension: 2", "dimension: 2.5", "dimension", "expected an integer"},
          {"dimension: 2", "dimension: [2]", "dimension", "expected a number"},
          {"reference: {solution: westergaard", "colour: red\nreference: {solution: westergaard", "colour",
           "unknown key 'colour'"},
          {"law: silling_plane_strain\n", "", "(top level)", "missing required key 'law'", "dimension: 2"},
          {"max: [4, 2]", "max: [4, -1]", "domain.box", "max must exceed min", "box:"},
          {"max: [4, 2]", "max: [4]", "domain.box.max", "expected 2 coordinates"},
          {"max: [4, 2]", "max: 4", "domain.box.max", "expected a list of numbers"},
          {"max: [4, 2]", "max: [4, .inf]", "domain.box.max[1]", "expected a finite number"},
          {"max: [4, 2]", "max: [4, two]", "domain.box.max[1]", "expected a number"},
          {"  spacing: 0.5", "  spacing: 0.5\n  count: 8", "domain", "give exactly one of spacing, count",
           "  box:"},
          {"spacing: 0.5", "spacing: 0", "domain.spacing", "spacing must be positive"},
          {"spacing: 0.5", "count: 1", "domain.count", "count (particles along x) must be at least 2"},
          {"spacing: 0.5", "spacing: 0.00001", "domain", "more than 1e5 particles along x", "  box:"},
          {"placement: cell", "placement: face", "domain.placement", "'face' is not one of: cell, node"},
          {"placement: cell", "placement: cell\n  obq_space: law", "domain.obq_space",
           "obq_space needs quadrature: obq or obq_cut", "  obq_space"},
          {"placement: cell", "placement: cell\n  obq_symmetric: true", "domain.obq_symmetric",
           "obq_symmetric needs quadrature: obq or obq_cut", "  obq_symmetric"},
          {"placement: cell", "placement: cell\n  quadrature: obq\n  obq_space: mine", "domain.obq_space",
           "'mine' is not one of: paper001, paper001_odd, law", "  obq_space"},
          {"amplitude: 0.1", "amplitude: 0.5", "domain.perturbation.amplitude",
           "amplitude is a fraction of h"},
          {"seed: 3}", "seed: 3, colour: 1}", "domain.perturbation.colour", "unknown key 'colour'",
           "perturbation:"},
          {"radius: 0.3", "radius: -1", "domain.holes[0].circle.radius", "radius must be positive"},
          {"center: [1, 1]", "center: [1, 1, 1]", "domain.holes[0].circle.center", "expected 2 coordinates"},
          {"    - circle: {center: [1, 1], radius: 0.3}",
           "    - circle: {center: [1, 1], radius: 0.3}\n      box: {min: [0, 0], max: [1, 1]}",
           "domain.holes[0]", "give exactly one of circle, sphere, polygon, box"},
          {"    - circle: {center: [1, 1], radius: 0.3}", "    - box: {min: [1, 1], max: [0.5, 1.5]}",
           "domain.holes[0].box", "max must exceed min"},
          {"  holes:\n    - circle: {center: [1, 1], radius: 0.3}", "  holes: {circle: 1}", "domain.holes",
           "expected a list"},
          {"[[2, 0.5], [3, 0.5], [3, 1.5]]", "[[2, 0.5], [3, 0.5]]", "domain.inclusions[0].polygon",
           "a polygon needs at least 3 vertices", "- polygon"},
          {"      material: soft", "      material: stone", "domain.inclusions[0]",
           "unknown material 'stone'", "- polygon"},
          {"      material: soft\n", "", "domain.inclusions[0]", "missing required key 'material'",
           "- polygon"},
          {"    - circle: {center: [1, 1], radius: 0.3}",
           "    - circle: {center: [1, 1], radius: 0.3}\n      material: soft", "domain.holes[0].material",
           "unknown key 'material'", "      material: soft"},
      });
}

TEST(SceneErrors, HorizonLawAndMaterials) {
  check(kScene2,
        {
            {"horizon: {ratio: 3.0}", "horizon: {ratio: 3.0, length: 1}", "horizon",
             "give exactly one of ratio (delta/h), length"},
            {"horizon: {ratio: 3.0}", "horizon: {ratio: 0.5}", "horizon",
             "the horizon must be at least one spacing h"},
            {"horizon: {ratio: 3.0}", "horizon: {length: 0.1}", "horizon",
             "the horizon must be at least one spacing h"},
            {"horizon: {ratio: 3.0}", "horizon: 3.0", "horizon", "expected a map of keys"},
            {"law: silling_plane_strain", "law: nope", "law", "unknown law 'nope'"},
            {"law: silling_plane_strain", "law: lps_3d", "law", "law lps_3d is 3D, the scene is 2D"},
            {"influence: const", "influence: cubik", "influence", "unknown influence function 'cubik'"},
            {"{name: soft, K: 100, G: 50}", "{name: rock, K: 100, G: 50}", "materials[1]",
             "material 'rock' defined twice"},
            {"    nu: 0.25", "    nu: 0.25\n    K: 10", "materials[0]", "give either E and nu, or K and G",
             "  - name: rock"},
            {"    nu: 0.25", "    nu: 0.7", "materials[0]", "Poisson's ratio", "  - name: rock"},
            {"    E: 1000", "    E: -1", "materials[0]", "Young's modulus", "  - name: rock"},
            {"    nu: 0.25\n", "", "materials[0]", "missing required key 'nu'", "  - name: rock"},
            {"{name: soft, K: 100, G: 50}", "{name: soft, K: 100, G: -50}", "materials[1]",
             "shear modulus G must be positive"},
            {"    plane: strain", "    plane: both", "materials[0].plane",
             "'both' is not one of: strain, stress"},
            {"    plane: strain", "    plane: strain\n    density: 0", "materials[0].density",
             "density must be positive", "    density"},
            {"    plane: strain", "    plane: strain\n    parameters: {stab: abc}",
             "materials[0].parameters.stab", "expected a number", "    parameters"},
            {"    plane: strain", "    plane: strain\n    colour: red", "materials[0].colour",
             "unknown key 'colour'", "    colour"},
            {"materials:\n", "materials: []\nold:\n", "materials", "give at least one material"},
            {"materials:\n", "materials: {a: 1}\nold:\n", "materials", "expected a list"},
        });
}

TEST(SceneErrors, BoundaryConditionsAndRegions) {
  check(
      kScene2,
      {
          {"fixed: [x, y]", "fixed: [x, q]", "boundary[0].fixed", "'q' is not a component of a 2D scene"},
          {"fixed: [x, y]", "fixed: [x, z]", "boundary[0].fixed", "'z' is not a component of a 2D scene"},
          {"fixed: [x, y]", "fixed: {x: 1}", "boundary[0].fixed",
           "expected a component (x, y, z) or a list of them"},
          {"    fixed: [x, y]", "    fixed: [x, y]\n    colour: red", "boundary[0].colour",
           "unknown key 'colour'", "    colour"},
          {"    fixed: [x, y]", "    components: [x]", "boundary[0]",
           "give exactly one of fixed, displacement, velocity, field, traction, body_force",
           "  - region: {side: bottom}"},
          {"    traction: [0, -0.001]", "    traction: [0, -0.001]\n    fixed: [x]", "boundary[1]",
           "give exactly one of fixed", "  - region: {side: top"},
          {"    fixed: [x, y]", "    fixed: [x, y]\n    components: [x]", "boundary[0].components",
           "components belongs to field conditions", "    components: [x]"},
          {"region: {side: top, thickness: 0.5}", "region: {box: {min: [0, 1.5], max: [4, 2]}}",
           "boundary[1]", "a traction on a region that is not a side needs face_measure",
           "  - region: {box: {min: [0, 1.5]"},
          {"traction: [0, -0.001]", "traction: [0, -0.001, 0]", "boundary[1].traction",
           "expected 2 coordinates"},
          {"displacement: {x: 0.01}", "displacement: {}", "boundary[2].displacement",
           "give at least one of x, y, z"},
          {"displacement: {x: 0.01}", "displacement: {w: 0.01}", "boundary[2].displacement.w",
           "unknown key 'w'"},
          {"displacement: {x: 0.01}", "displacement: {x: up}", "boundary[2].displacement.x",
           "expected a number"},
          {"body_force: [0, -1]", "body_force: [0, -1, 0]", "boundary[4].body_force",
           "expected 2 coordinates"},
          {"{side: bottom}", "{side: inside}", "boundary[0].region.side",
           "'inside' is not one of: left, right, bottom, top"},
          {"{side: bottom}", "{side: front}", "boundary[0].region.side",
           "'front' is not one of: left, right, bottom, top"},
          {"{side: bottom}", "{side: bottom, thickness: -1}", "boundary[0].region.thickness",
           "thickness must not be negative"},
          {"{side: bottom}", "{side: bottom, all: true}", "boundary[0].region",
           "give exactly one of side, box, outside, collar, all"},
          {"{side: bottom}", "{side: bottom, colour: red}", "boundary[0].region.colour",
           "unknown key 'colour'"},
          {"{box: {min: [0, 0], max: [0.5, 2]}}", "{box: {min: [0, 0]}}", "boundary[2].region.box",
           "missing required key 'max'"},
          {"region: {all: true}", "region: {all: false}", "boundary[4].region.all", "use all: true"},
          {"region: {all: true}", "region: {all: maybe}", "boundary[4].region.all", "expected true or false"},
          {"field: {solution: uniaxial, traction: -0.001}", "field: {solution: bending, traction: -0.001}",
           "boundary[3].field.solution", "'bending' is not one of: uniaxial, biaxial, shear, westergaard"},
          {"field: {solution: uniaxial, traction: -0.001}", "field: {solution: uniaxial, traction: big}",
           "boundary[3].field.traction", "expected a number"},
          {"field: {solution: uniaxial, traction: -0.001}",
           "field: {solution: uniaxial, traction: -0.001, typo: 1}", "boundary[3].field.typo",
           "unknown key 'typo'"},
          {"field: {solution: uniaxial, traction: -0.001}", "field: {solution: uniaxial}",
           "boundary[3].field", "missing required key 'traction'"},
          {"field: {solution: uniaxial, traction: -0.001}", "field: {solution: westergaard, pressure: 1}",
           "boundary[3].field", "missing required key 'half_length'"},
          {"field: {solution: uniaxial, traction: -0.001}",
           "field: {solution: westergaard, pressure: 1, half_length: 0}", "boundary[3].field.half_length",
           "half_length must be positive"},
          {"field: {solution: uniaxial, traction: -0.001}",
           "field: {solution: uniaxial, traction: -0.001, nu: 0.5}", "boundary[3].field.nu",
           "Poisson's ratio nu must lie in (-1, 0.5)"},
          {"boundary:\n", "boundary: {a: 1}\nold:\n", "boundary", "expected a list"},
      });
}

TEST(SceneErrors, CracksSolverOutputProbes) {
  check(kScene2,
        {
            {"segment: [[1.5, 1.1], [2.5, 1.1]]", "segment: [[1.5, 1.1]]", "cracks[0].segment",
             "a 2D crack is a segment: two points"},
            {"segment: [[1.5, 1.1], [2.5, 1.1]]", "segment: [[1.5, 1.1], [1.5, 1.1]]", "cracks[0].segment",
             "the two points coincide"},
            {"    pressure: 0.1", "    pressure: high", "cracks[0].pressure", "expected a number"},
            {"  - segment: [[1.5, 1.1], [2.5, 1.1]]\n    pressure: 0.1", "  - pressure: 0.1", "cracks[0]",
             "missing required key 'segment'"},
            {"    pressure: 0.1", "    pressure: 0.1\n    colour: red", "cracks[0].colour",
             "unknown key 'colour'", "    colour"},
            {"linear: auto", "linear: magic", "solver.linear",
             "'magic' is not one of: auto, cholmod, umfpack, cg, bicgstab"},
            {"linear: auto", "nonlinear: picard", "solver.nonlinear", "'picard' is not one of: newton"},
            {"load_steps: 1", "load_steps: 0", "solver.load_steps", "load_steps must be at least 1"},
            {"tolerance: 1.0e-10", "tolerance: -1", "solver.tolerance", "tolerances must be positive",
             "tolerance: -1"},
            {"max_iterations: 30", "max_iterations: 0", "solver.max_iterations",
             "max_iterations must be at least 1"},
            {"max_iterations: 30", "max_iterations: 30.5", "solver.max_iterations", "expected an integer"},
            {"max_iterations: 30", "max_iterations: 30, colour: red", "solver.colour", "unknown key 'colour'",
             "solver:"},
            {"vtu: true", "vtu: 3", "output.vtu", "expected true or false"},
            {"directory: out/t", "directory: [a]", "output.directory", "expected a string"},
            {"csv: false", "csv: false, png: true", "output.png", "unknown key 'png'", "output:"},
            {"    component: y", "    component: w", "probes[0].component",
             "'w' is not a component of a 2D scene"},
            {"    component: y\n", "", "probes[0]", "missing required key 'component'", "  - name: top"},
            {"    region: {side: top}\n    component", "    component", "probes[0]",
             "missing required key 'region'", "  - name: top"},
            {"    reference: {solution: uniaxial, traction: -0.001}",
             "    reference: {solution: uniaxial, traction: -0.001, H: 2}", "probes[0].reference.H",
             "unknown key 'H'"},
            {"reference: {solution: westergaard, pressure: 0.1, half_length: 0.5}",
             "reference: {solution: nope}", "reference.solution", "'nope' is not one of"},
            {"    reference: {solution: uniaxial, traction: -0.001}",
             "    reference: {solution: uniaxial, traction: -0.001}\n    reference_at: top",
             "probes[0].reference_at", "'top': expected region, particles or a point", "    reference_at"},
            {"    region: {side: top}\n    component: y",
             "    region: {all: true}\n    component: y\n    reference_at: region", "probes[0].reference_at",
             "region: only a box or side region has a reference point", "    reference_at"},
            {"    reference: {solution: uniaxial, traction: -0.001}", "    reference_at: particles",
             "probes[0].reference_at", "reference_at needs a reference field"},
            {"    component: y", "    component: y\n    reference_at: [1]", "probes[0].reference_at",
             "expected 2 coordinates", "    reference_at"},
            {"segment: [[1.5, 1.1], [2.5, 1.1]]", "segment: [[1.5, 1.1], [2.5, 1.1]]\n    tips: blunt",
             "cracks[0].tips", "'blunt' is not one of: cut, kept", "    tips"},
        });
}

TEST(SceneErrors, ThreeDimensionalScenes) {
  check(
      kScene3,
      {
          {"sphere: {center: [0.5, 0.5, 0.5], radius: 0.2}", "polygon: [[0, 0, 0], [1, 0, 0], [1, 1, 0]]",
           "domain.holes[0].polygon", "polygons are 2D shapes"},
          {"[[0, 0, 0.5], [1, 0, 0.5], [1, 1, 0.5]]", "[[0, 0, 0.5], [1, 0, 0.5]]", "cracks[0].polygon",
           "a 3D crack is a planar polygon: at least three points"},
          {"[[0, 0, 0.5], [1, 0, 0.5], [1, 1, 0.5]]", "[[0, 0, 0.5], [1, 0, 0.5], [1, 1, 0.5], [0, 1, 0.9]]",
           "cracks[0].polygon", "the polygon is not planar"},
          {"[[0, 0, 0.5], [1, 0, 0.5], [1, 1, 0.5]]", "[[0, 0, 0.5], [1, 0, 0.5], [2, 0, 0.5]]",
           "cracks[0].polygon", "the polygon has no area"},
          {"{E: 1, nu: 0.25}", "{E: 1, nu: 0.25, plane: strain}", "materials[0].plane",
           "'strain' is not one of: none"},
          {"fixed: [x, y, z]", "fixed: [x, y, w]", "boundary[0].fixed",
           "'w' is not a component of a 3D scene"},
          {"{side: front}", "{side: middle}", "boundary[0].region.side",
           "'middle' is not one of: left, right, bottom, top, back, front"},
          {"law: lps_3d", "law: silling_plane_strain", "law",
           "law silling_plane_strain is 2D, the scene is 3D"},
      });
}

TEST(SceneErrors, SyntaxErrorsAndFiles) {
  const std::string syntax = error_of("dimension: 2\ndomain: [1, 2\n");
  EXPECT_TRUE(std::regex_search(syntax, std::regex(R"(^scene\.yaml:\d+: YAML syntax error)"))) << syntax;
  const std::string list = error_of("- 1\n- 2\n");
  EXPECT_TRUE(std::regex_search(list, std::regex(R"(^scene\.yaml:1: \(top level\): expected a map)")))
      << list;
  try {
    pd::read_scene("/nonexistent/dir/scene.yaml");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const pd::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.yaml"), std::string::npos) << e.what();
  }
}
