// ParaView output: a VTK unstructured grid (.vtu) with one vertex cell per particle.
#pragma once

#include <span>
#include <string>

#include "output/particle_fields.hpp"
#include "particles.hpp"

namespace pd {

// Points at the reference positions (ParaView's "Warp By Vector" on the displacement
// shows the deformed body), point data "displacement" (when u is not empty,
// [n*dim]) and every field, all Float64 in VTK's appended raw binary format (8 bytes
// a value instead of ~24 in ASCII, and bit-exact when read back; the head names the
// machine's byte order, blocks have UInt64 size headers). 2D points and vectors are
// padded with z = 0, as VTK wants 3 components. Written atomically
// (write_file_atomically). The root carries run_id (run_id.hpp), which VTK ignores.
// tests/output/check_outputs.py reads every kind with VTK.
void write_vtu_file(const std::string& path, const Particles& particles, std::span<const double> u,
                    std::span<const OutputField> fields);

// The same document as a string (for tests and for callers that compress or embed it).
std::string vtu_document(const Particles& particles, std::span<const double> u,
                         std::span<const OutputField> fields);

}  // namespace pd
