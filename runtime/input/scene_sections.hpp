// What the readers of a scene's sections share (scene.cpp reads them in order): the scene
// read so far, the YAML with its locations, and what a later section or a rule
// (scene_rules.hpp) needs of an earlier one. Internal to input/.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "input/particle_file.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "kernel_abi.hpp"

namespace pd {

// The scene's top-level sections, in the order they are read.
enum class Section {
  dimension,
  domain,
  horizon,
  law,
  influence,
  materials,
  boundary,
  cracks,
  body_force,
  solver,
  output,
  probes,
  reference,
  dynamics,
  damage
};

struct SceneReading {
  Scene& s;
  YAML::Node root;
  YamlAt top;
  MapReader& m;                             // the top-level map
  const abi::LawDescriptor* law = nullptr;  // once `law` is read
  std::optional<ParticleFile> cloud;        // domain.particles, attached once the materials are known
  // A top-level key as a location (the node may be missing: "file:?: key").
  YamlAt section(const std::string& key) const { return top.child(root[key], key); }
};

// x, y, z as an index below dim, or -1.
int axis_index(std::string_view word, int dim);
// axis_index, failing at `at` ("'w' is not a component of a 2D scene").
int component_index(const YamlAt& at, const std::string& c, int dim);
// `x` or a list of components.
std::array<bool, 3> read_components(const YamlAt& at, int dim);

// An optional top-level list `key`: read(element, index) for each element, into `out`.
template <class T, class Read>
void read_list(SceneReading& r, const std::string& key, std::vector<T>& out, Read read) {
  if (!r.m.has(key)) return;
  const YamlAt list = r.m.get(key);
  require_list(list);
  for (std::size_t i = 0; i < list.node.size(); ++i) out.push_back(read(list.element(list.node[i], i), i));
}

// The section readers (one file each: read_domain.cpp, read_law.cpp, ...).
void read_domain(SceneReading& r);
void read_horizon(SceneReading& r);
void read_law(SceneReading& r);
void read_influence(SceneReading& r);
void read_materials(SceneReading& r);
void read_boundary(SceneReading& r);
void read_cracks(SceneReading& r);
void read_output(SceneReading& r);
void read_probes(SceneReading& r);
// An analytic field (`reference`, a probe's reference, a field condition) and `body_force`.
FieldSpec read_field(const YamlAt& at, int dim);
BodyForceField read_body_force(const YamlAt& at, int dim);

}  // namespace pd
