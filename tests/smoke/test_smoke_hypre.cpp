// hypre smoke test: the 1D Laplacian tridiag(-1, 2, -1) of order N is assembled row-block-wise
// across ranks through the IJ interface and solved with PCG preconditioned by BoomerAMG (hypre's
// defaults). The right-hand side is b = A x* for x*_i = sin(pi (i+1) / (N+1)), so x* is the exact
// discrete answer. Error bound: ||x - x*||_2 <= cond(A) ||r|| / ||b|| ||x*||_2 with
// cond(A) ~ 4 (N+1)^2 / pi^2, relative residual 1e-12 and ||x*||_2 = sqrt((N+1)/2).
// Iterations: AMG makes the count independent of N (plain CG would grow like N); we ask for at
// most 20 (mean residual reduction <= 0.25 per iteration; measured 11-14 on 1-3 ranks) at
// N = 1000 and 8000, and at most 3 more on the 8x finer problem.
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

struct Result {
  int iterations;
  double residual;
  double error;  // max |x - x*| over all ranks
};

Result solve_laplacian(HYPRE_BigInt n) {
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const HYPRE_BigInt lower = n * rank / size, upper = n * (rank + 1) / size - 1;
  auto exact = [n](HYPRE_BigInt i) { return std::sin(std::numbers::pi * (i + 1) / (n + 1)); };

  HYPRE_IJMatrix a;
  HYPRE_IJVector b, x;
  REQUIRE(HYPRE_IJMatrixCreate(comm, lower, upper, lower, upper, &a) == 0);
  HYPRE_IJMatrixSetObjectType(a, HYPRE_PARCSR);
  HYPRE_IJMatrixInitialize(a);
  HYPRE_IJVectorCreate(comm, lower, upper, &b);
  HYPRE_IJVectorCreate(comm, lower, upper, &x);
  for (HYPRE_IJVector v : {b, x}) {
    HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(v);
  }
  std::vector<HYPRE_BigInt> rows;
  std::vector<double> rhs, zero;
  for (HYPRE_BigInt i = lower; i <= upper; ++i) {
    std::vector<HYPRE_BigInt> cols;
    std::vector<double> values;
    double ax = 2.0 * exact(i);
    if (i > 0) cols.push_back(i - 1), values.push_back(-1.0), ax -= exact(i - 1);
    cols.push_back(i), values.push_back(2.0);
    if (i < n - 1) cols.push_back(i + 1), values.push_back(-1.0), ax -= exact(i + 1);
    HYPRE_Int ncols = static_cast<HYPRE_Int>(cols.size());
    REQUIRE(HYPRE_IJMatrixSetValues(a, 1, &ncols, &i, cols.data(), values.data()) == 0);
    rows.push_back(i);
    rhs.push_back(ax);
    zero.push_back(0.0);
  }
  const auto local = static_cast<HYPRE_Int>(rows.size());
  REQUIRE(HYPRE_IJMatrixAssemble(a) == 0);
  HYPRE_IJVectorSetValues(b, local, rows.data(), rhs.data());
  HYPRE_IJVectorSetValues(x, local, rows.data(), zero.data());
  REQUIRE(HYPRE_IJVectorAssemble(b) == 0);
  REQUIRE(HYPRE_IJVectorAssemble(x) == 0);
  HYPRE_ParCSRMatrix pa;
  HYPRE_ParVector pb, px;
  HYPRE_IJMatrixGetObject(a, reinterpret_cast<void**>(&pa));
  HYPRE_IJVectorGetObject(b, reinterpret_cast<void**>(&pb));
  HYPRE_IJVectorGetObject(x, reinterpret_cast<void**>(&px));

  HYPRE_Solver pcg, amg;
  HYPRE_ParCSRPCGCreate(comm, &pcg);
  HYPRE_PCGSetTol(pcg, 1e-12);
  HYPRE_PCGSetMaxIter(pcg, 100);
  HYPRE_PCGSetTwoNorm(pcg, 1);
  HYPRE_BoomerAMGCreate(&amg);
  HYPRE_BoomerAMGSetPrintLevel(amg, 0);
  HYPRE_BoomerAMGSetTol(amg, 0.0);
  HYPRE_BoomerAMGSetMaxIter(amg, 1);
  HYPRE_ParCSRPCGSetPrecond(pcg, HYPRE_BoomerAMGSolve, HYPRE_BoomerAMGSetup, amg);
  REQUIRE(HYPRE_ParCSRPCGSetup(pcg, pa, pb, px) == 0);
  REQUIRE(HYPRE_ParCSRPCGSolve(pcg, pa, pb, px) == 0);
  HYPRE_Int iterations = 0;
  double residual = 0.0;
  HYPRE_PCGGetNumIterations(pcg, &iterations);
  HYPRE_PCGGetFinalRelativeResidualNorm(pcg, &residual);

  std::vector<double> solution(rows.size());
  HYPRE_IJVectorGetValues(x, local, rows.data(), solution.data());
  double local_error = 0.0;
  for (std::size_t k = 0; k < rows.size(); ++k)
    local_error = std::max(local_error, std::abs(solution[k] - exact(rows[k])));
  double error = 0.0;
  MPI_Allreduce(&local_error, &error, 1, MPI_DOUBLE, MPI_MAX, comm);

  HYPRE_BoomerAMGDestroy(amg);
  HYPRE_ParCSRPCGDestroy(pcg);
  HYPRE_IJMatrixDestroy(a);
  HYPRE_IJVectorDestroy(b);
  HYPRE_IJVectorDestroy(x);
  return {static_cast<int>(iterations), residual, error};
}

}  // namespace

TEST_CASE("hypre: IJ assembly across ranks, PCG + BoomerAMG on the 1D Laplacian") {
  REQUIRE(HYPRE_Init() == 0);
  int coarse_iterations = 0;
  for (const HYPRE_BigInt n : {1000, 8000}) {
    const Result r = solve_laplacian(n);
    const double cond = 4.0 * (n + 1.0) * (n + 1.0) / (std::numbers::pi * std::numbers::pi);
    const double bound = cond * 1e-12 * std::sqrt((n + 1.0) / 2.0);
    MESSAGE("hypre PCG+AMG, N = ", n, ": ", r.iterations, " iterations, relative residual ",
            r.residual, ", max error ", r.error, " (bound ", bound, ")");
    CHECK(r.residual < 1e-12);
    CHECK(r.error < bound);
    CHECK(r.iterations <= 20);
    if (n == 1000)
      coarse_iterations = r.iterations;
    else
      CHECK(r.iterations <= coarse_iterations + 3);
  }
  HYPRE_Finalize();
}
