// From a scene to particles and families: lattice points in the domain box (cell
// centers or nodes), holes removed, inclusions tagged, a seeded perturbation, then
// neighbour search with a cell list; bond cutting by cracks is in crack_cut.hpp.
#pragma once

#include <vector>

#include "discretize/crack_cut.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

// Lattice points of the scene's domain (volume h^dim each), holes removed, inclusion
// materials assigned, perturbed by amplitude*h (uniform, seeded) when asked.
Particles discretize(const Scene& scene);

// The particles of a region, ascending.
std::vector<int> region_particles(const Region& region, const Particles& p, const Scene& scene);

// All pairs closer than delta (|xi| <= delta (1 + 1e-12)), both directions, in
// compressed rows sorted by neighbour index; w from the influence function; alpha = 1.
Bonds find_bonds(const Particles& p, double delta, double (*influence)(double r, double delta));

// Removes the bonds whose influence weight is negligible, w <= 1e-12 max w (the ring
// exactly delta away for an influence function that vanishes at r = delta -- linear,
// quadratic, cubic -- where rounding of |xi| leaves w at 1e-48 rather than 0), keeping
// the compressed rows. Close to exact for every law whose force state carries w (all of
// laws/), but a law may ignore w, so only approximations use it: the short-horizon
// preconditioner, where at delta = 2h that ring is a third of the family and its
// couplings widen the factor's fill (the 400^2 crack with Oterkus's law: UMFPACK ran out
// of memory). Returns the count.
int drop_negligible_bonds(Bonds& bonds);

// The mean family size that find_bonds(p, short_delta, influence) followed by
// drop_negligible_bonds would give, counted on existing bonds of a horizon >= short_delta
// (without building the short families): what the solver-path rule estimates the
// short-horizon preconditioner from.
double mean_short_family_size(const Bonds& bonds, double short_delta,
                              double (*influence)(double r, double delta));

}  // namespace pd
