// Constraints from boundary conditions, and the cluster / rigid-mode check.
#include "constraints/constraints.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/fictitious_layer.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

namespace {
// Two conditions may constrain the same component of a particle only when they agree: the
// same value at full load, both velocities or both displacements, and the same time
// function. Anything else is a contradiction the solver would settle silently by order.
void check_agree(const Scene& scene, const Particles& particles, const PrescribedDof& first,
                 const PrescribedDof& second) {
  using K = BoundaryCondition::Kind;
  const BoundaryCondition& a = scene.boundary[static_cast<std::size_t>(first.condition)];
  const BoundaryCondition& b = scene.boundary[static_cast<std::size_t>(second.condition)];
  const auto what = [](const PrescribedDof& q) {
    return q.kind == K::Velocity ? "velocity" : q.kind == K::Fixed ? "fixed displacement" : "displacement";
  };
  const auto time = [](const BoundaryCondition& bc) { return bc.time ? bc.time->describe() : std::string(); };
  const bool same = first.value == second.value &&
                    (first.kind == K::Velocity) == (second.kind == K::Velocity) && time(a) == time(b);
  if (same) return;
  const int d = particles.dim, p = second.dof / d;
  const double* x = particles.position(p);
  const std::string at = d == 2 ? fmt::format("({:.6g}, {:.6g})", x[0], x[1])
                                : fmt::format("({:.6g}, {:.6g}, {:.6g})", x[0], x[1], x[2]);
  const std::string timing =
      time(a) == time(b) ? std::string()
                         : fmt::format(", in time {} against {}", time(b).empty() ? "constant" : time(b),
                                       time(a).empty() ? "constant" : time(a));
  throw SceneError(fmt::format(
      "{}: prescribes the {} {} {:.6g} on particle {} at {}, which {} already prescribes as the {} {:.6g}{}: "
      "two conditions may constrain the same component only with the same value",
      b.where, "xyz"[second.dof % d], what(second), second.value, p, at, a.where, what(first), first.value,
      timing));
}
}  // namespace

std::vector<PrescribedDof> prescribed_dofs(const Scene& scene, const Particles& particles) {
  using K = BoundaryCondition::Kind;
  const int d = particles.dim;
  std::vector<int> entry(static_cast<std::size_t>(particles.size()) * d, -1);
  std::vector<PrescribedDof> out;
  for (std::size_t ci = 0; ci < scene.boundary.size(); ++ci) {
    const BoundaryCondition& bc = scene.boundary[ci];
    if (bc.kind == K::Traction || bc.kind == K::BodyForce) continue;
    if (bc.method == BoundaryCondition::Method::fictitious_layer) continue;  // ties: scene_layer_ties
    const auto ids = region_particles(bc.region, particles, scene);
    if (ids.empty()) throw SceneError(bc.where + ": the region holds no particle");
    std::unique_ptr<AnalyticField> field;
    if (bc.kind == K::Field) field = std::make_unique<AnalyticField>(bc.field, scene.materials[0].elastic);
    for (int p : ids)
      for (int c = 0; c < d; ++c) {
        if (!bc.components[c]) continue;
        const int dof = p * d + c;
        const double value = bc.kind == K::Fixed ? 0.0
                             : field             ? field->displacement(particles.position(p))[c]
                                                 : bc.values[c];
        const PrescribedDof q{dof, bc.kind, value, static_cast<int>(ci)};
        if (entry[dof] < 0) {
          entry[dof] = static_cast<int>(out.size()), out.push_back(q);
        } else {
          check_agree(scene, particles, out[entry[dof]], q);
          out[entry[dof]] = q;
        }
      }
  }
  return out;
}

namespace {
// Each constrained dof's kind and time function (DofMap::set_motion), from the condition
// that sets it: its `time`, copied once per condition that has one.
PrescribedMotion prescribed_motion(const Scene& scene, const std::vector<int>& constrained,
                                   const std::vector<int>& condition,
                                   const std::vector<BoundaryCondition::Kind>& kind) {
  using K = BoundaryCondition::Kind;
  PrescribedMotion m;
  std::vector<int> function_of(scene.boundary.size(), -1);
  for (std::size_t ci = 0; ci < scene.boundary.size(); ++ci)
    if (scene.boundary[ci].time)
      function_of[ci] = static_cast<int>(m.functions.size()), m.functions.push_back(*scene.boundary[ci].time);
  for (int dof : constrained) {
    const K k = kind[static_cast<std::size_t>(dof)];
    m.kind.push_back(k == K::Velocity ? PrescribedMotion::Kind::velocity
                     : k == K::Fixed  ? PrescribedMotion::Kind::fixed
                                      : PrescribedMotion::Kind::displacement);
    m.function.push_back(function_of[static_cast<std::size_t>(condition[static_cast<std::size_t>(dof)])]);
  }
  return m;
}
}  // namespace

DofMap scene_constraints(const Scene& scene, const Particles& particles) {
  using K = BoundaryCondition::Kind;
  const int d = particles.dim;
  const std::size_t n = static_cast<std::size_t>(particles.size()) * d;
  std::vector<double> value(n, 0.0);
  std::vector<char> fixed(n, 0);
  // The field condition that set each dof, when its values are not proportional to the
  // load (a rotation: DofMap::set_load_path).
  std::vector<std::shared_ptr<const AnalyticField>> rotation(scene.boundary.size());
  for (std::size_t ci = 0; ci < scene.boundary.size(); ++ci) {
    const BoundaryCondition& bc = scene.boundary[ci];
    if (bc.kind != K::Field) continue;
    auto field = std::make_shared<const AnalyticField>(bc.field, scene.materials[0].elastic);
    if (field->name() == "rotation") rotation[ci] = std::move(field);
  }
  std::vector<std::shared_ptr<const AnalyticField>> path(n);
  std::vector<int> condition(n, -1);
  std::vector<K> kind(n, K::Fixed);
  for (const PrescribedDof& q : prescribed_dofs(scene, particles)) {
    fixed[q.dof] = 1;
    value[q.dof] = q.value;
    path[q.dof] = rotation[q.condition];
    condition[q.dof] = q.condition, kind[q.dof] = q.kind;
  }
  DofMap dofs(fixed, value);
  dofs.set_motion(prescribed_motion(scene, dofs.constrained_dofs(), condition, kind));
  if (std::any_of(path.begin(), path.end(), [](const auto& f) { return f != nullptr; })) {
    // The positions, copied: the map must not point into a particle array (the model
    // that owns both may move).
    dofs.set_load_path([d, x = particles.x, path = std::move(path), constrained = dofs.constrained_dofs(),
                        values = dofs.prescribed()](double load, int i) {
      const int dof = constrained[static_cast<std::size_t>(i)];
      const auto& f = path[static_cast<std::size_t>(dof)];
      return f ? f->displacement_at_load(&x[static_cast<std::size_t>(dof / d) * d], load)[dof % d]
               : load * values[static_cast<std::size_t>(i)];
    });
  }
  std::vector<TiedDof> ties = scene_layer_ties(scene, particles);
  if (!ties.empty()) dofs.tie(std::move(ties));
  return dofs;
}

namespace {
// Rigid-body modes that the constrained dofs `dofs` of one cluster leave free, as a
// message ("" when held).
std::string missing_constraints(const Particles& p, const std::vector<int>& dofs) {
  const int d = p.dim;
  // For each component, the positions (along the next axis) of the particles holding it.
  std::vector<std::vector<double>> coords(static_cast<std::size_t>(d));
  for (int dof : dofs) coords[dof % d].push_back(p.x[(dof / d) * d + (dof % d + 1) % d]);
  std::string missing;
  const char* axes = "xyz";
  for (int c = 0; c < d; ++c)
    if (coords[c].empty())
      missing += fmt::format("no particle has its {} displacement prescribed (rigid translation in {}); ",
                             axes[c], axes[c]);
  auto spread = [](const std::vector<double>& v) {
    if (v.empty()) return 0.0;
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return *hi - *lo;
  };
  if (d == 2 && missing.empty() && spread(coords[0]) == 0.0 && spread(coords[1]) == 0.0) {
    // x fixed along one horizontal line and y along one vertical line: rotation about
    // their crossing point is free unless the two constraints sit at different points.
    bool blocked = false;
    for (int dof : dofs)
      for (int other : dofs)
        if (dof % 2 == 0 && other % 2 == 0 && p.x[(dof / 2) * 2 + 1] != p.x[(other / 2) * 2 + 1])
          blocked = true;
    if (!blocked && coords[0].size() + coords[1].size() < 3)
      missing += "the constraints leave the rigid rotation free; ";
  }
  return missing;
}
}  // namespace

namespace {
// Empty when every cluster is held; otherwise what leaves the first free one free.
std::string unheld_message(const Particles& particles, const Bonds& bonds, const DofMap& dofs) {
  // Clusters of particles joined by intact bonds (union-find): each needs its own
  // constraints, or it floats (a particle whose every bond is broken is a cluster of one).
  const int n = particles.size(), d = particles.dim;
  std::vector<int> parent(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) parent[p] = p;
  auto root = [&](int p) {
    while (parent[p] != p) p = parent[p] = parent[parent[p]];
    return p;
  };
  for (int p = 0; p < n; ++p)
    for (int e = bonds.offsets[p]; e < bonds.offsets[p + 1]; ++e)
      if (bonds.alpha[e] != 0.0) parent[root(p)] = root(bonds.neighbor[e]);
  std::map<int, std::vector<int>> clusters, cluster_dofs;
  for (int p = 0; p < n; ++p) clusters[root(p)].push_back(p);
  for (int dof : dofs.constrained_dofs()) cluster_dofs[root(dof / d)].push_back(dof);
  // A tied dof holds its component when it does not follow a rigid translation of its
  // masters (a fictitious layer's odd mirror u_f = 2U* - u: coefficients summing to -1).
  for (const TiedDof& t : dofs.ties()) {
    double same = 0;
    for (std::size_t k = 0; k < t.masters.size(); ++k)
      if (t.masters[k] % d == t.dof % d) same += t.coefficients[k];
    if (std::abs(same - 1.0) > 1e-12) cluster_dofs[root(t.dof / d)].push_back(t.dof);
  }
  for (const auto& [r, members] : clusters) {
    const std::string missing = missing_constraints(particles, cluster_dofs[r]);
    if (missing.empty()) continue;
    std::string list;
    for (std::size_t i = 0; i < std::min<std::size_t>(members.size(), 8); ++i)
      list += (i ? ", " : "") + std::to_string(members[i]);
    const double* x = particles.position(members[0]);
    const std::string what = clusters.size() == 1
                                 ? std::string("the body is under-constrained: ")
                                 : fmt::format(
                                       "a cluster of {} particle(s) joined by intact bonds (particles {}{}; "
                                       "the first at ({:.6g}, {:.6g})) "
                                       "is disconnected from the rest of the body and under-constrained: ",
                                       members.size(), list, members.size() > 8 ? ", ..." : "", x[0], x[1]);
    return what + missing.substr(0, missing.size() - 2);
  }
  return {};
}
}  // namespace

void check_held(const Particles& particles, const Bonds& bonds, const DofMap& dofs) {
  if (const std::string m = unheld_message(particles, bonds, dofs); !m.empty()) throw std::runtime_error(m);
}

void check_scene_holds_body(const Scene& scene, const Particles& particles, const Bonds& bonds,
                            const DofMap& dofs) {
  const std::string m = unheld_message(particles, bonds, dofs);
  if (m.empty()) return;
  // Without constraints even a load-free body has no unique static solution (any rigid
  // motion is one): refuse rather than report u = 0.
  if (scene.boundary.empty())
    throw SceneError(
        scene.file + ": boundary: the scene has no boundary section, so nothing holds the body (" + m +
        "); a static solve needs fixed or prescribed displacements that remove its rigid motions "
        "(a body in free flight needs a dynamics section)");
  throw SceneError(scene.file + ": boundary: " + m);
}

}  // namespace pd
