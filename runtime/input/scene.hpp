// A scene: everything a run needs, read from YAML (docs/scene_format.md). Plain data;
// every field has the default documented there. read_scene validates completely
// before returning, so a scene that is returned is usable.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "discretize/quadrature.hpp"
#include "input/dynamics_spec.hpp"
#include "input/region.hpp"
#include "input/time_function.hpp"
#include "material/elastic_constants.hpp"

namespace pd {

struct Shape {  // a hole or an inclusion
  enum class Kind { Circle, Polygon, Box } kind = Kind::Circle;
  Point center{};      // circle (sphere in 3D)
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
  std::array<bool, 3> components{};  // which components are constrained (Fixed, Displacement, Field, Velocity)
  Point values{};                    // prescribed displacement, velocity, traction or body force
  FieldSpec field;
  double face_measure = 0;           // Traction: length/area the traction acts on (0: the region's domain face)
  std::string where;                 // "file:line: boundary[i]", for messages found after reading
  // Dynamic scenes: the values are scaled by f(t) (a velocity's displacement is the
  // integral). Without one: constant 1, i.e. applied at t = 0.
  std::optional<TimeFunction> time;
  std::string time_where;  // "file:line: boundary[i].time_function"
};

struct Crack {
  std::vector<Point> points;  // 2D: a segment (2 points); 3D: a planar polygon
  double pressure = 0;
  // Dynamic scenes: the pressure is scaled by f(t); without one it acts from t = 0.
  std::optional<TimeFunction> time;
  std::string time_where;  // "file:line: cracks[i].time_function"
  std::string where;       // "file:line: cracks[i]", for warnings about the crack
};

struct SolverSpec {
  // auto | cholmod | umfpack | cg | bicgstab | matrix_free (Newton-Krylov on the
  // generated tangent-vector product, never forming K)
  std::string linear = "auto";
  std::string preconditioner = "auto";  // cg: ic | diagonal; bicgstab: ilut; matrix_free: short_horizon | diagonal
  double preconditioner_ratio = 2.0;  // matrix_free short_horizon: delta/h of the preconditioning stiffness
  std::string nonlinear = "newton";  // the only nonlinear method so far; the key keeps scenes explicit
  int load_steps = 1;
  double tolerance = 1e-10;     // on the residual norm relative to the load
  double increment_tolerance = 1e-9;  // or on the last Newton increment relative to u
  int max_iterations = 30;
  double krylov_tolerance = 1e-12;
  int krylov_max_iterations = 0;  // 0: 2 x unknowns for assembled Krylov, 20000 matrix-free
  // auto: the assembled tangent (a direct solver) up to this many estimated nonzeros,
  // matrix-free above. On the crack at delta/h = 3.5 (one run, shared machine) CHOLMOD
  // and the short-horizon matrix-free path broke even near 1.5e6 nonzeros (60^2: 1.10 s
  // vs 0.86 s); at 100^2 (4.3e6) matrix-free took 3.9 s against CHOLMOD's 15 s.
  long long direct_max_nonzeros = 2'000'000;
  // auto, above direct_max_nonzeros: the short-horizon preconditioner while its stiffness
  // has at most this many nonzeros (its factor must fit in memory), Jacobi above
  long long preconditioner_max_nonzeros = 40'000'000;
};

struct OutputSpec {
  std::string directory = "out";
  bool vtu = true;
  bool csv = true;
  // Paper 000 eq. (49): also write the displacement averaged over each family with this
  // influence function (and its field error). Empty: no smoothing.
  std::string smoothing_influence;
};

struct Probe {
  std::string name;
  Region region;
  int component = 0;
  std::optional<FieldSpec> reference;  // analytic field to compare the mean against
  std::string where;
};

struct Scene {
  std::string file;
  int dim = 2;
  Point lo{}, hi{};                // domain box
  double h = 0;                    // spacing
  std::string placement = "cell";  // cell: points at cell centers; node: on a lattice including the faces
  double perturbation = 0;         // fraction of h
  unsigned seed = 1;
  Quadrature quadrature = Quadrature::Volume;  // domain.quadrature
  std::vector<Shape> holes, inclusions;
  double horizon_ratio = 3.0;  // delta / h, unless horizon_length > 0
  double horizon_length = 0;
  std::string law;
  std::string influence = "const";
  std::vector<MaterialSpec> materials;  // [0] is the body's material
  std::vector<BoundaryCondition> boundary;
  std::vector<Crack> cracks;
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

  double delta() const { return horizon_length > 0 ? horizon_length : horizon_ratio * h; }
  int material_index(const std::string& name) const;
};

struct YamlAt;
// A region map (side / box / outside / collar / all); used by the section readers.
Region read_region(const YamlAt& at, int dim);

// Reads and validates a scene file; throws SceneError (file:line: key: message).
Scene read_scene(const std::string& path);
// Same, from YAML text (for tests and fuzzing); `name` stands for the file in messages.
Scene parse_scene(const std::string& yaml, const std::string& name);

}  // namespace pd
