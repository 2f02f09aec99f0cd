// domain.particles: a body read from a .vtu point cloud (input/particle_vtu.hpp).
// Our own VTU writer's file of a box lattice gives the same particles and solution as the
// box scene; hand-written ASCII files cover each refusal, naming the scene key, the file,
// the element's line and the point id. Files written by VTK itself in every encoding are
// read in tests/output/check_vtu_particles.py.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "discretize/discretization.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "output/vtu_writer.hpp"
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
  const fs::path dir = fs::temp_directory_path() / ("pd_particle_vtu_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}
pd::Scene scene_of(const fs::path& file, const std::string& extra = "") {
  return pd::parse_scene("dimension: 2\ndomain: {particles: " + file.string() + extra + "}\n" + kRest,
                         "scene.yaml");
}
std::string error_of(const std::string& vtu) {
  const fs::path path = scratch() / "body.vtu";
  std::ofstream(path, std::ios::binary) << vtu;
  try {
    scene_of(path);
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}
// An ASCII VTU of two particles; the arrays' texts are parameters (line numbers: Points on 5,
// volume on 8, material on 9).
std::string ascii_vtu(const std::string& points = "0 0 0  1 0 0", const std::string& volume = "1 1",
                      const std::string& material =
                          "<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">0 1</DataArray>",
                      const std::string& piece = "NumberOfPoints=\"2\" NumberOfCells=\"0\"") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid><Piece " +
         piece +
         ">\n<Points>\n"
         "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" +
         points +
         "</DataArray>\n</Points>\n<PointData>\n"
         "<DataArray type=\"Float64\" Name=\"volume\" format=\"ascii\">" +
         volume + "</DataArray>\n" + material + "\n</PointData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n";
}
}  // namespace

TEST(ParticleVtu, OurOwnWritersFileOfABoxLatticeGivesTheSameParticlesAndSolution) {
  pd::Scene box = pd::parse_scene(
      "dimension: 2\ndomain: {box: {min: [0, 0], max: [1, 1]}, count: 10, placement: node}\n" + kRest,
      "box.yaml");
  pd::Particles lattice = pd::discretize(box);
  // The right half glass (index 1), stored as Float64 like every field our writer writes.
  std::vector<double> material(static_cast<std::size_t>(lattice.size()));
  for (int i = 0; i < lattice.size(); ++i) material[i] = lattice.x[2 * i] > 0.55 ? 1 : 0;
  for (int i = 0; i < lattice.size(); ++i) lattice.material[i] = static_cast<int>(material[i]);
  const std::vector<pd::OutputField> fields = {{"volume", 1, lattice.volume}, {"material", 1, material}};
  const fs::path path = scratch() / "lattice.vtu";
  pd::write_vtu_file(path.string(), lattice, {}, fields);

  pd::Scene file = scene_of(path, ", spacing: 0.1");
  EXPECT_EQ(file.h, box.h);
  const pd::Particles b = pd::discretize(file);
  EXPECT_EQ(b.x, lattice.x);
  EXPECT_EQ(b.volume, lattice.volume);
  EXPECT_EQ(b.material, lattice.material);
  int glass = 0;
  for (int m : b.material) glass += m;
  EXPECT_EQ(glass, 5 * 11);  // the columns x = 0.6, ..., 1.0 of 11 rows

  // Without the material array every particle is the first material, as in the box scene: the same solution.
  pd::write_vtu_file(path.string(), pd::discretize(box), {},
                     std::vector<pd::OutputField>{{"volume", 1, lattice.volume}});
  pd::Scene plain = scene_of(path, ", spacing: 0.1");
  box.output.vtu = box.output.csv = plain.output.vtu = plain.output.csv = false;
  pd::Simulation sa(box, [](const std::string&) {}), sb(plain, [](const std::string&) {});
  sa.run(false);
  sb.run(false);
  EXPECT_EQ(sa.displacement(), sb.displacement());
}

TEST(ParticleVtu, MalformedFilesNameTheKeyTheLineAndThePoint) {
  EXPECT_EQ(error_of(ascii_vtu()), "");
  const std::string where = "scene.yaml:2: domain.particles: ";
  const struct {
    std::string vtu, message;
  } cases[] = {
      {"not xml at all", "body.vtu:1: not a VTK XML file: "},
      {"<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"/>\n", "body.vtu:2: not a VTK unstructured grid"},
      {ascii_vtu("0 0 0  1 0 0", "1 -1"),
       "body.vtu:8: PointData 'volume': point id 1: volume must be positive and finite (got -1)"},
      {ascii_vtu("0 0 0  1 0 0", "1 nan"),
       "body.vtu:8: PointData 'volume': point id 1: volume must be positive and finite (got nan)"},
      {ascii_vtu("0 0 0  1 0 0", "1"), "body.vtu:8: PointData 'volume': 1 values where 2 were expected"},
      {ascii_vtu("0 0 0  1 zero 0"), "body.vtu:5: Points: value 4: 'zero' is not a number"},
      {ascii_vtu("0 0 0  1 0 0.5"), "body.vtu:5: Points: point id 1: z = 0.5 in a 2D scene"},
      {ascii_vtu("0 0 0  0 0 0"), "body.vtu:5: Points: point id 1: a second particle at the same position"},
      {ascii_vtu("0 0 0  1 0 0", "1 1",
                 "<DataArray type=\"Float64\" Name=\"material\" format=\"ascii\">0 0.5</DataArray>"),
       "body.vtu:9: PointData 'material': point id 1: 0.5 is not a material index"},
      {ascii_vtu("0 0 0  1 0 0", "1 1",
                 "<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">0 2</DataArray>"),
       "body.vtu:9: point id 1: unknown material '2' (the scene's materials: rock, glass)"},
      {ascii_vtu("0 0 0  1 0 0", "1 1",
                 "<DataArray type=\"Int32\" Name=\"volume\" format=\"ascii\">1 1</DataArray>"),
       "body.vtu:9: a second DataArray 'volume' (the first is on line 8)"},
      {ascii_vtu("0 0 0  1 0 0", "1 1", "", "NumberOfPoints=\"0\" NumberOfCells=\"0\""),
       "body.vtu:3: the grid has no points"},
      {ascii_vtu("0 0 0  1 0 0", "1 1",
                 "<DataArray type=\"Int32\" Name=\"material\" format=\"binary\">AAAA!AAA</DataArray>"),
       "body.vtu:9: PointData 'material': cannot decode the binary data: '!' is not a base64 character"},
  };
  for (const auto& c : cases) {
    const std::string e = error_of(c.vtu);
    EXPECT_EQ(e.rfind(where, 0), 0u) << c.vtu << "\n" << e;
    EXPECT_NE(e.find(c.message), std::string::npos) << c.vtu << "\n" << e << "\nexpected: " << c.message;
  }
  // Appended raw data whose block header promises 48 bytes where 2 follow.
  const std::string truncated =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "<UnstructuredGrid><Piece NumberOfPoints=\"2\">\n<Points>\n"
      "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>\n</Points>\n"
      "<PointData><DataArray type=\"Float64\" Name=\"volume\" format=\"ascii\">1 1</DataArray></PointData>\n"
      "</Piece></UnstructuredGrid>\n<AppendedData encoding=\"raw\">_" +
      std::string("\x30\0\0\0\0\0\0\0\x01\x02", 10) + "</AppendedData></VTKFile>\n";
  EXPECT_NE(error_of(truncated).find(
                "body.vtu:5: Points: cannot decode the appended data: the data ends before the array does"),
            std::string::npos)
      << error_of(truncated);
  // Block headers are outside input: a size they claim is checked against the array before
  // anything is allocated for it (the fuzzer's first find: 2^59 bytes asked of the allocator).
  const auto appended_points = [](const std::string& header_type, const std::string& compressor,
                                  const std::string& block) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\" "
           "header_type=\"" +
           header_type + "\"" + compressor +
           ">\n"
           "<UnstructuredGrid><Piece NumberOfPoints=\"2\">\n<Points>\n"
           "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" "
           "offset=\"0\"/>\n</Points>\n"
           "<PointData><DataArray type=\"Float64\" Name=\"volume\" format=\"ascii\">1 "
           "1</DataArray></PointData>\n"
           "</Piece></UnstructuredGrid>\n<AppendedData encoding=\"raw\">_" +
           block + "</AppendedData></VTKFile>\n";
  };
  const std::string huge_raw = appended_points("UInt64", "", std::string("\0\0\0\0\0\0\0\x08\x01\x02", 10));
  EXPECT_NE(error_of(huge_raw).find("body.vtu:5: Points: cannot decode the appended data: the block header "
                                    "claims 576460752303423488 bytes where the array needs 48"),
            std::string::npos)
      << error_of(huge_raw);
  // zlib: one block of 2^24 bytes claimed where the array needs 48.
  const std::string huge_zlib =
      appended_points("UInt32", " compressor=\"vtkZLibDataCompressor\"",
                      std::string("\x01\0\0\0\0\0\0\x01\0\0\0\0\x04\0\0\0xxxx", 20));
  EXPECT_NE(error_of(huge_zlib).find("body.vtu:5: Points: cannot decode the appended data: the block header "
                                     "claims 16777216 bytes where the array needs 48"),
            std::string::npos)
      << error_of(huge_zlib);
  // The right block size from 4 compressed bytes that are not a zlib stream: zlib's refusal.
  const std::string bad_stream =
      appended_points("UInt32", " compressor=\"vtkZLibDataCompressor\"",
                      std::string("\x01\0\0\0\x30\0\0\0\0\0\0\0\x04\0\0\0xxxx", 20));
  EXPECT_NE(error_of(bad_stream)
                .find("body.vtu:5: Points: cannot decode the appended data: zlib block 0 does "
                      "not decompress"),
            std::string::npos)
      << error_of(bad_stream);
  // No volume array: the PointData element's line.
  std::string no_volume = ascii_vtu("0 0 0  1 0 0", "1 1", "");
  no_volume.replace(no_volume.find("Name=\"volume\""), 13, "Name=\"vol\"");
  EXPECT_NE(error_of(no_volume).find("body.vtu:7: no point data array 'volume'"), std::string::npos)
      << error_of(no_volume);
}
