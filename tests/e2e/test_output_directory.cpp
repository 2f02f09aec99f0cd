// The output directory is claimed before the solve: a read-only directory, a file given
// as --out, a disk that refuses writes and a directory another run holds each stop
// `pd run` at once with exit 2 and a message naming the directory (before, the first
// three were found only after the whole solve, and two runs raced on fixed .tmp names).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "output/output_directory.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;

namespace {
// A static stretch: `count` particles along x, `load_steps` Newton load steps. Small
// (12, 1) solves in a moment; (30, 10^6) runs far longer than a test waits.
std::string stretch_scene(int count, double top, int load_steps) {
  return "dimension: 2\n"
         "domain: {box: {min: [0, 0], max: [1, 1]}, count: " +
         std::to_string(count) +
         "}\n"
         "law: silling_plane_strain\ninfluence: cubic\nmaterials: [{E: 1, nu: 0.25}]\n"
         "boundary:\n  - {region: {side: bottom}, fixed: [x, y]}\n"
         "  - {region: {side: top}, displacement: {x: 0, y: " +
         std::to_string(top) +
         "}}\n"
         "solver: {load_steps: " +
         std::to_string(load_steps) + "}\n";
}
const std::string kScene = stretch_scene(12, 0.01, 1), kLongScene = stretch_scene(30, 0.3, 1000000);

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = pd::test::fresh_directory(name);
  fs::permissions(dir, fs::perms::all);  // traversable by the unprivileged child below
  return dir;
}
using pd::test::read_text;

struct Child {
  bool unprivileged = false;  // as root: run pd as nobody, so permissions apply
  long file_size_limit = -1;  // RLIMIT_FSIZE in bytes: writes past it fail (EFBIG), as on a full disk
};
struct Outcome {
  int status = -1;
  std::string out, err;
};

pid_t start_pd(const fs::path& scene, const fs::path& out, const fs::path& dir, const Child& c) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (freopen((dir / "stdout.txt").c_str(), "w", stdout) == nullptr ||
        freopen((dir / "stderr.txt").c_str(), "w", stderr) == nullptr)
      _exit(99);
    if (c.file_size_limit >= 0) {
      std::signal(SIGXFSZ, SIG_IGN);  // the write then fails with EFBIG instead of killing pd
      const rlimit r{static_cast<rlim_t>(c.file_size_limit), static_cast<rlim_t>(c.file_size_limit)};
      setrlimit(RLIMIT_FSIZE, &r);
    }
    if (c.unprivileged && geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(97);
    execl(PD_EXE, "pd", "run", scene.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(98);
  }
  return pid;
}
Outcome wait_pd(pid_t pid, const fs::path& dir) {
  Outcome o;
  int status = 0;
  const auto t0 = std::chrono::steady_clock::now();
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(60)) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return o;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (WIFEXITED(status)) o.status = WEXITSTATUS(status);
  o.out = read_text(dir / "stdout.txt");
  o.err = read_text(dir / "stderr.txt");
  return o;
}
Outcome run_pd(const std::string& scene_text, const fs::path& out, const fs::path& dir, const Child& c = {}) {
  const fs::path scene = dir / "scene.yaml";
  std::ofstream(scene) << scene_text;
  fs::permissions(scene, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  return wait_pd(start_pd(scene, out, dir, c), dir);
}
// Nothing was solved: pd stopped before it built the body (the first log line).
bool stopped_before_the_solve(const Outcome& o) { return o.out.find("particles") == std::string::npos; }
}  // namespace

TEST(OutputDirectory, AWritableDirectoryRunsAndKeepsNoLockOrProbe) {
  const fs::path dir = fresh_directory("pd_outdir_ok"), out = dir / "out";
  const Outcome o = run_pd(kScene, out, dir);
  ASSERT_EQ(o.status, 0) << o.err;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    // .pd.files: the list of the run's files, read by the next run into the directory (output/staging.hpp)
    EXPECT_TRUE(name == "result.vtu" || name == "result.csv" || name == "summary.json" || name == ".pd.files")
        << "left " << name;
  }
  fs::remove_all(dir);
}

TEST(OutputDirectory, AReadOnlyDirectoryStopsTheRunBeforeTheSolve) {
  const fs::path dir = fresh_directory("pd_outdir_ro"), out = dir / "out";
  fs::create_directories(out);
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                           fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  const Outcome o = run_pd(kScene, out, dir, {.unprivileged = true});
  EXPECT_EQ(o.status, 2) << o.out << o.err;
  EXPECT_NE(
      o.err.find("output directory " + out.string() + ": cannot create a file in it: Permission denied"),
      std::string::npos)
      << o.err;
  EXPECT_TRUE(stopped_before_the_solve(o)) << o.out;
  EXPECT_TRUE(fs::is_empty(out));
  fs::permissions(out, fs::perms::all);
  fs::remove_all(dir);
}

TEST(OutputDirectory, AFileGivenAsOutStopsTheRunBeforeTheSolve) {
  const fs::path dir = fresh_directory("pd_outdir_file"), out = dir / "a_file";
  std::ofstream(out) << "keep me\n";
  const Outcome o = run_pd(kScene, out, dir);
  EXPECT_EQ(o.status, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("output directory " + out.string() + ": exists and is not a directory"),
            std::string::npos)
      << o.err;
  EXPECT_TRUE(stopped_before_the_solve(o)) << o.out;
  EXPECT_EQ(read_text(out), "keep me\n");
  fs::remove_all(dir);
}

TEST(OutputDirectory, ADiskThatRefusesWritesStopsTheRunBeforeTheSolve) {
  // RLIMIT_FSIZE makes every write past 1000 bytes fail, as a full disk does (ENOSPC
  // needs a full filesystem; the probe's failing write is the same path).
  const fs::path dir = fresh_directory("pd_outdir_full"), out = dir / "out";
  const Outcome o = run_pd(kScene, out, dir, {.file_size_limit = 1000});
  EXPECT_EQ(o.status, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("output directory " + out.string() + ": cannot write to it: File too large"),
            std::string::npos)
      << o.err;
  EXPECT_NE(o.err.find("MB free"), std::string::npos) << o.err;
  EXPECT_TRUE(stopped_before_the_solve(o)) << o.out;
  EXPECT_FALSE(fs::exists(out)) << "the directory pd created for the run was left behind";
  fs::remove_all(dir);
}

TEST(OutputDirectory, ASecondRunIntoTheSameDirectoryIsRefusedNamingTheFirst) {
  const fs::path dir = fresh_directory("pd_outdir_lock"), out = dir / "out";
  const fs::path first_dir = dir / "first", second_dir = dir / "second";
  fs::create_directories(first_dir), fs::create_directories(second_dir);
  std::ofstream(dir / "long.yaml") << kLongScene;
  const pid_t first = start_pd(dir / "long.yaml", out, first_dir, {});
  for (int i = 0; i < 1000 && !fs::exists(out / ".pd.lock"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(out / ".pd.lock"));
  const Outcome second = run_pd(kScene, out, second_dir);
  kill(first, SIGTERM);
  const Outcome o1 = wait_pd(first, first_dir);
  EXPECT_EQ(second.status, 2) << second.out << second.err;
  EXPECT_NE(
      second.err.find("output directory " + out.string() + ": another run (pid " + std::to_string(first)),
      std::string::npos)
      << second.err;
  EXPECT_TRUE(stopped_before_the_solve(second)) << second.out;
  EXPECT_EQ(o1.status, 143) << o1.err;
  // The first run, stopped, released the directory: nothing of either run is left.
  if (fs::exists(out))
    for (const auto& e : fs::directory_iterator(out)) ADD_FAILURE() << "left " << e.path();
  fs::remove_all(dir);
}

TEST(OutputDirectory, TheClaimIsExclusiveWithinAProcessToo) {
  const fs::path dir = fresh_directory("pd_outdir_claim");
  {
    const pd::OutputDirectoryClaim first(dir.string());
    EXPECT_THROW(pd::OutputDirectoryClaim second(dir.string()),
                 pd::OutputDirectoryError);  // flock: per open file
  }
  EXPECT_NO_THROW(pd::OutputDirectoryClaim again(dir.string()));
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

namespace {
// A dynamic bar with a snapshot every 10 steps; steps = 10^7 runs far longer than a test waits.
std::string dynamic_scene(long steps) {
  return "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 0.1]}, spacing: 0.025}\nhorizon: {ratio: 3.0}\n"
         "law: silling_plane_strain\ninfluence: const\nmaterials: [{name: bar, E: 1.0, nu: 0.0, density: "
         "1.0}]\n"
         "boundary:\n  - {region: {all: true}, fixed: [y]}\n"
         "dynamics:\n  method: explicit\n  steps: " +
         std::to_string(steps) +
         "\n  output_every: 10\n  snapshot_every: 10\n"
         "  checkpoint_every: 10\n  threads: 1\n"
         "  initial:\n    - {region: {all: true}, displacement: [1.0e-3, 0], gaussian: {axis: x, center: "
         "0.5, width: 0.1}}\n";
}
std::string run_id_in(const fs::path& file) {
  std::smatch m;
  const std::string text = read_text(file).substr(0, 4096);
  return std::regex_search(text, m, std::regex(R"(run_id"?\s*[=:]\s*"([^"]+)\")")) ? m[1].str() : "";
}
// Every VTK file under `out` (not in a staging directory) and summary.json carry `id`.
void expect_one_run(const fs::path& out, const std::string& id) {
  EXPECT_EQ(run_id_in(out / "summary.json"), id);
  int vtk_files = 0;
  for (auto it = fs::recursive_directory_iterator(out); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && name.rfind("unfinished-", 0) == 0) {
      it.disable_recursion_pending();
      continue;
    }
    const std::string ext = it->path().extension().string();
    if (ext == ".vtu" || ext == ".pvd") {
      ++vtk_files;
      EXPECT_EQ(run_id_in(it->path()), id) << it->path() << " belongs to another run";
    }
  }
  EXPECT_GE(vtk_files, 3);
}
}  // namespace

// A dynamic run killed with -9 into a directory holding an older result leaves that result
// whole (before: its snapshots and pvd were overwritten by the killed run's, under the old
// summary.json); the next run names the killed run's staging directory and replaces the old
// result entirely, stale snapshots included.
TEST(OutputDirectory, ARunKilledWithSignalNineLeavesTheOlderResultWhole) {
  const fs::path dir = fresh_directory("pd_outdir_kill9"), out = dir / "out";
  for (const char* d : {"a", "b", "c"}) fs::create_directories(dir / d);
  const Outcome a = run_pd(dynamic_scene(40), out, dir / "a");
  ASSERT_EQ(a.status, 0) << a.err;
  const std::string id_a = run_id_in(out / "summary.json");
  ASSERT_FALSE(id_a.empty());
  expect_one_run(out, id_a);

  std::ofstream(dir / "long.yaml") << dynamic_scene(10000000);
  const pid_t b = start_pd(dir / "long.yaml", out, dir / "b", {});
  // Wait until the second run has written snapshots of its own (wherever it writes them).
  bool wrote = false;
  for (int i = 0; i < 3000 && !wrote; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(out, ec))
      if (e.path().extension() == ".vtu" && e.path().filename().string() >= "step_00000040.vtu") {
        const std::string id = run_id_in(e.path());
        wrote = wrote || (!id.empty() && id != id_a);
      }
  }
  kill(b, SIGKILL);
  int status = 0;
  waitpid(b, &status, 0);
  ASSERT_TRUE(wrote) << "the second run wrote no snapshot";
  expect_one_run(out, id_a);

  const Outcome c = run_pd(dynamic_scene(20), out, dir / "c");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("  warning: " + out.string() + "/unfinished-"), std::string::npos) << c.out;
  const std::string id_c = run_id_in(out / "summary.json");
  EXPECT_NE(id_c, id_a);
  expect_one_run(out, id_c);
  EXPECT_FALSE(fs::exists(out / "snapshots/step_00000040.vtu")) << "a snapshot of the older run was left";
  EXPECT_TRUE(fs::exists(out / "snapshots/step_00000020.vtu"));
  fs::remove_all(dir);
}
