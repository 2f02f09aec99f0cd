// A body from elsewhere: a point cloud read from a CSV file (or a .vtu:
// input/particle_vtu.hpp) (`domain.particles:` in a
// scene), e.g. the cell centres and volumes of a mesh (docs/scene_format.md says how
// to make one). One header line naming the columns, in any order:
//   x, y[, z]  positions (the scene's dimension: z is required in 3D, refused in 2D)
//   volume     > 0 (an area in 2D)
//   material   optional: a material name of the scene, or its index in `materials`
// then one row per particle. Blank lines and lines starting with # are skipped. Every
// error names the file, the line and the row: "body.csv:17: row 15: volume must be
// positive (got -1)".
#pragma once

#include <string>
#include <vector>

#include "input/yaml_keys.hpp"

namespace pd {

struct ParticleFile {
  std::string path;
  int dim = 2;
  std::vector<double> x;              // [n*dim]
  std::vector<double> volume;         // [n]
  std::vector<std::string> material;  // [n] as written ("" when the file has no material column)
  std::vector<int> line;              // [n] the file line of each row, for later messages
  bool point_ids = false;             // messages say "point id i" (a .vtu, from 0), not "row i+1" (a CSV)
  std::string item(int i) const {
    return point_ids ? "point id " + std::to_string(i) : "row " + std::to_string(i + 1);
  }
  int size() const { return static_cast<int>(volume.size()); }
};

// Throws SceneError ("path:line: row k: message"). Rejects: a missing file, an unknown
// or repeated column, a missing x/y/z/volume column, a row of the wrong length, a value
// that is not a finite number, a non-positive volume, two particles at one position,
// and a file without rows. A path ending in .vtu is read by read_particle_vtu.
ParticleFile read_particle_file(const std::string& path, int dim);
// The same for a CSV file's contents, already read; `path` is only named in messages.
ParticleFile parse_particle_csv(const std::string& contents, const std::string& path, int dim);

// The material index of every row: a name from `names`, or an index into it. Throws
// SceneError naming the line of the first row whose material is unknown.
std::vector<int> particle_materials(const ParticleFile& f, const std::vector<std::string>& names);

}  // namespace pd
