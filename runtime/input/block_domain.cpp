// The domain section of a scene whose body is made of lattice blocks.
#include "input/block_domain.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "input/enum_choice.hpp"
#include "input/lattice_block_cloud.hpp"

namespace pd {

void read_block_domain(const YamlAt& domain, Scene& s) {
  MapReader d(domain);
  for (const char* key :
       {"box", "count", "spacing", "placement", "perturbation", "holes", "inclusions", "particles"})
    if (d.has(key))
      d.get(key).fail(std::string(key) + " does not apply to a body of blocks (give it per block)");
  const std::vector<Quadrature> supported = quadratures_with(&QuadratureRule::blocks);
  if (d.has("quadrature"))
    s.quadrature = read_word(d.get("quadrature"), supported, [&](const std::string&) {
      return "a body of blocks supports quadrature: " + name_list<Quadrature>(supported, " or ") +
             " (paper 003 eq. 17)";
    });
  const YamlAt list = d.get("blocks");
  require_list(list);
  if (list.node.size() == 0) list.fail("give at least one block");
  std::vector<LatticeBlock> blocks;
  for (std::size_t i = 0; i < list.node.size(); ++i) {
    const YamlAt at = list.element(list.node[i], i);
    MapReader b(at);
    MapReader box(b.get("box"));
    LatticeBlock block;
    block.lo = to_point(box.get("min"), s.dim);
    block.hi = to_point(box.get("max"), s.dim);
    box.finish();
    for (int c = 0; c < s.dim; ++c)
      if (!(block.hi[c] > block.lo[c])) b.get("box").fail("max must exceed min in every coordinate");
    block.spacing = b.number("spacing");
    if (!(block.spacing > 0)) b.get("spacing").fail("spacing must be positive");
    for (int c = 0; c < s.dim; ++c)
      if ((block.hi[c] - block.lo[c]) / block.spacing > 1e5)
        b.get("spacing").fail("more than 1e5 particles along an axis");
    block.where = at.location();
    b.finish();
    blocks.push_back(block);
  }
  d.finish();
  auto p = std::make_shared<Particles>();
  try {
    *p = lattice_blocks(blocks, s.dim, s.particle_spacing);
  } catch (const std::invalid_argument& e) {
    throw SceneError(e.what());
  }
  s.lo = blocks[0].lo, s.hi = blocks[0].hi;
  s.h = 0;
  for (const LatticeBlock& b : blocks) {
    for (int c = 0; c < s.dim; ++c)
      s.lo[c] = std::min(s.lo[c], b.lo[c]), s.hi[c] = std::max(s.hi[c], b.hi[c]);
    s.h = std::max(s.h, b.spacing);
  }
  s.placement = Placement::cell;
  s.point_cloud = std::move(p);
}

}  // namespace pd
