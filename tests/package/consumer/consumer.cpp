// Solves a scene through the installed library (the law table, the scene reader and a
// static run, writing no file) and compares the probe with the one the installed `pd run`
// wrote into summary.json: the library and the command line give the same number.
// usage: consumer SCENE SUMMARY_JSON; exit 0 when they agree bit for bit.
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "run/simulation.hpp"

int main(int argc, char** argv) {
  if (argc != 3 || !pd::abi::find_law("silling_plane_strain")) return 1;
  pd::Simulation sim(pd::read_scene(argv[1]), [](const std::string&) {});
  const pd::RunSummary s = sim.run(false);
  if (!s.newton.converged || s.probes.empty()) return 1;
  std::ifstream in(argv[2]);
  const double cli = nlohmann::json::parse(in)["probes"][0]["value"].get<double>();
  std::printf("%s: library %.17g, pd run %.17g\n", s.probes[0].name.c_str(), s.probes[0].value, cli);
  return s.probes[0].value == cli ? 0 : 1;
}
