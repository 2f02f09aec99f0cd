// `pd study STUDY.yaml [--out DIR] [--quick]`: a convergence/cost study (runtime/study).
#include <cmath>
#include <cstdio>
#include <fmt/core.h>

#include "cli/commands.hpp"
#include "input/yaml_keys.hpp"
#include "study/study.hpp"

namespace pd::cli {

int study_command(const Args& args) {
  const char* usage =
      "usage: pd study STUDY.yaml [--out DIR] [--quick]\n"
      "  Runs every problem x law x influence x delta/h x resolution of the study (cached in DIR/points/,\n"
      "  so an interrupted study resumes), then writes DIR/points.csv, DIR/orders.md and DIR/*.png.\n"
      "  --quick runs the study's reduced sweep. DIR defaults to out/study.\n";
  std::string path, out = "out/study";
  bool quick = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-h" || args[i] == "--help") return fmt::print("{}", usage), 0;
    if (args[i] == "--quick")
      quick = true;
    else if (args[i] == "--out" && i + 1 < args.size())
      out = args[++i];
    else if (path.empty())
      path = args[i];
    else
      return fmt::print(stderr, "{}", usage), 2;
  }
  if (path.empty()) return fmt::print(stderr, "{}", usage), 2;
  StudySpec spec;
  try {
    spec = read_study(path);
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
    fmt::print("  {:<10} {:<32} {:<10} delta/h={:<4} {:<18} order {:7.3f}{}\n", o.problem, o.law, o.influence, o.ratio,
               o.smoothing.empty() ? "" : "smoothed " + o.smoothing, o.order, o.paper.order ? fmt::format("   (paper {:.4f})", *o.paper.order) : "");
  fmt::print("results: {}/points.csv, {}/orders.md, {}/*.png\n", out, out, out);
  return 0;
}

}  // namespace pd::cli
