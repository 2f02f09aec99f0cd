// SIGINT/SIGTERM during `pd run`: the run stops between Newton iterations with a clear
// message and exit status 128 + signal, and leaves no file in the output directory,
// not even a temporary; a signal recorded before the outputs are written drops them.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "input/scene.hpp"
#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "run/simulation.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;

namespace {
// A nonlinear stretch in very many load steps: far longer than the test waits, and a
// Newton iteration every few milliseconds, so the flag is polled often.
const char* kLongScene = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [1, 1]}
  count: 30
law: silling_plane_strain
influence: cubic
materials: [{E: 1, nu: 0.25}]
boundary:
  - region: {side: bottom}
    fixed: [x, y]
  - region: {side: top}
    displacement: {x: 0, y: 0.3}
solver: {load_steps: 1000000}
)";

using pd::test::fresh_directory;
using pd::test::read_text;

struct Outcome {
  int status = -1;  // exit status, or -1 when the process did not exit normally in time
  std::string stderr_text;
};

// Runs `pd run scene --out out`, waits for its first Newton iteration line on stdout,
// sends `sig`, and waits (at most 60 s) for it to exit.
Outcome interrupt_pd(const fs::path& scene, const fs::path& out, const fs::path& err, int sig) {
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(pipe_fd[1], STDOUT_FILENO);
    close(pipe_fd[0]);
    if (freopen(err.c_str(), "w", stderr) == nullptr) _exit(99);
    execl(PD_EXE, "pd", "run", scene.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(98);
  }
  close(pipe_fd[1]);
  std::string seen;
  char buf[4096];
  while (seen.find("iteration") == std::string::npos) {
    const ssize_t n = read(pipe_fd[0], buf, sizeof buf);
    if (n <= 0) break;
    seen.append(buf, static_cast<std::size_t>(n));
  }
  const bool started = seen.find("iteration") != std::string::npos;
  if (started) kill(pid, sig);
  // Keep draining stdout so the child never blocks on a full pipe.
  std::thread drain([fd = pipe_fd[0]] {
    char b[4096];
    while (read(fd, b, sizeof b) > 0) {
    }
  });
  Outcome o;
  int status = 0;
  const auto t0 = std::chrono::steady_clock::now();
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(60)) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      drain.join();
      close(pipe_fd[0]);
      return o;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  drain.join();
  close(pipe_fd[0]);
  if (started && WIFEXITED(status)) o.status = WEXITSTATUS(status);
  o.stderr_text = read_text(err);
  return o;
}
}  // namespace

TEST(Interrupt, SignalDuringTheSolveStopsCleanlyWithoutFiles) {
  const fs::path dir = fresh_directory("pd_interrupt");
  const fs::path scene = dir / "long.yaml", out = dir / "out";
  std::ofstream(scene) << kLongScene;
  for (const auto& [sig, status, name] :
       {std::tuple{SIGINT, 130, "SIGINT"}, std::tuple{SIGTERM, 143, "SIGTERM"}}) {
    const Outcome o = interrupt_pd(scene, out, dir / "stderr.txt", sig);
    EXPECT_EQ(o.status, status) << name << "\n" << o.stderr_text;
    EXPECT_NE(o.stderr_text.find(std::string("interrupted by ") + name + " during the solve (load step"),
              std::string::npos)
        << o.stderr_text;
    EXPECT_NE(o.stderr_text.find("no result files were written"), std::string::npos) << o.stderr_text;
    if (fs::exists(out))
      for (const auto& entry : fs::directory_iterator(out)) ADD_FAILURE() << name << " left " << entry.path();
  }
  fs::remove_all(dir);
}

TEST(Interrupt, SignalBeforeTheOutputsDropsThemAndTheirTemporaries) {
  const fs::path dir = fresh_directory("pd_interrupt_write");
  pd::request_interrupt(SIGTERM);
  EXPECT_THROW(pd::write_file_atomically((dir / "a.txt").string(), "x"), pd::Interrupted);
  pd::clear_interrupt();
  EXPECT_TRUE(fs::is_empty(dir));

  // A solve that sees the flag throws Interrupted (not a Newton failure) and writes nothing.
  pd::Scene s = pd::parse_scene(kLongScene, "long.yaml");
  s.solver.load_steps = 2;
  s.output.directory = (dir / "out").string();
  pd::Simulation sim(s, [](const std::string&) {});
  pd::request_interrupt(SIGINT);
  try {
    sim.run(true);
    ADD_FAILURE() << "the run was not interrupted";
  } catch (const pd::Interrupted& e) {
    EXPECT_EQ(e.signal(), SIGINT);
    EXPECT_NE(std::string(e.what()).find(
                  "interrupted by SIGINT during the solve (load step 1/2, Newton iteration 0)"),
              std::string::npos)
        << e.what();
  }
  pd::clear_interrupt();
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}
