// The steps a dynamic driver takes on the process that runs it, behind one interface, so
// that explicit dynamics and dynamic relaxation are each one loop (run/explicit_run.cpp,
// run/relaxation_run.cpp) for every backend. SerialSteps (serial_steps.hpp) holds the whole
// body; the PETSc one (petsc/rank_steps.hpp) holds one rank's particles plus ghosts and sums
// over the ranks. Which one a run gets is the solver plan's choice (solver.backend), made
// by the driver (run/dynamic_run.cpp, DynamicRun::make_steps), not the command line's.
//
// State vectors are full length (model order) on every process. A process keeps the
// entries of the dofs it owns current; after sync() it also holds its ghosts'; after
// gather() process 0 (root) holds every entry, as the serial run does, for output.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace pd {

class StepExecutor {
 public:
  virtual ~StepExecutor() = default;
  // Process 0: the one that logs, records the series and writes files.
  virtual bool root() const = 0;
  // The free dofs this process steps (all free dofs serially; the owned ones on a rank).
  virtual const std::vector<int>& free_dofs() const = 0;
  // One line for the run log and summary.json naming how the run is spread over processes,
  // e.g. "distributed: velocity Verlet over 2 MPI ranks ..."; empty serially.
  virtual std::string describe(const std::string& method, const std::string& per_update,
                               const std::string& global_sums) const = 0;
  // f = f_int(u) + loads(t), g = the loads on free dofs and -f_int on constrained ones (the
  // work of the reactions), at the dofs this process owns (zero elsewhere on a rank).
  virtual void forces(double t, std::vector<double>& f, std::vector<double>& g) = 0;
  // Every effect's after_step at the current u, on the families this process owns; true
  // when an effect changed the model on this process (no communication: the dynamic loops
  // go on either way, and a rank's later gather brings the owners' changes to rank 0).
  virtual bool after_step() = 0;
  // A law with memory: commits the history at the current u (Model::commit_history), every
  // time step of explicit dynamics, where each step stands. Nothing for an elastic law.
  virtual void commit_history() = 0;
  // Brings u at the ghosts up to date after this process moved its own dofs.
  virtual void sync() = 0;
  // Root's u, v and bond factors become the whole body's (before a series row, snapshot,
  // checkpoint or the end). `extra`: further dof vectors to gather likewise (ADR's state).
  virtual void gather(const std::vector<std::vector<double>*>& extra = {}) = 0;
  // The sum over the processes (identity serially).
  virtual double sum(double local) const = 0;
  // In place, over the processes, of `count` values (ADR's damping sums; nothing serially).
  virtual void sum_in_place(double* values, int count) const = 0;
  // The sum over the processes of the squares of `values` at their free dofs.
  virtual double free_square_sum(const std::vector<double>& values) const = 0;
  // Throws logic_error when a value the set-up computed on every process differs between them.
  virtual void check_agrees(double value, const std::string& what) const = 0;
  // Throws Interrupted on every process when any received a signal (all stop at one step).
  virtual void check_interrupt(const std::string& where) const = 0;
  // Throws runtime_error(message) on every process when u is not finite at a dof of any.
  virtual void check_finite(const std::string& message) const = 0;
};

// What an executor steps: the model (its assembler, effects, dofs), the run's state u and v
// (v empty for relaxation), and the scene file for error messages. All must outlive it.
struct StepState {
  Model& model;
  std::vector<double>& u;
  std::vector<double>& v;
  const std::string& scene_file;
};

}  // namespace pd
