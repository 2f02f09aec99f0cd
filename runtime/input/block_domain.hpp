// `domain: {blocks: [{box: {min, max}, spacing}, ...]}`: a non-uniform body made of lattice
// blocks, each with its own spacing (runtime/discretize/lattice_blocks.hpp; paper 003
// Fig. 23). horizon.ratio then gives each particle delta = ratio * its block's spacing;
// horizon.length one delta for all.
#pragma once

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

// Reads the blocks into s.point_cloud (material 0: inclusions do not apply) and
// s.particle_spacing; sets s.lo, s.hi (the blocks' bounding box), s.h (the largest
// spacing: what `side` regions take as the outermost row's thickness) and placement
// "cell". Errors name the block: a side that is not a whole number of spacings, overlapping
// blocks, and keys of the single lattice (box, count, spacing, holes, ...).
void read_block_domain(const YamlAt& domain, Scene& s);

}  // namespace pd
