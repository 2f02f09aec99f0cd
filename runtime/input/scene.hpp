// A scene: everything a run needs, read from YAML (docs/scene_format.md). Plain data;
// every field has the default documented there. read_scene validates completely
// before returning, so a scene that is returned is usable.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "input/dynamics_spec.hpp"
#include "input/enum_names.hpp"
#include "input/quadrature.hpp"
#include "input/region.hpp"
#include "input/solver_spec.hpp"
#include "input/surface_match.hpp"
#include "input/time_function.hpp"
#include "material/elastic_constants.hpp"
#include "particles.hpp"

namespace pd {

struct Shape {  // a hole or an inclusion
  enum class Kind { Circle, Polygon, Box } kind = Kind::Circle;
  Point center{};  // circle (sphere in 3D)
  double radius = 0;
  std::vector<Point> vertices;  // polygon (2D)
  Point min{}, max{};           // box
  std::string material;         // inclusions only
  bool contains(const double* x, int dim) const;
};

struct MaterialSpec {
  std::string name = "default";
  IsotropicElastic elastic;
  PlaneAssumption plane = PlaneAssumption::Strain;
  double density = 1.0;
  std::map<std::string, double> parameters;  // extra law parameters by name
};

// An analytic solution and its parameters (see runtime/fields/analytic.hpp).
struct FieldSpec {
  std::string solution;  // uniaxial biaxial shear westergaard
  std::map<std::string, double> parameters;
};

struct BoundaryCondition {
  // Velocity: a prescribed velocity (dynamic scenes only).
  enum class Kind { Fixed, Displacement, Field, Traction, BodyForce, Velocity } kind = Kind::Fixed;
  Region region;
  std::array<bool, 3>
      components{};  // which components are constrained (Fixed, Displacement, Field, Velocity)
  Point values{};    // prescribed displacement, velocity, traction or body force
  FieldSpec field;
  double face_measure = 0;  // Traction: length/area the traction acts on (0: the region's domain face)
  std::string where;        // "file:line: boundary[i]", for messages found after reading
  // Dynamic scenes: the values are scaled by f(t) (a velocity's displacement is the
  // integral). Without one: constant 1, i.e. applied at t = 0.
  std::optional<TimeFunction> time;
  std::string time_where;  // "file:line: boundary[i].time_function"
  // `method: fictitious_layer` (paper 003 eqs. 29-35): the region is a layer outside the
  // body whose particles follow their mirror images across `face` (discretize/fictitious_layer.hpp).
  enum class Method { on_body, fictitious_layer } method = Method::on_body;
  Point face_point{}, face_normal{};  // a point of the body's face, unit normal out of the body
};

// `body_force: {field, region}`: a body force density from an analytic field on the
// region's particles (effects/body_force_field.cpp).
struct BodyForceField {
  FieldSpec field;
  Region region;      // default: all particles
  std::string where;  // "file:line: body_force", for messages found after reading
};

// What a bond passing exactly through a 2D crack tip does (docs/scene_format.md).
enum class CrackTips { cut, kept };
template <>
struct enum_names<CrackTips> {
  static constexpr std::array<EnumName<CrackTips>, 2> table{
      {{CrackTips::cut, "cut"}, {CrackTips::kept, "kept"}}};
};

// domain.placement: cell: points at cell centres; node: on a lattice including the faces.
enum class Placement { cell, node };
template <>
struct enum_names<Placement> {
  static constexpr std::array<EnumName<Placement>, 2> table{
      {{Placement::cell, "cell"}, {Placement::node, "node"}}};
};

// domain.obq_space: the reproducing space of the OBQ weights (discretize/obq_weights.hpp).
enum class ObqSpace { paper001, paper001_odd, law };
template <>
struct enum_names<ObqSpace> {
  static constexpr std::array<EnumName<ObqSpace>, 3> table{
      {{ObqSpace::paper001, "paper001"}, {ObqSpace::paper001_odd, "paper001_odd"}, {ObqSpace::law, "law"}}};
};

struct Crack {
  std::vector<Point> points;  // 2D: a segment (2 points); 3D: a planar polygon
  CrackTips tips = CrackTips::cut;
  double pressure = 0;
  // Dynamic scenes: the pressure is scaled by f(t); without one it acts from t = 0.
  std::optional<TimeFunction> time;
  std::string time_where;  // "file:line: cracks[i].time_function"
  std::string where;       // "file:line: cracks[i]", for warnings about the crack
};

// output.j_integral: a rectangular contour for the nonlocal J-integral (post/j_integral.hpp).
struct JContour {
  Point min{}, max{};
  std::string where;  // "file:line: output.j_integral[i]", for messages
};

struct OutputSpec {
  std::string directory = "out";
  bool vtu = true;
  bool csv = true;
  // Paper 000 eq. (49): also write the displacement averaged over each family with this
  // influence function (and its field error). Empty: no smoothing.
  std::string smoothing_influence;
  std::vector<JContour> j_integral;  // static 2D runs: J on each contour (paper 004)
  bool stress = false;  // the peridynamic stress field (paper 002 eq. 2.13, assembly/peridynamic_stress.hpp)
};

struct Probe {
  std::string name;
  Region region;
  // What is averaged: a displacement component, or a component (row, column) of the
  // peridynamic stress (assembly/peridynamic_stress.hpp; `quantity: stress`, `component: xy`).
  enum class Quantity { displacement, stress } quantity = Quantity::displacement;
  int component = 0;                   // displacement component, or the stress row (force component)
  int stress_column = 0;               // stress column (bond component)
  std::optional<FieldSpec> reference;  // analytic field to compare the mean against (displacement only)
  // Where the reference is taken (docs/scene_format.md, `reference_at`): the region's
  // point (the paper's, default), an explicit point, or the mean over the particles.
  enum class ReferenceAt { region, point, particles } reference_at = ReferenceAt::region;
  Point reference_point{};
  std::string where;
};

struct Scene {
  std::string file;
  int dim = 2;
  Point lo{}, hi{};  // domain box
  double h = 0;      // spacing
  Placement placement = Placement::cell;
  double perturbation = 0;  // fraction of h
  unsigned seed = 1;
  Quadrature quadrature = Quadrature::Volume;  // domain.quadrature
  ObqSpace obq_space = ObqSpace::paper001;     // domain.obq_space
  bool obq_symmetric = false;                  // domain.obq_symmetric
  bool compensation = false;  // domain.compensation (paper 002 eq. 3.61, assembly/compensation.hpp)
  bool surface_correction =
      false;  // domain.surface_correction (paper 003 eq. 19, assembly/surface_correction.hpp)
  SurfaceMatch surface_match = SurfaceMatch::Terms;  // ... : terms, responses or directions
  // domain.gauss_points (paper 002 §3.3, discretize/gauss_points.hpp): points per axis of
  // each cell (0: off, the quadrature above) and the MLS support in units of h.
  int gauss_points = 0;
  double gauss_support = 3.0;
  std::vector<Shape> holes, inclusions;
  double horizon_ratio = 3.0;  // delta / h, unless horizon_length > 0
  double horizon_length = 0;
  std::string law;
  std::string influence = "const";
  std::vector<MaterialSpec> materials;  // [0] is the body's material
  std::vector<BoundaryCondition> boundary;
  std::vector<Crack> cracks;
  std::optional<BodyForceField> body_force;
  // What the reader accepted but a careful user would want to hear about ("file:line: key:
  // message"): the run logs each as a warning and lists them in summary.json.
  std::vector<std::string> warnings;
  SolverSpec solver;
  OutputSpec output;
  std::vector<Probe> probes;
  // Analytic field for the global error of paper 000 eq. (48), when given.
  std::optional<FieldSpec> reference;
  // Present only when the scene calls for them: `pd run` then uses the dynamic driver
  // (dynamics) and bonds break at a critical stretch (damage).
  std::optional<DynamicsSpec> dynamics;
  std::optional<DamageSpec> damage;
  // domain.particles: the body read from a file (input/particle_domain.hpp), used by
  // discretize() instead of the box lattice.
  std::shared_ptr<const Particles> point_cloud;
  // domain.blocks (input/block_domain.hpp): the lattice spacing of each particle of
  // point_cloud; empty for a single lattice or a particle file.
  std::vector<double> particle_spacing;

  double delta() const { return horizon_length > 0 ? horizon_length : horizon_ratio * h; }
  // The horizon of each particle of a body of blocks (ratio times its spacing, or the
  // one length); empty otherwise, when delta() is everyone's.
  std::vector<double> particle_horizons() const;
  int material_index(const std::string& name) const;
};

struct YamlAt;
// A point of the scene: exactly dim numbers (SceneError naming the key otherwise: "expected 2
// coordinates", or `what` instead of coordinates).
Point to_point(const YamlAt& at, int dim, const char* what = "coordinates");
// A region map (side / box / outside / collar / all); used by the section readers.
Region read_region(const YamlAt& at, int dim);

// Reads and validates a scene file; throws SceneError (file:line: key: message).
Scene read_scene(const std::string& path);
// Same, from YAML text (for tests and fuzzing); `name` stands for the file in messages.
Scene parse_scene(const std::string& yaml, const std::string& name);

}  // namespace pd
