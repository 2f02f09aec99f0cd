// The scene reader: YAML -> Scene, one section after another (a file each: read_domain.cpp,
// read_law.cpp, ...), the cross-section rules (scene_rules.cpp) checked as soon as their
// sections are read, every key checked (runtime/input/yaml_keys.hpp).
#include "input/scene.hpp"

#include "input/particle_domain.hpp"
#include "input/scene_rules.hpp"
#include "input/solver_reader.hpp"

namespace pd {

namespace {

struct SectionReader {
  Section section;
  void (*read)(SceneReading& r);
};

// In the order the sections are read: a section's reader may use the ones before it.
const SectionReader kSections[] = {
    {Section::dimension,
     [](SceneReading& r) {
       r.s.dim = r.m.integer("dimension", 2);
       if (r.s.dim != 2 && r.s.dim != 3) r.m.get("dimension").fail("dimension must be 2 or 3");
     }},
    {Section::domain, read_domain},
    {Section::horizon, read_horizon},
    {Section::law, read_law},
    {Section::influence, read_influence},
    {Section::materials, read_materials},
    {Section::boundary, read_boundary},
    {Section::cracks, read_cracks},
    {Section::body_force,
     [](SceneReading& r) {
       if (r.m.has("body_force")) r.s.body_force = read_body_force(r.m.get("body_force"), r.s.dim);
     }},
    {Section::solver,
     [](SceneReading& r) {
       if (r.m.has("solver")) r.s.solver = read_solver(r.m.get("solver"));
     }},
    {Section::output, read_output},
    {Section::probes, read_probes},
    {Section::reference,
     [](SceneReading& r) {
       if (r.m.has("reference")) r.s.reference = read_field(r.m.get("reference"), r.s.dim);
     }},
    // Without dynamics, damage breaks bonds between the Newton load steps (Simulation).
    {Section::dynamics,
     [](SceneReading& r) {
       if (r.m.has("dynamics")) r.s.dynamics = read_dynamics(r.m.get("dynamics"), r.s.dim);
     }},
    {Section::damage,
     [](SceneReading& r) {
       if (r.m.has("damage")) r.s.damage = read_damage(r.m.get("damage"));
     }},
};

Scene read(const YAML::Node& root, const std::string& file) {
  Scene s;
  s.file = file;
  const YamlAt top{root, file, ""};
  MapReader m(top);
  SceneReading r{s, root, top, m, nullptr, std::nullopt};
  for (const SectionReader& section : kSections) {
    section.read(r);
    apply_scene_rules(section.section, r);
  }
  if (r.cloud) attach_point_cloud(r.section("domain"), *r.cloud, s);  // its materials are checked
  m.finish();
  return s;
}

}  // namespace

std::vector<double> Scene::particle_horizons() const {
  std::vector<double> delta(particle_spacing.size());
  for (std::size_t i = 0; i < delta.size(); ++i)
    delta[i] = horizon_length > 0 ? horizon_length : horizon_ratio * particle_spacing[i];
  return delta;
}

int Scene::material_index(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

Scene parse_scene(const std::string& yaml, const std::string& name) {
  const YAML::Node root = parse_yaml(yaml, name);
  if (!root.IsMap()) throw SceneError(name + ":1: (top level): expected a map of keys");
  return read(root, name);
}

Scene read_scene(const std::string& path) { return parse_scene(read_input_file(path, "scene"), path); }

}  // namespace pd
