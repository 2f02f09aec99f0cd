// The domain section of a scene whose body is a point cloud.
#include "input/particle_domain.hpp"

#include <cmath>
#include <filesystem>

#include "input/enum_choice.hpp"

namespace pd {

ParticleFile read_particle_domain(const YamlAt& domain, Scene& s) {
  MapReader d(domain);
  for (const char* key : {"box", "count", "placement", "perturbation", "holes", "inclusions"})
    if (d.has(key)) d.get(key).fail(std::string(key) + " does not apply to a body read from a particle file");
  const YamlAt at = d.get("particles");
  std::filesystem::path path = d.text("particles");
  if (path.is_relative()) path = std::filesystem::path(s.file).parent_path() / path;
  ParticleFile f;
  try {
    f = read_particle_file(path.string(), s.dim);
  } catch (const SceneError& e) {
    at.fail(e.what());
  }
  double mean = 0;
  for (double v : f.volume) mean += std::pow(v, 1.0 / s.dim);
  s.h = mean / f.size();
  if (d.has("spacing")) {
    s.h = d.number("spacing");
    if (!(s.h > 0)) d.get("spacing").fail("spacing must be positive");
  }
  if (d.has("quadrature"))
    s.quadrature = read_word(d.get("quadrature"), every_value<Quadrature>(), [](const std::string&) {
      return "unknown quadrature (" + name_list<Quadrature>() + ")";
    });
  for (int c = 0; c < s.dim; ++c) s.lo[c] = s.hi[c] = f.x[static_cast<std::size_t>(c)];
  for (int i = 0; i < f.size(); ++i)
    for (int c = 0; c < s.dim; ++c) {
      const double x = f.x[static_cast<std::size_t>(i) * s.dim + c];
      s.lo[c] = std::min(s.lo[c], x), s.hi[c] = std::max(s.hi[c], x);
    }
  s.placement = Placement::node;
  d.finish();
  return f;
}

void attach_point_cloud(const YamlAt& domain, const ParticleFile& f, Scene& s) {
  std::vector<std::string> names;
  for (const MaterialSpec& m : s.materials) names.push_back(m.name);
  auto p = std::make_shared<Particles>();
  p->dim = s.dim;
  p->x = f.x;
  p->volume = f.volume;
  try {
    p->material = particle_materials(f, names);
  } catch (const SceneError& e) {
    domain.child(domain.node["particles"], "particles").fail(e.what());
  }
  s.point_cloud = std::move(p);
}

}  // namespace pd
