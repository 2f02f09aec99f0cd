// Particle table as CSV: id, reference position, displacement, then every field.
#pragma once

#include <span>
#include <string>

#include "output/particle_fields.hpp"
#include "particles.hpp"

namespace pd {

// Header: id,x,y[,z][,u_x,u_y[,u_z]][,field or field_0..field_{c-1} ...]; vector
// fields of dim components are suffixed _x/_y/_z. 17 significant digits. Written
// atomically.
void write_csv_file(const std::string& path, const Particles& particles, std::span<const double> u,
                    std::span<const OutputField> fields);
std::string csv_document(const Particles& particles, std::span<const double> u,
                         std::span<const OutputField> fields);

}  // namespace pd
