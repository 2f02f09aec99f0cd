// The kernel ABI (runtime/kernel_abi.hpp) as C++ text: the one place in the generator
// that spells its types, fields, array layouts and kernel signatures. The kernel builders
// (law/kernels.cpp), the emitter and the file formatter ask here.
#pragma once

#include <string>
#include <vector>

namespace pdgen::abi_text {

// A kernel's C++ signature: return type, "type name" parameters and their names.
struct Signature {
  std::string return_type;
  std::vector<std::string> params, names;
};
enum class Kernel { Moments, Residual, Tangent, Jvp, Sensitivity, Form, Energy, Outputs, Update, Influence };
Signature signature(Kernel k);

// Family inputs. Per bond k: component c of a vector field (xi, Y), a scalar field
// (w, alpha, V). Per family: V0, delta, parameter i, moment i.
std::string bond_vector(const std::string& field, int dim, int c);
std::string bond_scalar(const std::string& field);
// A per-bond array the caller may leave null, meaning 1 for every bond.
std::string optional_bond_scalar(const std::string& field);
std::string family_scalar(const std::string& field);
std::string param(int i);
// Bond k's pair value of parameter i of n: `mean` (a function of kernel_abi.hpp) of the
// center's and the neighbour's value, or the center's when fam.nbr_params is null.
std::string pair_param(int i, int n_params, const std::string& mean);
std::string moment_input(int i);
// Bond k's committed value of history variable i of n (Family::history; null: `initial`),
// and the update kernel's store of its new value.
std::string history_input(int i, int n_history, double initial);
std::string history_output(int i, int n_history);
// The center's committed value of per-particle history variable i (Family::particle_history;
// null: `initial`), and the update kernel's store of its new value.
std::string particle_history_input(int i, double initial);
std::string particle_history_output(int i);
std::string bond_count();  // L
std::string scratch();     // the per-bond cache's storage

// Kernel outputs. Nodal vector `array` (forces, df): the center's component c and
// neighbour k+1's; the JVP's bond increment dY_k = dy_{k+1} - dy_0.
std::string center_component(const std::string& array, int c);
std::string neighbour_component(const std::string& array, int dim, int c);
std::string bond_increment(int dim, int c);
// The sensitivity kernel's column of parameter i: a nodal vector like `forces`.
std::string sensitivity_column(int dim, int i);
std::string forces_requested();  // the tangent writes forces only when given them
std::string factor_direct(int dim, int r, int c);
std::string factor_left(int dim, int n_states, int s, int r);
std::string factor_right(int dim, int n_states, int s, int c);
// The same factor entries read in the form kernel: bond `bond` (a C++ expression), the
// factors bound to `factors`.
std::string factor_at(const std::string& which, const std::string& bond, int per_bond, int index);
std::string bond_volume(const std::string& bond);  // V of bond `bond`
std::string center_volume();                       // V0
std::string moment_output(int i);
std::string output(int i);

// Generated files: the header every generated file includes, and descriptor types.
std::string abi_include();
std::string param_range_type();  // the ABI's enum of parameter ranges
std::string law_descriptor_type();
std::string monomial_group_type();
std::string radial_term_type();
// The definitions of all_laws, all_influences, find_law and find_influence over the
// given descriptor calls ("pd::generated::silling_3d_descriptor()") and influence entries.
std::string law_table(const std::vector<std::string>& descriptors,
                      const std::vector<std::string>& influences);

}  // namespace pdgen::abi_text
