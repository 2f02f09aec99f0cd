// Gathers of owned values to rank 0. Each rank's block is contiguous in the Morton
// order and the blocks follow in rank order, so the concatenation of the ranks' packed
// owned values is the whole body in that order; rank 0 unpacks it to model order.
#include "petsc/rank_gather.hpp"

#include <algorithm>
#include <climits>
#include <numeric>
#include <stdexcept>

namespace pd {

namespace {
// Concatenates every rank's `mine` on rank 0 (MPI_Gatherv; int counts: under 2^31 values).
std::vector<double> gather_concatenated(const std::vector<double>& mine, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (mine.size() > static_cast<std::size_t>(INT_MAX))
    throw std::runtime_error("gather to rank 0: over 2^31 values on one rank");
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(rank == 0 ? ranks : 0), offsets(counts.size());
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  std::vector<double> all;
  if (rank == 0) {
    long long total = 0;
    for (int r = 0; r < ranks; ++r) offsets[r] = static_cast<int>(total), total += counts[r];
    if (total > INT_MAX) throw std::runtime_error("gather to rank 0: over 2^31 values in all");
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm);
  return all;
}
}  // namespace

void gather_particle_values(const Partition& part, int width, std::vector<double>& full, MPI_Comm comm) {
  std::vector<double> mine(static_cast<std::size_t>(part.owned()) * width);
  for (int i = 0; i < part.owned(); ++i)
    std::copy_n(full.begin() + static_cast<std::ptrdiff_t>(part.owned_particle(i)) * width, width,
                mine.begin() + static_cast<std::ptrdiff_t>(i) * width);
  const std::vector<double> all = gather_concatenated(mine, comm);
  if (part.rank != 0) return;
  const int n = static_cast<int>(part.order.order.size());
  for (int k = 0; k < n; ++k)
    std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(k) * width, width,
                full.begin() + static_cast<std::ptrdiff_t>(part.order.order[k]) * width);
}

void gather_family_alpha(const Partition& part, Bonds& bonds, MPI_Comm comm) {
  std::vector<double> mine;
  for (int i = 0; i < part.owned(); ++i) {
    const int p = part.owned_particle(i);
    mine.insert(mine.end(), bonds.alpha.begin() + bonds.offsets[p],
                bonds.alpha.begin() + bonds.offsets[p + 1]);
  }
  const std::vector<double> all = gather_concatenated(mine, comm);
  if (part.rank != 0) return;
  std::size_t at = 0;
  for (int p : part.order.order) {
    std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(at), bonds.offsets[p + 1] - bonds.offsets[p],
                bonds.alpha.begin() + bonds.offsets[p]);
    at += static_cast<std::size_t>(bonds.offsets[p + 1] - bonds.offsets[p]);
  }
  if (at != all.size())
    throw std::logic_error("gather_family_alpha: the ranks' families do not cover the bonds");
}

}  // namespace pd
