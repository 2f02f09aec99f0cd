// `pd study STUDY.yaml [--out DIR] [--quick]`: a convergence/cost study (runtime/study).
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "input/yaml_keys.hpp"
#include "study/study.hpp"

namespace pd::cli {

namespace {
struct StudyOptions {
  std::string path, out = "out/study", placement;
  bool quick = false;
};

int run_study_file(const StudyOptions& options) {
  const std::string& path = options.path;
  const std::string& out = options.out;
  const bool quick = options.quick;
  StudySpec spec;
  try {
    spec = read_study(path);
    spec.placement = options.placement;
  } catch (const SceneError& e) {
    fmt::print(stderr, "pd study: {}\n", e.what());
    return 2;
  }
  // Flushed per point: a long study run into a file or a pipe shows its progress.
  const auto orders = run_study(spec, out, quick, [](const std::string& l) {
    fmt::print("{}\n", l);
    std::fflush(stdout);
  });
  fmt::print("\norders of convergence (least squares on log e vs log h):\n");
  for (const auto& o : orders)
    fmt::print("  {:<10} {:<32} {:<10} delta/h={:<4} {:<18} order {:7.3f}{}\n", o.problem, o.law, o.influence,
               o.ratio, o.smoothing.empty() ? "" : "smoothed " + o.smoothing, o.order,
               o.paper.order ? fmt::format("   (paper {:.4f})", *o.paper.order) : "");
  fmt::print("results: {}/points.csv, {}/orders.md, {}/*.png\n", out, out, out);
  return 0;
}
}  // namespace

Command add_study_command(CLI::App& pd) {
  CLI::App* cmd = pd.add_subcommand("study", "convergence and cost study");
  cmd->footer(
      "Runs every problem x law x influence x delta/h x resolution of the study (cached in DIR/points/,\n"
      "so an interrupted study resumes), then writes DIR/points.csv, DIR/orders.md and DIR/*.png.\n"
      "Exit codes: 0 done, 1 a run failed, 2 bad usage or a bad study file.\n");
  auto options = std::make_shared<StudyOptions>();
  cmd->add_option("STUDY", options->path, "the study file (YAML)")->required();
  cmd->add_option("--out", options->out, "the output directory DIR")
      ->capture_default_str()
      ->check(kNonEmptyPath);
  cmd->add_option("--placement", options->placement,
                  "replace every problem's domain.placement (node or cell)")
      ->check(CLI::IsMember({"node", "cell"}));
  cmd->add_flag("--quick", options->quick, "run the study's reduced sweep");
  return [options] { return run_study_file(*options); };
}

}  // namespace pd::cli
