// A checkpoint is used only by the run that wrote it, intact: a flipped bit anywhere, a
// checkpoint of another law on the same grid, one past the scene's last step and one
// of the other byte order are refused with a CheckpointError (exit 2 in `pd run`)
// naming the file and what differs. Before, all four were accepted (the flipped bit and
// the other law changed the result by percents; the late one reported an inconsistent time).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "dynamics/checkpoint.hpp"
#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "temp_files.hpp"

namespace {
void quiet(const std::string&) {}

pd::Scene bar(const std::string& law, int steps, const std::string& name) {
  pd::Scene s = pd::parse_scene(R"(dimension: 2
domain: {box: {min: [0, 0], max: [1, 0.1]}, spacing: 0.025}
horizon: {ratio: 3.0}
law: )" + law + R"(
influence: const
materials: [{name: bar, E: 1.0, nu: 0.0, density: 1.0}]
boundary: [{region: {all: true}, fixed: [y]}]
dynamics:
  steps: )" + std::to_string(steps) +
                                    R"(
  checkpoint_every: 10
  progress_seconds: 0
  threads: 1
  initial: [{region: {all: true}, displacement: [1.0e-3, 0], gaussian: {axis: x, center: 0.5, width: 0.1}}]
)",
                                "bar.yaml");
  const auto dir = pd::test::scratch_path("pd_checkpoint_refusals_" + name);
  s.output.directory = dir.string();
  return s;
}

// Runs `scene` to its end and returns the path of its last checkpoint.
std::string checkpoint_of(const pd::Scene& scene) {
  pd::DynamicSimulation sim(scene, quiet);
  sim.run(false);
  return scene.output.directory + "/checkpoint.bin";
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// The message of the CheckpointError a restart from `path` throws ("" when none).
std::string restart_error(pd::Scene scene, const std::string& path) {
  scene.dynamics->restart = path;
  try {
    pd::DynamicSimulation sim(scene, quiet);
    sim.run(false);
  } catch (const pd::CheckpointError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(CheckpointRefusals, TheRunThatWroteItResumes) {
  const pd::Scene scene = bar("silling_plane_strain", 20, "own");
  pd::Scene half = scene;
  half.dynamics->steps = 10;
  const std::string path = checkpoint_of(half);
  EXPECT_EQ(restart_error(scene, path), "");
}

TEST(CheckpointRefusals, FlippedBitsAreFound) {
  const std::string path = checkpoint_of(bar("silling_plane_strain", 10, "flip"));
  const std::string good = bytes_of(path);
  ASSERT_GT(good.size(), 1000u);
  ASSERT_NO_THROW(pd::parse_checkpoint(good, path));
  // One bit at a time: every byte of the head (identity, step, first records) and of the
  // tail (text, end, checksum), and every 61st byte between (the arrays). The magic and
  // the byte-order mark (bytes 0-11) have their own messages.
  std::vector<std::size_t> bytes;
  for (std::size_t i = 12; i < good.size(); i += (i < 2048 || i + 512 > good.size()) ? 1 : 61)
    bytes.push_back(i);
  for (std::size_t i : bytes) {
    std::string b = good;
    b[i] = static_cast<char>(b[i] ^ (1 << (i % 8)));
    try {
      pd::parse_checkpoint(b, path);
      ADD_FAILURE() << "a flipped bit in byte " << i << " of " << good.size() << " was accepted";
      break;
    } catch (const pd::CheckpointError& e) {
      ASSERT_NE(std::string(e.what()).find("damaged"), std::string::npos) << "byte " << i << ": " << e.what();
    }
  }
  EXPECT_THROW(pd::parse_checkpoint(good.substr(0, good.size() - 100), path), pd::CheckpointError);
  // Through the file, as a restart reads it.
  std::string b = good;
  b[good.size() / 2] ^= 4;
  write_bytes(path, b);
  EXPECT_NE(restart_error(bar("silling_plane_strain", 20, "flip_restart"), path).find("damaged"),
            std::string::npos);
}

TEST(CheckpointRefusals, AnotherLawOnTheSameGridIsRefusedNamingBoth) {
  const std::string path = checkpoint_of(bar("silling_plane_strain", 10, "silling"));
  const std::string message = restart_error(bar("lps_plane_strain", 20, "lps"), path);
  EXPECT_NE(message.find("belongs to another run"), std::string::npos) << message;
  EXPECT_NE(message.find("law: checkpoint silling_plane_strain, this run lps_plane_strain"),
            std::string::npos)
      << message;
}

TEST(CheckpointRefusals, OtherMaterialOrGridIsRefused) {
  const std::string path = checkpoint_of(bar("silling_plane_strain", 10, "grid"));
  pd::Scene stiffer = bar("silling_plane_strain", 20, "stiffer");
  stiffer.materials[0].elastic = pd::IsotropicElastic::from_E_nu(2.0, 0.0);
  EXPECT_NE(restart_error(stiffer, path).find("material[0]"), std::string::npos);
  pd::Scene longer = bar("silling_plane_strain", 20, "longer");
  longer.hi[0] = 1.2;
  EXPECT_NE(restart_error(longer, path).find("particles:"), std::string::npos);
}

TEST(CheckpointRefusals, ACheckpointPastTheLastStepIsRefused) {
  const std::string path = checkpoint_of(bar("silling_plane_strain", 30, "late"));
  const std::string message = restart_error(bar("silling_plane_strain", 20, "short"), path);
  EXPECT_NE(message.find("at step 30, past this scene's last step 20"), std::string::npos) << message;
}

TEST(CheckpointRefusals, TheOtherByteOrderAndOtherFormatsAreRefused) {
  const std::string path = checkpoint_of(bar("silling_plane_strain", 10, "order"));
  std::string b = bytes_of(path);
  std::swap(b[8], b[11]), std::swap(b[9], b[10]);  // the byte-order mark as the other order writes it
  write_bytes(path + ".swapped", b);
  try {
    pd::read_checkpoint(path + ".swapped");
    ADD_FAILURE() << "a checkpoint of the other byte order was accepted";
  } catch (const pd::CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("byte order"), std::string::npos) << e.what();
  }
  b = bytes_of(path);
  b[7] = '1';  // PDCKPT01: the format without checksum or identity
  write_bytes(path + ".old", b);
  EXPECT_THROW(pd::read_checkpoint(path + ".old"), pd::CheckpointError);
  write_bytes(path + ".foreign", "hello, world");
  EXPECT_THROW(pd::read_checkpoint(path + ".foreign"), pd::CheckpointError);
}
