// The model in two phases: the body (particles, bonds, law parameters, family checks,
// quadrature, dofs), then the assemblers the plan asks for (the effects: model_effects.cpp).
#include "model/model.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "assembly/compensation.hpp"
#include "assembly/surface_correction.hpp"
#include "constraints/constraints.hpp"
#include "discretize/crack_cut.hpp"
#include "discretize/discretization.hpp"
#include "discretize/lattice_blocks.hpp"
#include "discretize/law_space.hpp"
#include "discretize/partial_volume.hpp"
#include "input/yaml_keys.hpp"  // SceneError
#include "material/admissible_poisson.hpp"
#include "material/elastic_constants.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
// `domain.quadrature: obq_cut`: the region the particles cover, which the families at a
// face integrate over -- the box, grown by h/2 for node placement (the particles on
// the faces stand for cells that reach half a spacing beyond them). None for `obq`.
std::optional<Box2> obq_cut_body(const Scene& scene) {
  if (!quadrature_rule(scene.quadrature).cut_box_body) return std::nullopt;
  if (scene.dim != 2 || scene.point_cloud || !scene.holes.empty())
    throw std::invalid_argument(scene.file +
                                ": domain.quadrature: " + std::string(name_of(scene.quadrature)) +
                                " needs a 2D box body without holes (use obq)");
  const double grow = scene.placement == Placement::node ? 0.5 * scene.h : 0.0;
  Box2 body;
  for (int a = 0; a < 2; ++a) body.lo[a] = scene.lo[a] - grow, body.hi[a] = scene.hi[a] + grow;
  return body;
}

void check_neighbours(const Particles& p, const Bonds& bonds) {
  for (int i = 0; i < p.size(); ++i)
    if (bonds.family_size(i) == 0)
      throw SceneError(fmt::format("particle {} at ({:.6g}, {:.6g}) has no neighbour within the horizon", i,
                                   p.x[i * p.dim], p.x[i * p.dim + 1]));
}

// The scene's pre-cracks cut the bonds; a crack that cuts none is named in the warnings.
int cut_by_pre_cracks(const Scene& scene, const Particles& particles, Bonds& bonds,
                      std::vector<std::string>& warnings) {
  std::vector<int> crossed;
  const int cut = cut_bonds(scene.cracks, particles, bonds, &crossed) / 2;
  for (std::size_t c = 0; c < scene.cracks.size(); ++c)
    if (crossed[c] == 0)
      warnings.push_back(scene.cracks[c].where +
                         ": the crack crosses no bond (it lies outside the body, in a hole, "
                         "or between particles closer than a spacing): it has no effect");
  return cut;
}

// domain.surface_correction (paper 003): scale the bonds of the families cut by a surface.
void correct_surface_bonds(const Scene& scene, const DiscretizedBody& b, Bonds& bonds) {
  if (!scene.particle_spacing.empty())
    throw SceneError(scene.file +
                     ": domain.surface_correction: not with domain.blocks (the factors compare each "
                     "family with the full family of one regular lattice)");
  const SurfaceCorrectionInputs in{
      b.law, &b.params, scene.delta(), scene.h, scene.quadrature, b.influence->weight, scene.surface_match};
  apply_surface_correction(bonds, surface_correction_factors(b.particles, bonds, in),
                           b.law->has_dilatation_sum);
}

// domain.quadrature: obq / obq_cut (paper 001): the collocation weights on the bonds.
std::unique_ptr<Collocation> obq_collocation(const Scene& scene, const DiscretizedBody& b,
                                             std::string& description) {
  const std::optional<Box2> body = obq_cut_body(scene);
  ReproducingSpace space =
      scene.obq_space == ObqSpace::paper001_odd ? paper001_odd_space(scene.dim) : paper001_space(scene.dim);
  if (scene.obq_space == ObqSpace::law) try {
      space = law_reproducing_space(*b.law, scene.dim, b.influence->weight, b.influence->name);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(scene.file + ": domain.obq_space: " + e.what());
    }
  return std::make_unique<Collocation>(make_obq_collocation(b.particles, b.bonds, space, description,
                                                            body ? &*body : nullptr, scene.obq_symmetric));
}

// domain.gauss_points (paper 002 §3.3). The Gauss bonds are not cut by cracks and do not
// break; the cells are of one spacing.
std::unique_ptr<GaussPoints> gauss_points_of(const Scene& scene, const DiscretizedBody& b) {
  if (!scene.cracks.empty() || scene.damage || !scene.particle_spacing.empty())
    throw SceneError(scene.file +
                     ": domain.gauss_points: not with cracks, damage or domain.blocks (the Gauss bonds "
                     "are not cut and do not break; the cells need one spacing)");
  GaussPointOptions o;
  o.per_axis = scene.gauss_points;
  o.support = scene.gauss_support;
  return std::make_unique<GaussPoints>(
      build_gauss_points(b.particles, scene.h, scene.delta(), b.influence->weight, o));
}
}  // namespace

DiscretizedBody::DiscretizedBody(const Scene& scene) {
  const auto t0 = std::chrono::steady_clock::now();
  law = abi::find_law(scene.law);
  influence = abi::find_influence(scene.influence);
  if (!law || !influence) throw std::invalid_argument("unknown law or influence function");
  particles = discretize(scene);
  bonds = scene.particle_spacing.empty()
              ? find_quadrature_bonds(particles, scene.delta(), scene.h, scene.quadrature, influence->weight)
              : find_block_bonds(particles, scene.particle_horizons(), scene.particle_spacing,
                                 scene.quadrature, influence->weight);  // domain.blocks
  bond_count = bonds.bond_count() / 2;
  warnings = scene.warnings;
  cut_by_cracks = cut_by_pre_cracks(scene, particles, bonds, warnings);
  check_neighbours(particles, bonds);
  quality = check_family_quality(particles, bonds, influence->weight, influence->name, scene.h);
  for (const MaterialSpec& mat : scene.materials)
    params.push_back(law_parameters(*law, mat.elastic, mat.plane, mat.parameters));
  if (scene.compensation) {
    const CompensationInputs in{law, &params, scene.delta(), scene.h, scene.quadrature, influence->weight};
    apply_compensation(bonds, compensation_factors(particles, bonds, in));
  }
  if (scene.surface_correction) correct_surface_bonds(scene, *this, bonds);
  if (quadrature_rule(scene.quadrature).own_weights)
    collocation = obq_collocation(scene, *this, collocation_description);
  if (scene.gauss_points > 0) gauss_points = gauss_points_of(scene, *this);
  for (const MaterialSpec& mat : scene.materials)
    warn_if_poisson_ratio_differs(*law, mat.elastic, mat.plane, mat.name);
  dofs = scene_constraints(scene, particles);
  build_seconds = seconds_since(t0);
}

Model::Model(const Scene& scene, const Planner& planner) : DiscretizedBody(scene) {
  const auto t0 = std::chrono::steady_clock::now();
  const ModelPlan plan = planner(*this);
  for (std::size_t b = 0; law->n_history > 0 && b < bonds.neighbor.size(); ++b)
    bond_history.insert(bond_history.end(), law->history_initial, law->history_initial + law->n_history);
  for (int p = 0; law->n_particle_history > 0 && p < particles.size(); ++p)
    particle_history.insert(particle_history.end(), law->particle_history_initial,
                            law->particle_history_initial + law->n_particle_history);
  // The short horizon first: the damage effect breaks its bonds with the real ones.
  if (plan.short_delta) build_short_horizon(scene, *plan.short_delta);
  build_assembler(scene, plan);
  build_effects(scene);
  build_seconds += seconds_since(t0);
}

void Model::commit_history(const double* u) {
  if (!has_history()) return;
  const FamilyAssembler* families = assembler->bond_families();
  if (families == nullptr)
    throw std::logic_error("commit_history: a law with history needs the bond-family assembler");
  const LawHistory updated = families->updated_history(u);
  // In place: the assembler points into these arrays.
  std::copy(updated.bond.begin(), updated.bond.end(), bond_history.begin());
  std::copy(updated.particle.begin(), updated.particle.end(), particle_history.begin());
}

void Model::build_assembler(const Scene& scene, const ModelPlan& plan) {
  AssemblerOptions options;
  // A scene with damage needs the damaged variant from the start: bonds may break.
  options.intact = cut_by_cracks == 0 && !scene.damage;
  options.matrix = plan.matrix;
  options.threads = plan.threads;
  options.collocation = collocation.get();
  options.gauss_points = gauss_points.get();
  options.history = bond_history.empty() ? nullptr : bond_history.data();
  options.particle_history = particle_history.empty() ? nullptr : particle_history.data();
  options.time_step = &step_duration;
  assembler = make_force_operator(particles, bonds, *law, params, options);
  assembler_options = options;
}

void Model::build_short_horizon(const Scene& scene, double short_delta) {
  if (collocation) {
    // OBQ collocation (paper 001): the volume rule's stiffness on a shorter horizon is not
    // an approximation of this operator -- on scenes/paper001_hole.yaml it left matrix-free
    // GMRES at a relative residual of 1.8e-2 after 20 000 iterations, and PETSc's Krylov
    // solve likewise, even with an exact factor of it. The preconditioner is the collocation
    // tangent itself (its own bonds and weights): a factor of it solves in one iteration.
    AssemblerOptions options;
    options.intact = cut_by_cracks == 0 && !scene.damage;
    options.collocation = collocation.get();
    approximation = std::make_unique<FamilyAssembler>(particles, bonds, *law, params, options);
    return;
  }
  // The same law's stiffness on a horizon of ratio h: far fewer nonzeros, and spectrally
  // close on the smooth modes that make K ill-conditioned.
  // A body of blocks: each particle's own short horizon min(delta_i, ratio h_i) -- one
  // short_delta from the largest spacing would give a fine particle more bonds than its real
  // family, and a coarse one at the interface a degenerate family.
  if (!scene.particle_spacing.empty()) {
    std::vector<double> delta = scene.particle_horizons();
    for (std::size_t i = 0; i < delta.size(); ++i)
      delta[i] = std::min(delta[i], scene.solver.preconditioner_ratio * scene.particle_spacing[i]);
    short_bonds = find_bonds_per_particle(particles, delta, influence->weight);
  } else {
    short_bonds = find_bonds(particles, short_delta, influence->weight);
  }
  drop_negligible_bonds(short_bonds);
  const int cut = cut_bonds(scene.cracks, particles, short_bonds);
  AssemblerOptions options;
  options.intact = cut == 0 && !scene.damage;
  approximation = std::make_unique<FamilyAssembler>(particles, short_bonds, *law, params, options);
}

}  // namespace pd
