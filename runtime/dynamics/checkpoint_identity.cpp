// The identity of a dynamic run, for its checkpoints.
#include "dynamics/checkpoint_identity.hpp"

#include <fmt/format.h>

namespace pd {

namespace {
template <class T>
std::string hash_of(const std::vector<T>& v, std::uint64_t h = 0xcbf29ce484222325ull) {
  return fmt::format("{:016x}", fnv1a(v.data(), v.size() * sizeof(T), h));
}
const char* plane_name(PlaneAssumption p) {
  switch (p) {
    case PlaneAssumption::Strain:
      return "strain";
    case PlaneAssumption::Stress:
      return "stress";
    case PlaneAssumption::None:
      return "none";
  }
  return "?";
}
}  // namespace

std::string pd_build_identity() {
#ifdef PD_VERSION
  const std::string version = PD_VERSION;
#else
  const std::string version = "(unversioned build)";
#endif
#ifdef __VERSION__
  return "pd " + version + ", compiler " + __VERSION__;
#else
  return "pd " + version;
#endif
}

CheckpointIdentity checkpoint_identity(const Scene& scene, const Particles& particles, const Bonds& bonds,
                                       double dt) {
  CheckpointIdentity id;
  id["binary"] = pd_build_identity();
  id["method"] = scene.dynamics ? std::string(name_of(scene.dynamics->method)) : std::string("static");
  id["law"] = scene.law;
  id["influence"] = scene.influence;
  id["dimension"] = std::to_string(scene.dim);
  id["horizon"] = fmt::format("{:.17g}", scene.delta());
  id["particles"] = fmt::format("{} (positions, volumes, materials: hash {}{}{})", particles.size(),
                                hash_of(particles.x), hash_of(particles.volume), hash_of(particles.material));
  // The quadrature sets each bond's volume (the bonds' hash above does not see the factors).
  id["quadrature"] =
      std::string(name_of(scene.quadrature)) + (scene.compensation ? ", compensation" : "") +
      (scene.surface_correction
           ? fmt::format(", surface correction ({})", surface_match_name(scene.surface_match))
           : std::string()) +
      (scene.gauss_points > 0 ? fmt::format(", gauss points {} per axis, MLS support {:.17g} h",
                                            scene.gauss_points, scene.gauss_support)
                              : std::string());
  id["bonds"] = fmt::format("{} (hash {})", bonds.neighbor.size(), hash_of(bonds.neighbor));
  for (std::size_t k = 0; k < scene.materials.size(); ++k) {
    const MaterialSpec& m = scene.materials[k];
    std::string text = fmt::format("{}: E {:.17g}, nu {:.17g}, density {:.17g}, plane {}", m.name,
                                   m.elastic.E, m.elastic.nu, m.density, plane_name(m.plane));
    for (const auto& [name, value] : m.parameters) text += fmt::format(", {} {:.17g}", name, value);
    id[fmt::format("material[{}]", k)] = text;
  }
  id["damage"] = !scene.damage
                     ? std::string("none")
                     : fmt::format("critical_stretch {:.17g}, fracture_energy {:.17g}, tension_only {}",
                                   scene.damage->critical_stretch, scene.damage->fracture_energy,
                                   scene.damage->tension_only);
  if (dt > 0) id["time_step"] = fmt::format("{:.17g}", dt);
  return id;
}

void check_checkpoint_belongs(const std::string& path, const Checkpoint& c,
                              const CheckpointIdentity& expected, long long last_step) {
  std::string differences;
  for (const auto& [key, value] : expected) {
    const auto it = c.identity.find(key);
    const std::string theirs = it == c.identity.end() ? "(none)" : it->second;
    if (theirs != value) differences += fmt::format("\n  {}: checkpoint {}, this run {}", key, theirs, value);
  }
  for (const auto& [key, value] : c.identity)
    if (!expected.count(key))
      differences += fmt::format("\n  {}: checkpoint {}, this run (none)", key, value);
  if (!differences.empty())
    throw CheckpointError(
        fmt::format("{}: the checkpoint belongs to another run (a restart continues only the run that "
                    "wrote it):{}",
                    path, differences));
  if (c.step < 0 || c.step > last_step)
    throw CheckpointError(
        fmt::format("{}: the checkpoint is at step {}, past this scene's last step {} (dynamics.steps)", path,
                    c.step, last_step));
}

}  // namespace pd
