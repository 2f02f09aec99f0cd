// `domain: {particles: FILE, spacing: h}`: a body given as a point cloud
// (runtime/input/particle_file.hpp) instead of a box lattice.
#pragma once

#include <memory>
#include <optional>

#include "input/particle_file.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

// Reads the domain map: the file (relative to the scene's directory), the optional
// nominal spacing (default: the mean of volume^(1/dim)); sets s.lo, s.hi (the
// particles' bounding box), s.h and placement "node" (the box faces pass through the
// outermost particles, so `side` regions take the outermost row). Keys of the box
// lattice (box, count, holes, ...) are errors here.
ParticleFile read_particle_domain(const YamlAt& domain, Scene& s);

// Once the materials are known: the particles with their material indices, into
// s.point_cloud. Errors name the scene's domain.particles and the file's line.
void attach_point_cloud(const YamlAt& domain, const ParticleFile& f, Scene& s);

}  // namespace pd
