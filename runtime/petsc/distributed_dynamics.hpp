// Dynamic runs over MPI ranks (`solver.backend: petsc` with a `dynamics` section), as the
// serial runtime sees them: no PETSc type here, so the dispatch in `pd run` compiles with
// or without PETSc (without it, solve/without_petsc.cpp refuses).
#pragma once

namespace pd {

struct DynamicRun;
struct RunSummary;

// Runs `run` (prepared on every rank from the same scene by prepare_dynamic_run, so its
// set-up -- model, inertia or fictitious density, stable time step -- is the serial one
// bit for bit) with each rank stepping only its own particles: one ghost update of u per
// step, the forces of its own families summed into their owners, bonds broken on its own
// families. Rank 0 gathers the state when a series row, snapshot or checkpoint is due and
// writes the serial run's files (when `write`); checkpoints are the serial format,
// restartable with any rank count. Explicit dynamics: run_distributed_explicit
// (distributed_explicit.cpp); adaptive dynamic relaxation: run_distributed_relaxation
// (distributed_relaxation.cpp).
RunSummary run_distributed_dynamics(DynamicRun& run, bool write, int stop_after = 0);
RunSummary run_distributed_explicit(DynamicRun& run, bool write, int stop_after);
RunSummary run_distributed_relaxation(DynamicRun& run, bool write, int stop_after);

}  // namespace pd
