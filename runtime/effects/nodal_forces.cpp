// Dead loads: a nodal force vector, and the scene's tractions and constant body forces as one.
#include <fmt/core.h>

#include <cmath>

#include "discretize/discretization.hpp"
#include "effects/loads.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

namespace {
// Dead loads: a fixed nodal force vector scaled by the load factor.
class NodalForces final : public Effect {
 public:
  NodalForces(std::vector<double> f, std::string description)
      : f_(std::move(f)), description_(std::move(description)) {}
  std::string name() const override { return "external loads"; }
  bool is_load() const override { return true; }
  std::size_t allocated_bytes() const override { return f_.size() * sizeof(double); }
  std::string describe() const override {
    double total = 0;
    for (double v : f_) total += std::fabs(v);
    return fmt::format("external loads: {}, sum |f| = {:.6g}", description_, total);
  }
  void add_forces(const double*, double load, double* r) const override {
    for (std::size_t i = 0; i < f_.size(); ++i) r[i] += load * f_[i];
  }

 private:
  std::vector<double> f_;
  std::string description_;
};

// The measure (length in 2D, area in 3D) of the domain face a side region lies on.
double face_measure(const Scene& s, Region::Side side) {
  const int axis = (side == Region::Side::left || side == Region::Side::right)   ? 0
                   : (side == Region::Side::bottom || side == Region::Side::top) ? 1
                                                                                 : 2;
  double m = 1;
  for (int c = 0; c < s.dim; ++c)
    if (c != axis) m *= s.hi[c] - s.lo[c];
  return m;
}

}  // namespace

std::unique_ptr<Effect> make_nodal_forces(std::vector<double> f, std::string description) {
  return std::make_unique<NodalForces>(std::move(f), std::move(description));
}

std::unique_ptr<Effect> make_external_loads(const Scene& s, const Particles& p) {
  return make_external_loads(s, p, s.boundary);
}

std::unique_ptr<Effect> make_external_loads(const Scene& s, const Particles& p,
                                            std::span<const BoundaryCondition> conditions) {
  const int d = s.dim;
  std::vector<double> f(static_cast<std::size_t>(p.size()) * d, 0.0);
  int tractions = 0, body = 0;
  for (const BoundaryCondition& bc : conditions) {
    if (bc.kind != BoundaryCondition::Kind::Traction && bc.kind != BoundaryCondition::Kind::BodyForce)
      continue;
    if (bc.method == BoundaryCondition::Method::fictitious_layer) continue;  // carried by the layer's ties
    const auto ids = region_particles(bc.region, p, s);
    if (ids.empty()) throw SceneError(bc.where + ": the region holds no particle");
    if (bc.kind == BoundaryCondition::Kind::Traction) {
      ++tractions;
      const double measure = bc.face_measure > 0 ? bc.face_measure : face_measure(s, bc.region.side);
      for (int i : ids)
        for (int c = 0; c < d; ++c) f[i * d + c] += bc.values[c] * measure / static_cast<double>(ids.size());
    } else {
      ++body;
      for (int i : ids)
        for (int c = 0; c < d; ++c) f[i * d + c] += bc.values[c] * p.volume[i];
    }
  }
  if (tractions + body == 0) return nullptr;
  return make_nodal_forces(std::move(f),
                           fmt::format("{} traction and {} body-force conditions", tractions, body));
}

}  // namespace pd
