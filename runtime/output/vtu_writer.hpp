// ParaView output: a VTK unstructured grid (.vtu) with one vertex cell per particle.
#pragma once

#include <span>
#include <string>

#include "output/particle_fields.hpp"
#include "particles.hpp"

namespace pd {

// Points at the reference positions (ParaView's "Warp By Vector" on the displacement
// shows the deformed body), point data "displacement" (when u is not empty,
// [n*dim]) and every field, all ASCII Float64 with 17 significant digits so a
// result read back is bit-exact. 2D points and vectors are padded with z = 0, as VTK
// wants 3 components. Written atomically (write_file_atomically).
void write_vtu_file(const std::string& path, const Particles& particles, std::span<const double> u,
                    std::span<const OutputField> fields);

// The same document as a string (for tests and for callers that compress or embed it).
std::string vtu_document(const Particles& particles, std::span<const double> u, std::span<const OutputField> fields);

}  // namespace pd
