// A point cloud from a VTK unstructured grid (`domain.particles: body.vtu`): the grid's
// points are the particles, point data "volume" (one component, > 0) their volumes and
// the optional point data "material" (integral values) their material indices into the
// scene's `materials`. Cells are ignored (docs/scene_format.md says how to turn a mesh's
// cells into such points). Read as VTK writes it: DataArrays in ascii, binary (base64) or
// appended (raw or base64) format, UInt32 or UInt64 block headers, uncompressed or
// vtkZLibDataCompressor, either byte order. The XML is parsed by libxml2.
// Every error names the file and the line of the element: "body.vtu:7: PointData
// 'volume': point id 14: volume must be positive (got -1)" (point ids from 0, as ParaView
// shows them).
#pragma once

#include <string>

#include "input/particle_file.hpp"

namespace pd {

// Throws SceneError. Rejects what read_particle_file rejects for a CSV (non-finite
// values, non-positive volumes, two particles at one position, no particles), a 2D
// scene's point with z != 0, more than one Piece, a missing volume array, arrays of the
// wrong length or type, and data that cannot be decoded (with the reason).
ParticleFile read_particle_vtu(const std::string& path, int dim);
// The same for a .vtu file's bytes, already read; `path` is only named in messages.
ParticleFile parse_particle_vtu(const std::string& contents, const std::string& path, int dim);

}  // namespace pd
