// A measured displacement field (digital image correlation, or a reference run) for a
// calibration (sensitivity/calibration.hpp): a CSV file with a header line naming its
// columns, then one row per measurement point. The columns read:
//   x, y[, z]        the point's reference position (z required in 3D, refused in 2D)
//   u_x, u_y[, u_z]  the measured displacement components, at least one of them
// Any other column (pd's result.csv has id and the law's outputs) is ignored, so a run's
// result.csv is a valid field. Blank lines and lines starting with # are skipped. Every
// error names the file and line: "dic.csv:17: row 15: u_x: 'abc' is not a finite number".
#pragma once

#include <string>
#include <vector>

namespace pd {

struct MeasuredField {
  std::string path;
  int dim = 2;
  std::vector<double> x;       // [n*dim] positions
  std::vector<double> value;   // [n*dim] displacements (0 where a component is not measured)
  std::vector<bool> measured;  // [dim] which components the file gives
  std::vector<int> line;       // [n] the file line of each row
  int size() const { return static_cast<int>(line.size()); }
};

// Throws SceneError ("path:line: message") on a missing file, a repeated column, no
// position or no displacement column, a row of the wrong length, a value that is not a
// finite number, and a file without rows.
MeasuredField read_measured_field(const std::string& path, int dim);
MeasuredField parse_measured_field(const std::string& contents, const std::string& path, int dim);

}  // namespace pd
