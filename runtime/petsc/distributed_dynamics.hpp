// Explicit dynamics over MPI ranks (`solver.backend: petsc` with `dynamics.method:
// explicit`), as the serial runtime sees it: no PETSc type here, so the dispatch in
// `pd run` compiles with or without PETSc (without it, solve/without_petsc.cpp refuses).
#pragma once

namespace pd {

struct DynamicRun;
struct RunSummary;

// Runs `run` (prepared on every rank from the same scene by prepare_dynamic_run, so its
// set-up -- model, inertia, stable time step -- is the serial one bit for bit) with each rank stepping only its
// own particles: one ghost update of u per step, the forces of its own families summed
// into their owners, bonds broken on its own families. Rank 0 gathers the state when a
// series row, snapshot or checkpoint is due and writes the serial run's files (when
// `write`); checkpoints are the serial format, restartable with any rank count.
// Refuses dynamic relaxation (std::runtime_error): its damping needs global sums the
// serial AdaptiveDynamicRelaxation does not take.
RunSummary run_distributed_dynamics(DynamicRun& run, bool write, int stop_after = 0);

}  // namespace pd
