// The effects built from a scene's conditions: dead nodal forces (tractions and constant
// body forces), crack pressure, body forces from an analytic field, the pre-cracks, and
// a dynamic run's timed loads (damage evolution: damage_evolution.hpp). Each factory
// returns nullptr when the scene does not call for it; model/model_effects.cpp puts
// them in the model in the order the run log lists them.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "effects/effect.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

// Dead loads given as a nodal force vector [n * dim] at full load.
std::unique_ptr<Effect> make_nodal_forces(std::vector<double> f, std::string description);

// Dead loads: tractions on boundary particles (paper 000 eq. 34: the total force T x
// face measure shared equally by the region's particles) and body forces (per volume).
std::unique_ptr<Effect> make_external_loads(const Scene& scene, const Particles& p);
// The same for some of the scene's conditions only (a dynamic run scales each by its own
// function of time); the others in `conditions` are skipped.
std::unique_ptr<Effect> make_external_loads(const Scene& scene, const Particles& p,
                                            std::span<const BoundaryCondition> conditions);

// Crack pressure on the broken bonds between nearest neighbours across a crack
// (paper 000 eqs. 23, 30): a pair force of magnitude p V / |xi| along the deformed
// bond, pushing the two particles apart (p h per face particle for |xi| = h in 2D). On a
// perturbed cloud the pair forces are scaled so the total normal load on each face is
// still p x crack length (area in 3D); on the paper's lattice the scale is exactly 1.
// One effect for all the pressurised cracks given; h: the particle spacing (the pairs
// are the nearest neighbours, |xi| < 1.2 h, whose bond the crack crosses). Reads the
// bonds and particles without copying them.
std::unique_ptr<Effect> make_crack_pressure(std::span<const Crack> cracks, double h, const Particles& p,
                                            const Bonds& bonds);
std::unique_ptr<Effect> make_crack_pressure(const Scene& scene, const Particles& p, const Bonds& bonds);

// The scene's `body_force: {field: ...}`: b(x_i) V_i on the region's particles, b the body
// force density of an analytic field (effects/body_force_field.cpp).
std::unique_ptr<Effect> make_body_force_field(const Scene& scene, const Particles& p);

// The bonds the pre-cracks cut (`cut_bonds` > 0, each once), as the run log's line.
std::unique_ptr<Effect> make_pre_cracks(long long cut_bonds);

// A dynamic run's load: `inner` at f(t) for the t the driver passes as the load; its log
// line is the inner one plus `suffix` (", times ramp(...)").
std::unique_ptr<Effect> make_timed(std::unique_ptr<Effect> inner, TimeFunction time, std::string suffix);

}  // namespace pd
