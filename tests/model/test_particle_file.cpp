// domain.particles: a body read from a CSV point cloud. The lattice of a box scene,
// written as a file, gives the same particles and the same solution; malformed files are
// refused naming the scene key, the file, its line and the row.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "discretize/discretization.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "run/simulation.hpp"

namespace fs = std::filesystem;

namespace {
const std::string kRest = R"(law: silling_plane_strain
influence: cubic
materials: [{name: rock, E: 1, nu: 0.25}, {name: glass, E: 2, nu: 0.25}]
boundary:
  - {region: {side: bottom}, fixed: [x, y]}
  - {region: {side: top}, displacement: {x: 0, y: 0.01}}
)";

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("pd_particle_file_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}
// A scene whose domain is the file with `csv` as its text; returns the parse error ("" if none).
std::string error_of(const std::string& csv, const std::string& domain_extra = "") {
  const fs::path path = scratch() / "body.csv";
  std::ofstream(path) << csv;
  try {
    pd::parse_scene("dimension: 2\ndomain: {particles: " + path.string() + domain_extra + "}\n" + kRest,
                    "scene.yaml");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}
std::string lattice_csv(int n, double h, const char* material_column) {
  std::string s = std::string("x,y,volume") + (material_column ? ",material" : "") + "\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      s += fmt::format("{:.17g},{:.17g},{:.17g}", i * h, j * h, h * h);
      if (material_column) s += std::string(",") + (i > n / 2 ? material_column : "rock");
      s += "\n";
    }
  return s;
}
}  // namespace

TEST(ParticleFile, TheLatticeOfABoxSceneAsAFileGivesTheSameParticlesAndSolution) {
  pd::Scene box = pd::parse_scene(
      "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 1]}, count: 10, placement: node}\n" + kRest,
      "box.yaml");
  const fs::path path = scratch() / "lattice.csv";
  std::ofstream(path) << lattice_csv(10, 0.1, nullptr);
  // Without spacing, h is the mean of sqrt(volume): 0.1 up to rounding (which moves delta, and u, in the last
  // digits).
  EXPECT_NEAR(
      pd::parse_scene("dimension: 2\ndomain: {particles: " + path.string() + "}\n" + kRest, "file.yaml").h,
      box.h, 1e-15);
  pd::Scene file = pd::parse_scene(
      "dimension: 2\ndomain: {particles: " + path.string() + ", spacing: 0.1}\n" + kRest, "file.yaml");
  EXPECT_EQ(file.h, box.h);
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(file.lo[c], box.lo[c]);
    EXPECT_EQ(file.hi[c], box.hi[c]);
  }
  const pd::Particles a = pd::discretize(box), b = pd::discretize(file);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.material, b.material);
  box.output.vtu = box.output.csv = file.output.vtu = file.output.csv = false;
  pd::Simulation sa(box, [](const std::string&) {}), sb(file, [](const std::string&) {});
  sa.run(false);
  sb.run(false);
  EXPECT_EQ(sa.displacement(), sb.displacement());
}

TEST(ParticleFile, MaterialsByNameOrIndex) {
  const fs::path path = scratch() / "two.csv";
  std::ofstream(path) << lattice_csv(4, 0.25, "1");  // index 1: glass
  const pd::Scene s =
      pd::parse_scene("dimension: 2\ndomain: {particles: " + path.string() + "}\n" + kRest, "scene.yaml");
  const pd::Particles p = pd::discretize(s);
  int glass = 0;
  for (int m : p.material) glass += m == 1;
  EXPECT_EQ(glass, 2 * 5);  // columns i = 3, 4 of 5 rows
  EXPECT_EQ(error_of(lattice_csv(4, 0.25, "glass")), "");
}

TEST(ParticleFile, MalformedFilesNameTheKeyTheLineAndTheRow) {
  const std::string where = "scene.yaml:2: domain.particles: ";
  const struct {
    std::string csv, message;
  } cases[] = {
      {"", "the particle file is empty"},
      {"x,y,volume\n", "body.csv:1: the particle file has a header but no particle rows"},
      {"x,y\n0,0\n", "body.csv:1: no column 'volume'"},
      {"x,y,z,volume\n0,0,0,1\n", "body.csv:1: a z column in a 2D scene"},
      {"x,y,volume,colour\n", "body.csv:1: unknown column 'colour'"},
      {"x,y,volume,x\n", "body.csv:1: column 'x' given twice"},
      {"# a comment\nx,y,volume\n0,0,1\n\n1,0\n", "body.csv:5: row 2: 2 values for 3 columns"},
      {"x,y,volume\n0,0,1\n1,zero,1\n", "body.csv:3: row 2: y: 'zero' is not a finite number"},
      {"x,y,volume\n0,0,nan\n", "body.csv:2: row 1: volume: 'nan' is not a finite number"},
      {"x,y,volume\n0,0,1e999\n", "body.csv:2: row 1: volume: '1e999' is not a finite number"},
      {"x,y,volume\n0,0,-1\n", "body.csv:2: row 1: volume must be positive (got -1)"},
      {"x,y,volume\n0,0,1\n1,0,1\n0,0,1\n", "body.csv:4: row 3: a second particle at the same position"},
      {"x,y,volume,material\n0,0,1,rock\n1,0,1,steel\n",
       "body.csv:3: row 2: unknown material 'steel' (the scene's materials: rock, glass)"},
      {"x,y,volume,material\n0,0,1,2\n", "body.csv:2: row 1: unknown material '2'"},
  };
  for (const auto& c : cases) {
    const std::string e = error_of(c.csv);
    EXPECT_EQ(e.rfind(where, 0), 0u) << c.csv << "\n" << e;
    EXPECT_NE(e.find(c.message), std::string::npos) << c.csv << "\n" << e;
  }
  EXPECT_NE(error_of("x,y,volume\n0,0,1\n", ", box: {min: [0, 0], max: [1, 1]}")
                .find("domain.box: box does not apply to a body read from a particle file"),
            std::string::npos);
  EXPECT_NE(error_of("x,y,volume\n0,0,1\n", ", spacing: 0").find("domain.spacing: spacing must be positive"),
            std::string::npos);
  fs::remove(scratch() / "body.csv");
  try {
    pd::parse_scene("dimension: 2\ndomain: {particles: nowhere.csv}\n" + kRest, "/tmp/scene.yaml");
    ADD_FAILURE() << "a missing particle file was accepted";
  } catch (const pd::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("domain.particles: /tmp/nowhere.csv: cannot open the particle file"),
              std::string::npos)
        << e.what();
  }
}
