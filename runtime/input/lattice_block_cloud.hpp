// The particles of a non-uniform body (paper 003 sections 4.2, 5.3-5.4): several boxes, each
// filled with its own cell-centred lattice. The scene reader makes them when it reads
// `domain.blocks` (input/block_domain.cpp); their families are discretize/lattice_blocks.hpp's.
#pragma once

#include <string>
#include <vector>

#include "input/region.hpp"  // Point
#include "particles.hpp"

namespace pd {

struct LatticeBlock {
  Point lo{}, hi{};
  double spacing = 0;
  std::string where;  // "file:line: domain.blocks[i]" for messages
};

// The union of the blocks' cell-centred lattices, block by block; spacing[i] is particle
// i's lattice spacing. Throws std::invalid_argument naming the block when a block's
// sides are not whole multiples of its spacing (to 1e-9) or two blocks overlap.
Particles lattice_blocks(const std::vector<LatticeBlock>& blocks, int dim, std::vector<double>& spacing);

}  // namespace pd
