// GoogleTest under MPI: one DistributedSession for the whole run; every rank runs every
// test, and the exit code is the worst rank's, so mpirun fails when any rank fails.
#include <gtest/gtest.h>
#include <mpi.h>

#include "solve/distributed_backend.hpp"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  int worst = 0;
  {
    pd::DistributedSession session({});
    // Only rank 0 prints the results; the others still count their failures.
    if (session.rank() != 0)
      delete testing::UnitTest::GetInstance()->listeners().Release(
          testing::UnitTest::GetInstance()->listeners().default_result_printer());
    int result = RUN_ALL_TESTS();
    MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  }
  return worst;
}
