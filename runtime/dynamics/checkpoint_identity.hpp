// What a checkpoint belongs to: the inputs that determine a dynamic run's state (law,
// influence, horizon, particle geometry, bonds, quadrature (with compensation and Gauss points), materials,
// damage rule, method, time step) and the binary that wrote it. A restart from a checkpoint of another run
// would continue a state this scene never produced (a law changed on the same grid ran with a 6.7 % different
// result and no word), so it is refused instead.
#pragma once

#include <map>
#include <string>

#include "dynamics/checkpoint.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

using CheckpointIdentity = std::map<std::string, std::string>;

// dt: the explicit time step in use (0 for relaxation, whose iteration is not a time).
// Boundary conditions and loads are not part of it: they act on the state, they do not
// define it (and every restart test resumes under the same loads).
CheckpointIdentity checkpoint_identity(const Scene& scene, const Particles& particles, const Bonds& bonds,
                                       double dt);

// The binary's identity: PD_VERSION when the build defines it, and the compiler.
std::string pd_build_identity();

// Throws CheckpointError naming the file and every entry that differs (the checkpoint's
// value and this run's), or the step when it lies past the scene's last step.
void check_checkpoint_belongs(const std::string& path, const Checkpoint& c,
                              const CheckpointIdentity& expected, long long last_step);

}  // namespace pd
