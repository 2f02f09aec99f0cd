// build_model: scene -> particles, bonds, law parameters, family checks.
#include "model/model.hpp"

#include <fmt/core.h>

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
  if (scene.quadrature != Quadrature::ObqCut) return std::nullopt;
  if (scene.dim != 2 || scene.point_cloud || !scene.holes.empty())
    throw std::invalid_argument(scene.file +
                                ": domain.quadrature: obq_cut needs a 2D box body without holes "
                                "(use obq)");
  const double grow = scene.placement == Placement::node ? 0.5 * scene.h : 0.0;
  Box2 body;
  for (int a = 0; a < 2; ++a) body.lo[a] = scene.lo[a] - grow, body.hi[a] = scene.hi[a] + grow;
  return body;
}
}  // namespace

Model build_model(const Scene& scene) {
  const auto t0 = std::chrono::steady_clock::now();
  Model m;
  m.law = abi::find_law(scene.law);
  m.influence = abi::find_influence(scene.influence);
  if (!m.law || !m.influence) throw std::invalid_argument("unknown law or influence function");
  m.particles = discretize(scene);
  m.bonds =
      scene.particle_spacing.empty()
          ? find_quadrature_bonds(m.particles, scene.delta(), scene.h, scene.quadrature, m.influence->weight)
          : find_block_bonds(m.particles, scene.particle_horizons(), scene.particle_spacing, scene.quadrature,
                             m.influence->weight);  // domain.blocks
  m.bond_count = m.bonds.bond_count() / 2;
  std::vector<int> crossed;
  m.cut_by_cracks = cut_bonds(scene.cracks, m.particles, m.bonds, &crossed) / 2;
  m.warnings = scene.warnings;
  for (std::size_t c = 0; c < scene.cracks.size(); ++c)
    if (crossed[c] == 0)
      m.warnings.push_back(scene.cracks[c].where +
                           ": the crack crosses no bond (it lies outside the body, in a hole, "
                           "or between particles closer than a spacing): it has no effect");
  const Particles& p = m.particles;
  for (int i = 0; i < p.size(); ++i)
    if (m.bonds.family_size(i) == 0)
      throw SceneError(fmt::format("particle {} at ({:.6g}, {:.6g}) has no neighbour within the horizon", i,
                                   p.x[i * p.dim], p.x[i * p.dim + 1]));
  m.quality = check_family_quality(p, m.bonds, m.influence->weight, m.influence->name, scene.h);
  for (const MaterialSpec& mat : scene.materials)
    m.params.push_back(law_parameters(*m.law, mat.elastic, mat.plane, mat.parameters));
  if (scene.compensation) {
    const CompensationInputs in{m.law,   &m.params,        scene.delta(),
                                scene.h, scene.quadrature, m.influence->weight};
    apply_compensation(m.bonds, compensation_factors(m.particles, m.bonds, in));
  }
  if (scene.surface_correction) {
    if (!scene.particle_spacing.empty())
      throw SceneError(scene.file +
                       ": domain.surface_correction: not with domain.blocks (the factors compare each "
                       "family with the full family of one regular lattice)");
    const SurfaceCorrectionInputs in{
        m.law,
        &m.params,
        scene.delta(),
        scene.h,
        scene.quadrature,
        m.influence->weight,
        scene.surface_match_responses ? SurfaceMatch::Responses : SurfaceMatch::Terms};
    apply_surface_correction(m.bonds, surface_correction_factors(m.particles, m.bonds, in),
                             m.law->has_dilatation_sum);
  }
  if (is_obq(scene.quadrature)) {
    const std::optional<Box2> body = obq_cut_body(scene);
    ReproducingSpace space =
        scene.obq_space == ObqSpace::paper001_odd ? paper001_odd_space(scene.dim) : paper001_space(scene.dim);
    if (scene.obq_space == ObqSpace::law) try {
        space = law_reproducing_space(*m.law, scene.dim, m.influence->weight, m.influence->name);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(scene.file + ": domain.obq_space: " + e.what());
      }
    m.collocation = std::make_unique<Collocation>(
        make_obq_collocation(m.particles, m.bonds, space, m.collocation_description, body ? &*body : nullptr,
                             scene.obq_symmetric));
  }
  if (scene.gauss_points > 0) {
    // The Gauss bonds are not cut by cracks and do not break; the cells are of one spacing.
    if (!scene.cracks.empty() || scene.damage || !scene.particle_spacing.empty())
      throw SceneError(scene.file +
                       ": domain.gauss_points: not with cracks, damage or domain.blocks (the Gauss bonds "
                       "are not cut and do not break; the cells need one spacing)");
    GaussPointOptions o;
    o.per_axis = scene.gauss_points;
    o.support = scene.gauss_support;
    m.gauss_points = std::make_unique<GaussPoints>(
        build_gauss_points(m.particles, scene.h, scene.delta(), m.influence->weight, o));
  }
  for (const MaterialSpec& mat : scene.materials)
    warn_if_poisson_ratio_differs(*m.law, mat.elastic, mat.plane, mat.name);
  m.dofs = scene_constraints(scene, m.particles);
  m.build_seconds = seconds_since(t0);
  return m;
}

AssemblerOptions attach_assembler(Model& model, const Scene& scene, bool matrix, int threads) {
  AssemblerOptions options;
  // A scene with damage needs the damaged variant from the start: bonds may break.
  options.intact = model.cut_by_cracks == 0 && !scene.damage;
  options.matrix = matrix;
  options.threads = threads;
  options.collocation = model.collocation.get();
  options.gauss_points = model.gauss_points.get();
  model.assembler = make_force_operator(model.particles, model.bonds, *model.law, model.params, options);
  model.assembler_options = options;
  return options;
}

void attach_short_horizon(Model& model, const Scene& scene, double short_delta) {
  if (model.collocation) {
    // OBQ collocation (paper 001): the volume rule's stiffness on a shorter horizon is not
    // an approximation of this operator -- on scenes/paper001_hole.yaml it left matrix-free
    // GMRES at a relative residual of 1.8e-2 after 20 000 iterations, and PETSc's Krylov
    // solve likewise, even with an exact factor of it. The preconditioner is the collocation
    // tangent itself (its own bonds and weights): a factor of it solves in one iteration.
    AssemblerOptions options;
    options.intact = model.cut_by_cracks == 0 && !scene.damage;
    options.collocation = model.collocation.get();
    model.approximation =
        std::make_unique<FamilyAssembler>(model.particles, model.bonds, *model.law, model.params, options);
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
    model.short_bonds = find_bonds_per_particle(model.particles, delta, model.influence->weight);
  } else {
    model.short_bonds = find_bonds(model.particles, short_delta, model.influence->weight);
  }
  drop_negligible_bonds(model.short_bonds);
  const int cut = cut_bonds(scene.cracks, model.particles, model.short_bonds);
  AssemblerOptions options;
  options.intact = cut == 0 && !scene.damage;
  model.approximation = std::make_unique<FamilyAssembler>(model.particles, model.short_bonds, *model.law,
                                                          model.params, options);
}

}  // namespace pd
