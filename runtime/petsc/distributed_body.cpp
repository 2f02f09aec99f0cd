// Ghost updates and the rank's family loops (residual, tangent-vector product, tangent).
#include "petsc/distributed_body.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

#include "assembly/collocation.hpp"
#include "local_matrix.hpp"
#include "petsc/petsc_check.hpp"

namespace pd {

namespace {
bool finite(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}
}  // namespace

DistributedBody::DistributedBody(const Particles& particles, const Bonds& bonds, MPI_Comm comm)
    : comm_(comm), dim_(particles.dim), particles_(particles) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  part_ = make_partition(particles, bonds, rank, ranks);
  for (int i = 0; i < part_.owned(); ++i) local_particles_.push_back(part_.owned_particle(i));
  local_particles_.insert(local_particles_.end(), part_.ghosts.begin(), part_.ghosts.end());
  std::vector<PetscInt> ghost_blocks;
  for (int g : part_.ghosts) ghost_blocks.push_back(part_.order.position[g]);
  check(VecCreateGhostBlock(comm, dim_, static_cast<PetscInt>(part_.owned()) * dim_, PETSC_DECIDE,
                            static_cast<PetscInt>(ghost_blocks.size()), ghost_blocks.data(), &ghosted_),
        "VecCreateGhostBlock");
}

DistributedBody::~DistributedBody() { VecDestroy(&ghosted_); }

Vec DistributedBody::create_vector() const {
  Vec v;
  check(VecCreateMPI(comm_, static_cast<PetscInt>(part_.owned()) * dim_, PETSC_DETERMINE, &v),
        "VecCreateMPI");
  check(VecSetBlockSize(v, dim_), "VecSetBlockSize");
  return v;
}

Vec DistributedBody::coordinates() const {
  Vec x = create_vector();
  PetscScalar* a;
  check(VecGetArray(x, &a), "VecGetArray");
  for (int i = 0; i < part_.owned(); ++i)
    for (int c = 0; c < dim_; ++c) a[i * dim_ + c] = particles_.position(part_.owned_particle(i))[c];
  check(VecRestoreArray(x, &a), "VecRestoreArray");
  return x;
}

void DistributedBody::zero_local(std::vector<double>& full) const {
  full.resize(static_cast<std::size_t>(particles_.size()) * dim_, 0.0);
  for (int p : local_particles_) std::fill_n(full.begin() + static_cast<std::ptrdiff_t>(p) * dim_, dim_, 0.0);
}

void DistributedBody::to_local(Vec x, std::vector<double>& full) {
  full.resize(static_cast<std::size_t>(particles_.size()) * dim_, 0.0);
  check(VecCopy(x, ghosted_), "VecCopy");
  check(VecGhostUpdateBegin(ghosted_, INSERT_VALUES, SCATTER_FORWARD), "VecGhostUpdateBegin");
  check(VecGhostUpdateEnd(ghosted_, INSERT_VALUES, SCATTER_FORWARD), "VecGhostUpdateEnd");
  Vec local;
  const PetscScalar* a;
  check(VecGhostGetLocalForm(ghosted_, &local), "VecGhostGetLocalForm");
  check(VecGetArrayRead(local, &a), "VecGetArrayRead");
  for (std::size_t s = 0; s < local_particles_.size(); ++s)
    std::copy_n(a + s * dim_, dim_, full.begin() + static_cast<std::ptrdiff_t>(local_particles_[s]) * dim_);
  check(VecRestoreArrayRead(local, &a), "VecRestoreArrayRead");
  check(VecGhostRestoreLocalForm(ghosted_, &local), "VecGhostRestoreLocalForm");
}

void DistributedBody::from_local(const std::vector<double>& full, Vec y) {
  Vec local;
  PetscScalar* a;
  check(VecGhostGetLocalForm(ghosted_, &local), "VecGhostGetLocalForm");
  check(VecGetArray(local, &a), "VecGetArray");
  for (std::size_t s = 0; s < local_particles_.size(); ++s)
    std::copy_n(full.begin() + static_cast<std::ptrdiff_t>(local_particles_[s]) * dim_, dim_, a + s * dim_);
  check(VecRestoreArray(local, &a), "VecRestoreArray");
  check(VecGhostRestoreLocalForm(ghosted_, &local), "VecGhostRestoreLocalForm");
  check(VecGhostUpdateBegin(ghosted_, ADD_VALUES, SCATTER_REVERSE), "VecGhostUpdateBegin");
  check(VecGhostUpdateEnd(ghosted_, ADD_VALUES, SCATTER_REVERSE), "VecGhostUpdateEnd");
  check(VecCopy(ghosted_, y), "VecCopy");
}

// A non-finite kernel value on one rank must stop every rank (the others would wait in
// the next collective call): the lowest bad particle is agreed on, then all throw.
void DistributedBody::agree_finite(int bad_particle, const char* stage, const FamilyAssembler& a) const {
  int local = bad_particle < 0 ? INT_MAX : bad_particle, global = INT_MAX;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, comm_);
  if (global != INT_MAX)
    throw std::runtime_error(std::string(stage) + ": non-finite value (NaN or Inf) from law " + a.law().name +
                             " at particle " + std::to_string(global));
}

// One per-family vector kernel over the owned families, scattered with `sign` into out
// (owned and ghost particles): kernel(g, p, fam, local) fills the family's local vector.
template <class Kernel>
void DistributedBody::scatter_family_vectors(const FamilyAssembler& a, const char* stage, double sign,
                                             const std::vector<double>& u, std::vector<double>& out,
                                             Kernel&& kernel) const {
  zero_local(out);
  FamilyGather g(a.inputs());
  const Collocation* coll = a.inputs().collocation;
  int bad = -1;
  for (int i = 0; i < part_.owned() && bad < 0; ++i) {
    const int p = part_.owned_particle(i);
    const abi::Family fam = g.gather(p, u.data());
    if (!has_intact_bond(fam)) continue;  // cut free by damage: no force
    const int L = fam.n_bonds;
    double* local = g.local_vector();
    kernel(g, p, fam, local);
    if (coll) scale_neighbour_rows(*coll, *a.inputs().bonds, p, 1, local);
    if (!finite(local, static_cast<std::size_t>(L + 1) * dim_)) bad = p;
    for (int k = 0; k <= L && bad < 0; ++k)
      for (int c = 0; c < dim_; ++c)
        out[static_cast<std::ptrdiff_t>(g.particle(p, k)) * dim_ + c] += sign * local[k * dim_ + c];
  }
  agree_finite(bad, stage, a);
}

void DistributedBody::internal_forces(const FamilyAssembler& a, const std::vector<double>& u,
                                      std::vector<double>& f) const {
  scatter_family_vectors(
      a, "force assembly", 1.0, u, f,
      [&](FamilyGather&, int, const abi::Family& fam, double* out) { a.variant().residual(fam, out); });
}

void DistributedBody::tangent_product(const FamilyAssembler& a, const std::vector<double>& u,
                                      const std::vector<double>& v, std::vector<double>& Kv) const {
  // K = -df/du: the solver's sign, as FamilyAssembler::stiffness_product.
  scatter_family_vectors(a, "matrix-free product", -1.0, u, Kv,
                         [&](FamilyGather& g, int p, const abi::Family& fam, double* out) {
                           a.variant().jvp(fam, g.gather_local(p, v.data()), out);
                         });
}

Mat DistributedBody::create_matrix(const FamilyAssembler& a) const {
  std::vector<int> diagonal, off;
  block_row_counts(part_, *a.inputs().bonds, coupling_of_law(a.law().n_states), diagonal, off);
  std::vector<PetscInt> d_nnz(diagonal.begin(), diagonal.end()), o_nnz(off.begin(), off.end());
  Mat K;
  const PetscInt m = static_cast<PetscInt>(part_.owned()) * dim_;
  check(MatCreate(comm_, &K), "MatCreate");
  check(MatSetSizes(K, m, m, PETSC_DETERMINE, PETSC_DETERMINE), "MatSetSizes");
  check(MatSetBlockSize(K, dim_), "MatSetBlockSize");
  // AIJ with block size dim, not BAIJ: PETSc 3.18's GAMG builds its graph only from AIJ
  // ("No method creategraph for Mat of type seqbaij"), and hypre takes AIJ too. The
  // blocks are still set whole (MatSetValuesBlocked) and -mat_type baij still works.
  check(MatSetType(K, MATAIJ), "MatSetType");
  check(MatSetFromOptions(K), "MatSetFromOptions");
  check(MatXAIJSetPreallocation(K, dim_, d_nnz.data(), o_nnz.data(), nullptr, nullptr),
        "MatXAIJSetPreallocation");
  // The pattern is exact: a block outside it is a bug, not a reason to reallocate.
  check(MatSetOption(K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
  return K;
}

// A law without states: of the dense local matrix M ((L+1) dim square, row-major) only
// the center's block row and the blocks (k, 0) and (k, k) are nonzero; those go in, so the
// matrix keeps create_matrix's one-horizon pattern.
void DistributedBody::add_pair_blocks(const double* M, int L, const std::vector<PetscInt>& ids,
                                      std::vector<PetscScalar>& values, Mat K) const {
  const int d = dim_, m = (L + 1) * d;
  values.resize(static_cast<std::size_t>(d) * m);
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < m; ++c)
      values[static_cast<std::size_t>(r) * m + c] = -M[static_cast<std::size_t>(r) * m + c];
  check(MatSetValuesBlocked(K, 1, ids.data(), L + 1, ids.data(), values.data(), ADD_VALUES),
        "MatSetValuesBlocked");
  for (int k = 1; k <= L; ++k) {
    const PetscInt cols[2] = {ids[0], ids[k]};
    for (int r = 0; r < d; ++r)
      for (int q = 0; q < d; ++q) {
        const std::size_t row = static_cast<std::size_t>(k * d + r) * m;
        values[static_cast<std::size_t>(r) * 2 * d + q] = -M[row + q];
        values[static_cast<std::size_t>(r) * 2 * d + d + q] = -M[row + k * d + q];
      }
    check(MatSetValuesBlocked(K, 1, &ids[k], 2, cols, values.data(), ADD_VALUES), "MatSetValuesBlocked");
  }
}

void DistributedBody::assemble_matrix(const FamilyAssembler& a, const std::vector<double>& u, Mat K) const {
  check(MatZeroEntries(K), "MatZeroEntries");
  FamilyGather g(a.inputs());
  TangentScratch scratch;
  const int S = a.law().n_states;
  const abi::TangentFactors factors = scratch.view(dim_, S, g.max_bonds());
  const Collocation* coll = a.inputs().collocation;
  std::vector<PetscInt> ids;
  std::vector<PetscScalar> values;
  const bool pairwise = coupling_of_law(S) == Coupling::pairwise;
  int bad = -1;
  for (int i = 0; i < part_.owned() && bad < 0; ++i) {
    const int p = part_.owned_particle(i);
    const abi::Family fam = g.gather(p, u.data());
    if (!has_intact_bond(fam)) continue;  // cut free by damage: no stiffness
    const int L = fam.n_bonds, m = (L + 1) * dim_;
    a.variant().tangent(fam, nullptr, factors);
    double* M = g.local_matrix();
    form_local_matrix(a.variant(), dim_, S, fam, factors, M);
    if (coll) scale_neighbour_rows(*coll, *a.inputs().bonds, p, m, M);
    if (!finite(M, static_cast<std::size_t>(m) * m)) {
      bad = p;
      break;
    }
    // M is row-major in the local dofs (a*dim + r, b*dim + q): PETSc's row-oriented
    // layout for MatSetValuesBlocked over the family's particles.
    ids.resize(static_cast<std::size_t>(L) + 1);
    for (int k = 0; k <= L; ++k) ids[k] = part_.order.position[g.particle(p, k)];
    if (pairwise) {
      add_pair_blocks(M, L, ids, values, K);
      continue;
    }
    values.resize(static_cast<std::size_t>(m) * m);
    for (std::size_t e = 0; e < values.size(); ++e) values[e] = -M[e];  // K = -df/du
    check(MatSetValuesBlocked(K, L + 1, ids.data(), L + 1, ids.data(), values.data(), ADD_VALUES),
          "MatSetValuesBlocked");
  }
  agree_finite(bad, "stiffness assembly", a);
  check(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

}  // namespace pd
