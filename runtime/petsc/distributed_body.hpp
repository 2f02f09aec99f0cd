// The body over the ranks: PETSc's vector layout for the partition, the ghost update
// (one horizon) and the family loops over the rank's own families, in the serial
// assembler's kernels and signs. Particle-major dofs; a model dof (p, c) is PETSc dof
// position(p) * dim + c.
#pragma once

#include <petscmat.h>
#include <petscvec.h>

#include <vector>

#include "assembly/assembler.hpp"
#include "petsc/partition.hpp"

namespace pd {

class DistributedBody {
 public:
  // bonds: the widest families any loop will read (the tangent's); they fix the ghosts.
  DistributedBody(const Particles& particles, const Bonds& bonds, MPI_Comm comm);
  ~DistributedBody();
  DistributedBody(const DistributedBody&) = delete;
  DistributedBody& operator=(const DistributedBody&) = delete;

  const Partition& partition() const { return part_; }
  int dim() const { return dim_; }
  MPI_Comm comm() const { return comm_; }
  // A new (not ghosted) vector in the partition's layout, block size dim.
  Vec create_vector() const;
  // The owned particles' reference positions (MatNullSpaceCreateRigidBody's input).
  Vec coordinates() const;
  // PETSc's global dof of model dof (p, c).
  PetscInt global_dof(int p, int c) const {
    return static_cast<PetscInt>(part_.order.position[p]) * dim_ + c;
  }

  // full ([n * dim], model order) at the owned and ghost particles = x (a ghost update).
  void to_local(Vec x, std::vector<double>& full);
  // y = the owned entries of full plus what the other ranks hold in their ghost copies
  // of this rank's particles (a reverse ghost update with addition).
  void from_local(const std::vector<double>& full, Vec y);
  // Zeros full at the owned and ghost particles (a full-length vector, sized on first use).
  void zero_local(std::vector<double>& full) const;
  // The model ids of the owned particles followed by the ghosts.
  const std::vector<int>& local_particles() const { return local_particles_; }

  // Over this rank's families only (results at owned and ghost particles, to be summed
  // by from_local); u, v full-length. Throws on every rank when a kernel gives a
  // non-finite value on any rank, naming the lowest such particle.
  void internal_forces(const FamilyAssembler& a, const std::vector<double>& u, std::vector<double>& f) const;
  void tangent_product(const FamilyAssembler& a, const std::vector<double>& u, const std::vector<double>& v,
                       std::vector<double>& Kv) const;
  // A matrix of dim x dim blocks (MATAIJ with block size dim; -mat_type may change it) preallocated
  // exactly for a's pattern: its bonds, two horizons for a law with states and one for a law
  // without (Coupling::pairwise: a bond-based law's 3D tangent at delta = 2h has 33 blocks a
  // row instead of 257).
  Mat create_matrix(const FamilyAssembler& a) const;
  // K = -df/du of a's families at u (full-length), off-process blocks sent by PETSc.
  void assemble_matrix(const FamilyAssembler& a, const std::vector<double>& u, Mat K) const;

 private:
  void agree_finite(int bad_particle, const char* stage, const FamilyAssembler& a) const;
  void add_pair_blocks(const double* M, int L, const std::vector<PetscInt>& ids,
                       std::vector<PetscScalar>& values, Mat K) const;
  template <class Kernel>
  void scatter_family_vectors(const FamilyAssembler& a, const char* stage, double sign,
                              const std::vector<double>& u, std::vector<double>& out, Kernel&& kernel) const;
  MPI_Comm comm_;
  int dim_;
  const Particles& particles_;
  Partition part_;
  std::vector<int> local_particles_;
  Vec ghosted_ = nullptr;
};

}  // namespace pd
