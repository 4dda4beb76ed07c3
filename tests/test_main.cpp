// doctest main for every valsalva test: MPI is always initialised ("serial" means one rank);
// the test fails on every rank when it fails on any.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  doctest::Context context(argc, argv);
  if (rank != 0) context.setOption("out", "/dev/null");
  int local = context.run();
  int global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const bool exit_only = context.shouldExit();
  MPI_Finalize();
  return exit_only ? local : global;
}
