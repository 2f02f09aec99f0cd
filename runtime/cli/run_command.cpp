// `pd run SCENE.yaml [--out DIR]`: solve a scene and write its results.
#include <fmt/core.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/memory_check.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "model/model.hpp"
#include "output/output_directory.hpp"
#include "output/staging.hpp"
#include "run/dynamic_run.hpp"
#include "run/static_run.hpp"
#include "solve/distributed_backend.hpp"
#include "version.hpp"

namespace pd::cli {

namespace {
// The first SIGINT/SIGTERM only records the signal: the solve stops at the next Newton
// (or Krylov, or time) step and no result file is written, not even a temporary. A
// second signal stops at once, removing the temporary file being written, if any.
extern "C" void on_interrupt(int sig) {
  if (interrupt_signal() == 0) {
    request_interrupt(sig);
    const char msg[] = "\npd run: stopping at the next step (signal again to stop at once)\n";
    [[maybe_unused]] auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
    return;
  }
  remove_pending_temporary();
  const char msg[] = "\npd run: stopped at once (the temporary file being written, if any, was removed)\n";
  [[maybe_unused]] auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
  _exit(128 + sig);
}

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write(2) in progress completes; the flag is polled after it
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}
}  // namespace

namespace {
const char* kRunDetails =
    "Solves the scene and writes DIR/result.vtu (ParaView), DIR/result.csv and DIR/summary.json;\n"
    "a scene with a dynamics section runs explicit dynamics or dynamic relaxation and also writes\n"
    "DIR/energies.csv, DIR/animation.pvd (snapshots) and DIR/checkpoint.bin as the scene asks;\n"
    "--restart resumes such a run from a checkpoint. The scene format: docs/scene_format.md.\n"
    "Exit codes: 0 solved, 1 solve failed, 2 bad usage or bad input (the message names file, line\n"
    "and key), 130 / 143 interrupted by SIGINT / SIGTERM (no result file is written).\n";

struct RunOptions {
  std::string scene_path, out_dir, restart, petsc_options;
};

// Why this run cannot go on the backend its scene names, if it cannot: several MPI
// processes on the serial backend would each write the same files.
std::optional<std::string> backend_refusal(const Scene& scene, const RunOptions& options) {
  const int processes = launched_process_count();
  if (scene.solver.backend != Backend::petsc) {
    if (processes > 1)
      return fmt::format(
          "started on {} MPI processes, but solver.backend is serial: add 'backend: petsc' to the "
          "solver section (docs/scene_format.md), or run without mpirun",
          processes);
    if (!options.petsc_options.empty()) return std::string("--petsc-options needs solver.backend: petsc");
    return std::nullopt;
  }
  if (!distributed_backend_available())
    return std::string(
        "solver.backend: petsc, but this pd was built without PETSc (install petsc-dev with "
        "scripts/install_deps.sh and configure again)");
  return std::nullopt;
}

// Reads the scene and applies the command line to it; 0, or the exit code of a refusal
// (printed): bad input, too little memory, a backend this run cannot use.
int read_run_scene(const RunOptions& options, Scene& scene) {
  try {
    scene = read_scene(options.scene_path);
  } catch (const SceneError& e) {
    fmt::print(stderr, "pd run: {}\n", e.what());
    return 2;
  }
  if (const auto refusal = memory_refusal(scene, available_memory())) {  // before any allocation
    fmt::print(stderr, "pd run: {}\n", *refusal);
    return 2;
  }
  if (!options.out_dir.empty()) scene.output.directory = options.out_dir;
  if (!options.restart.empty()) {
    if (!scene.dynamics) {
      fmt::print(stderr, "pd run: --restart needs a scene with a dynamics section\n");
      return 2;
    }
    scene.dynamics->restart = options.restart;
  }
  if (const auto refusal = backend_refusal(scene, options)) {
    fmt::print(stderr, "pd run: {}: {}\n", options.scene_path, *refusal);
    return 2;
  }
  return 0;
}

// Build the model (planned by its driver), run, write (rank 0 writes a static run's files).
RunSummary solve_scene(const Scene& scene, int rank, const RunLog& log) {
  if (scene.dynamics) {
    Model model = build_dynamic_model(scene);
    DynamicRun run = prepare_dynamic_run(model, scene, log);
    return run_dynamic(run, true);  // serially or over the ranks, as the solver plan says
  }
  StaticRun run;
  Model model = build_static_model(scene, run);
  describe_static_run(run, model, scene, log);
  run_static(run, model, scene, log);
  if (rank == 0) write_static_outputs(run, model, scene);
  return run.summary;
}

void log_leftovers(const StagingDirectory& staging, const std::string& directory, const RunLog& log) {
  for (const std::string& old : staging.leftovers())
    log(
        fmt::format("  warning: {}: the files of an earlier run into {} that did not finish (killed?): "
                    "its checkpoint, "
                    "if any, can resume it with --restart; remove the directory when it is not needed",
                    old, directory));
}

// The timings and the result files, named in the published directory.
void print_results(RunSummary& s, const StagingDirectory* staging, const std::string& directory) {
  for (auto& f : s.files)
    if (staging && f.rfind(staging->path() + "/", 0) == 0) f = directory + f.substr(staging->path().size());
  fmt::print("done in {:.3f} s (setup {:.3f}, solve {:.3f}, output {:.3f}); results:\n",
             s.setup_seconds + s.solve_seconds + s.output_seconds, s.setup_seconds, s.solve_seconds,
             s.output_seconds);
  for (const auto& f : s.files) fmt::print("  {}\n", f);
}

int run_scene(const RunOptions& options) {
  const std::string& scene_path = options.scene_path;
  install_interrupt_handlers();
  Scene scene;
  if (const int refused = read_run_scene(options, scene)) return refused;
  RunSummary s;
  const bool dynamic = scene.dynamics.has_value();
  const std::string directory = scene.output.directory;
  int rank = 0;
  // Rank 0 writes into a staging directory and publishes it when the run ends (done, failed
  // or stopped by a signal; not on bad input): kill -9 leaves the older result whole.
  std::optional<OutputDirectoryClaim> claim;
  std::optional<StagingDirectory> staging;
  const auto publish = [&] {
    if (staging) staging->publish();
  };
  try {
    // Every rank solves; rank 0 alone claims the directory, logs and writes the files.
    std::optional<DistributedSession> session;
    if (scene.solver.backend == Backend::petsc)
      session.emplace(std::vector<std::string>{scene.solver.petsc_options, options.petsc_options});
    rank = session ? session->rank() : 0;
    if (rank == 0) {
      claim.emplace(directory);  // writable and ours, before any solve
      staging.emplace(directory);
      scene.output.directory = staging->path();
    }
    const RunLog log = [rank](const std::string& line) {
      if (rank != 0) return;
      fmt::print("{}\n", line);
      std::fflush(stdout);
    };
    log(version_line());
    if (staging) log_leftovers(*staging, directory, log);
    if (session) log(fmt::format("PETSc backend on {} MPI process(es)", session->size()));
    s = solve_scene(scene, rank, log);
  } catch (const SceneError& e) {  // problems found after reading, e.g. an empty region
    // Those found while setting up the body (a horizon beyond the body, overflowing
    // moduli) know no file: name it, so every bad-input message starts with it.
    const std::string message = e.what();
    fmt::print(stderr, "pd run: {}{}\n", message.rfind(scene_path, 0) == 0 ? "" : scene_path + ": ", message);
    return 2;
  } catch (const Interrupted& e) {
    // Dynamic runs write snapshots and checkpoints as they go; those are complete files.
    publish();
    fmt::print(stderr, "pd run: {}; {}\n", e.what(),
               dynamic
                   ? "no result files were written (snapshots and checkpoints already written are complete)"
                   : "no result files were written");
    return 128 + e.signal();
  } catch (const std::exception&) {
    // A failed dynamic run's snapshots show how it failed: published like a finished run's
    // (without summary.json, so the directory says the run did not finish).
    publish();
    throw;
  }
  if (rank != 0) return 0;
  publish();
  print_results(s, staging ? &*staging : nullptr, directory);
  return 0;
}
}  // namespace

Command add_run_command(CLI::App& pd) {
  CLI::App* cmd = pd.add_subcommand("run", "solve a scene and write its results");
  cmd->footer(kRunDetails);
  auto options = std::make_shared<RunOptions>();
  cmd->add_option("SCENE", options->scene_path, "the scene file (YAML)")->required();
  cmd->add_option("--out", options->out_dir,
                  "the output directory DIR (default: the scene's output.directory)")
      ->check(kNonEmptyPath);
  cmd->add_option("--restart", options->restart, "resume a dynamic run from this checkpoint file")
      ->check(kNonEmptyPath);
  cmd->add_option(
      "--petsc-options", options->petsc_options,
      "PETSc options for solver.backend: petsc, after the scene's (--petsc-options='-ksp_monitor')");
  return [options] { return run_scene(*options); };
}

}  // namespace pd::cli
