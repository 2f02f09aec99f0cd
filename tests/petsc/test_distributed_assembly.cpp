// The distributed residual, tangent-vector product and tangent against the serial
// assembler's, entry by entry, at a deformed state, on any number of ranks.
#include <gtest/gtest.h>
#include <petscmat.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "petsc/distributed_body.hpp"

namespace pd {
namespace {

// A 2D body cut by a crack (broken bonds: the damaged kernels) and a 3D one; laws with
// horizon-sum states, so the tangent couples two horizons.
const char* k2D = R"(dimension: 2
domain: {box: {min: [0, 0], max: [1, 1]}, count: 14}
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: cubic
materials: [{E: 10, nu: 0.25, plane: strain}]
cracks: [{segment: [[0.2, 0.5], [0.7, 0.5]]}]
)";
const char* k3D = R"(dimension: 3
domain: {box: {min: [0, 0, 0], max: [1, 1, 1]}, count: 6}
horizon: {ratio: 2.0}
law: lps_3d
influence: linear
materials: [{E: 10, nu: 0.25}]
)";

// Laws without states: the pairwise (one-horizon) pattern, cracked in 2D.
const char* k2DPairwise = R"(dimension: 2
domain: {box: {min: [0, 0], max: [1, 1]}, count: 14}
horizon: {ratio: 3.0}
law: bond_based_constant_2d
influence: cubic
materials: [{E: 10, nu: 0.25, plane: strain}]
cracks: [{segment: [[0.2, 0.5], [0.7, 0.5]]}]
)";
const char* k3DPairwise = R"(dimension: 3
domain: {box: {min: [0, 0, 0], max: [1, 1, 1]}, count: 6}
horizon: {ratio: 2.0}
law: bond_based_constant_3d
influence: linear
materials: [{E: 10, nu: 0.25}]
)";

// The same pseudo-random displacement on every rank.
std::vector<double> deformation(int n) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-1e-2, 1e-2);
  std::vector<double> u(static_cast<std::size_t>(n));
  for (double& v : u) v = d(gen);
  return u;
}

// x (PETSc order) on every rank, in the model's order.
std::vector<double> gathered(const DistributedBody& body, Vec x) {
  VecScatter s;
  Vec all;
  VecScatterCreateToAll(x, &s, &all);
  VecScatterBegin(s, x, all, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(s, x, all, INSERT_VALUES, SCATTER_FORWARD);
  const PetscScalar* a;
  VecGetArrayRead(all, &a);
  const int d = body.dim();
  std::vector<double> out(body.partition().order.order.size() * d);
  for (std::size_t k = 0; k < body.partition().order.order.size(); ++k)
    for (int c = 0; c < d; ++c)
      out[static_cast<std::size_t>(body.partition().order.order[k]) * d + c] = a[k * d + c];
  VecRestoreArrayRead(all, &a);
  VecScatterDestroy(&s);
  VecDestroy(&all);
  return out;
}

void set_owned(const DistributedBody& body, const std::vector<double>& full, Vec x) {
  PetscScalar* a;
  VecGetArray(x, &a);
  const int d = body.dim();
  for (int i = 0; i < body.partition().owned(); ++i)
    for (int c = 0; c < d; ++c)
      a[i * d + c] = full[static_cast<std::size_t>(body.partition().owned_particle(i)) * d + c];
  VecRestoreArray(x, &a);
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

void check_against_serial(const char* yaml) {
  const Scene scene = parse_scene(yaml, "distributed.yaml");
  const Model model = build_model(scene, {.matrix = true, .threads = 1, .short_delta = std::nullopt});
  const FamilyAssembler& a = bond_families(*model.assembler, "the distributed assembly test");
  const int N = a.dofs(), d = scene.dim;
  const std::vector<double> u = deformation(N), v = deformation(N + 3);  // two different vectors
  std::vector<double> f(N), Kv(N);
  a.internal_forces(u.data(), f.data());
  a.stiffness_product(u.data(), v.data() + 3, Kv.data());
  SparseMatrix K;
  a.stiffness(u.data(), K);
  const std::vector<double> v_model(v.begin() + 3, v.end());

  DistributedBody body(model.particles, model.bonds, PETSC_COMM_WORLD);
  ASSERT_GT(model.bonds.bond_count(), 0);
  Vec x = body.create_vector(), y = body.create_vector();
  std::vector<double> u_local, v_local, out;
  set_owned(body, u, x);
  body.to_local(x, u_local);
  // The ghost update brought every value the rank's families read.
  for (int p : body.local_particles())
    for (int c = 0; c < d; ++c)
      EXPECT_EQ(u_local[static_cast<std::size_t>(p) * d + c], u[static_cast<std::size_t>(p) * d + c]);

  body.internal_forces(a, u_local, out);
  body.from_local(out, y);
  const std::vector<double> f_dist = gathered(body, y);
  const double f_scale = max_abs(f);
  for (int i = 0; i < N; ++i) EXPECT_NEAR(f_dist[i], f[i], 1e-12 * f_scale) << "force dof " << i;

  set_owned(body, v_model, x);
  body.to_local(x, v_local);
  body.tangent_product(a, u_local, v_local, out);
  body.from_local(out, y);
  const std::vector<double> Kv_dist = gathered(body, y);
  const double kv_scale = max_abs(Kv);
  for (int i = 0; i < N; ++i) EXPECT_NEAR(Kv_dist[i], Kv[i], 1e-12 * kv_scale) << "product dof " << i;

  // The matrix: every owned row has exactly the serial row's pattern and values.
  Mat M = body.create_matrix(a);
  body.assemble_matrix(a, u_local, M);
  const SparseMatrix Kr = K.transpose();  // row access: column j of Kr is row j of K
  double k_scale = 0;
  for (int j = 0; j < K.nonZeros(); ++j) k_scale = std::max(k_scale, std::fabs(K.valuePtr()[j]));
  for (int i = 0; i < body.partition().owned(); ++i) {
    const int p = body.partition().owned_particle(i);
    for (int c = 0; c < d; ++c) {
      const int row = p * d + c;
      PetscInt ncols;
      const PetscInt* cols;
      const PetscScalar* vals;
      MatGetRow(M, body.global_dof(p, c), &ncols, &cols, &vals);
      std::vector<std::pair<PetscInt, double>> dist(ncols);
      for (PetscInt k = 0; k < ncols; ++k) dist[k] = {cols[k], vals[k]};
      MatRestoreRow(M, body.global_dof(p, c), &ncols, &cols, &vals);
      std::vector<std::pair<PetscInt, double>> serial;
      for (SparseMatrix::InnerIterator it(Kr, row); it; ++it)
        serial.push_back(
            {body.global_dof(static_cast<int>(it.row()) / d, static_cast<int>(it.row()) % d), it.value()});
      std::sort(serial.begin(), serial.end());
      EXPECT_EQ(dist.size(), serial.size()) << "row of dof " << row;
      if (dist.size() != serial.size()) continue;  // no early return: MatDestroy below is collective
      for (std::size_t k = 0; k < dist.size(); ++k) {
        EXPECT_EQ(dist[k].first, serial[k].first) << "row of dof " << row;
        EXPECT_NEAR(dist[k].second, serial[k].second, 1e-12 * k_scale) << "row of dof " << row;
      }
    }
  }
  MatDestroy(&M);
  VecDestroy(&x);
  VecDestroy(&y);
}

TEST(DistributedAssembly, PlaneBodyWithCrackEqualsSerial) { check_against_serial(k2D); }
TEST(DistributedAssembly, Cube3DEqualsSerial) { check_against_serial(k3D); }
TEST(DistributedAssembly, PairwisePlaneBodyWithCrackEqualsSerial) { check_against_serial(k2DPairwise); }
TEST(DistributedAssembly, PairwiseCube3DEqualsSerial) { check_against_serial(k3DPairwise); }

TEST(Partition, OwnedBlocksCoverEveryParticleOnce) {
  const Scene scene = parse_scene(k2D, "p.yaml");
  const DiscretizedBody model(scene);
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  std::vector<int> owners(static_cast<std::size_t>(model.particles.size()), 0);
  for (int r = 0; r < ranks; ++r) {
    const Partition part = make_partition(model.particles, model.bonds, r, ranks);
    for (int i = 0; i < part.owned(); ++i) owners[part.owned_particle(i)] += 1;
    for (int g : part.ghosts) EXPECT_FALSE(part.owns(g));
  }
  for (int c : owners) EXPECT_EQ(c, 1);
}

}  // namespace
}  // namespace pd
