// hypre IJ assembly and PCG + BoomerAMG solve of the compact-Laplacian Poisson equation; see
// pressure_poisson.hpp for the discretisation and the null-space treatment.
#include "flow/pressure_poisson.hpp"

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_mv.h>  // hypre_ParVectorAxpy (no public HYPRE_ form in 2.26)
#include <fmt/format.h>

#include <map>
#include <stdexcept>
#include <string>

#include "core/compensated_sum.hpp"

namespace valsalva::flow {

namespace {

void check_hypre(HYPRE_Int code, const char* call, int line) {
  if (code != 0) {
    HYPRE_ClearAllErrors();
    throw std::runtime_error(std::string("flow/pressure_poisson.cpp:") + std::to_string(line) +
                             ": hypre call " + call + " failed with error code " +
                             std::to_string(code));
  }
}
#define VALSALVA_HYPRE(call) check_hypre((call), #call, __LINE__)

void init_hypre_once() {
  static const bool initialised = [] {
    HYPRE_Init();
    return true;
  }();
  (void)initialised;
}

// BoomerAMG V-cycle followed by removal of the constant (null-space) component of its output:
// on the singular system the AMG correction otherwise carries a growing constant that makes
// PCG lose conjugacy and stagnate above the tolerance (seen at 2 ranks).
struct NullSpacePreconditioner {
  HYPRE_Solver amg = nullptr;
  HYPRE_ParVector ones = nullptr;
  double count = 1;
};

HYPRE_Int precondition(HYPRE_Solver solver, HYPRE_ParCSRMatrix A, HYPRE_ParVector b,
                       HYPRE_ParVector x) {
  auto* p = reinterpret_cast<NullSpacePreconditioner*>(solver);
  const HYPRE_Int code = HYPRE_BoomerAMGSolve(p->amg, A, b, x);
  HYPRE_Real sum = 0;
  HYPRE_ParVectorInnerProd(x, p->ones, &sum);
  hypre_ParVectorAxpy(-sum / p->count, reinterpret_cast<hypre_ParVector*>(p->ones),
                      reinterpret_cast<hypre_ParVector*>(x));
  return code;
}

HYPRE_Int precondition_setup(HYPRE_Solver solver, HYPRE_ParCSRMatrix A, HYPRE_ParVector b,
                             HYPRE_ParVector x) {
  return HYPRE_BoomerAMGSetup(reinterpret_cast<NullSpacePreconditioner*>(solver)->amg, A, b, x);
}

// Plain V-cycle for the non-singular (Dirichlet) system.
HYPRE_Int precondition_plain(HYPRE_Solver solver, HYPRE_ParCSRMatrix A, HYPRE_ParVector b,
                             HYPRE_ParVector x) {
  return HYPRE_BoomerAMGSolve(reinterpret_cast<NullSpacePreconditioner*>(solver)->amg, A, b, x);
}

}  // namespace

struct PressurePoisson::Hypre {
  NullSpacePreconditioner precond;
  HYPRE_IJVector ones = nullptr;
  HYPRE_IJMatrix A = nullptr;
  HYPRE_IJVector b = nullptr, x = nullptr;
  HYPRE_ParCSRMatrix parA = nullptr;
  HYPRE_ParVector parb = nullptr, parx = nullptr;
  HYPRE_Solver pcg = nullptr, amg = nullptr;
  std::vector<HYPRE_BigInt> rows;
  std::vector<double> values;
  // Dirichlet elimination: owned row r gets + a x_c on its right-hand side for each coupling
  // (r, c, a) to a Dirichlet node c; Dirichlet rows carry their diagonal d.
  struct Coupling {
    int row, col;
    double a;
  };
  std::vector<Coupling> couplings;
  std::vector<double> dirichlet_diagonal;  // per owned node, 0 when not Dirichlet

  ~Hypre() {
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (A) HYPRE_IJMatrixDestroy(A);
    if (b) HYPRE_IJVectorDestroy(b);
    if (x) HYPRE_IJVectorDestroy(x);
    if (ones) HYPRE_IJVectorDestroy(ones);
  }
};

PressurePoisson::PressurePoisson(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                                 PoissonOptions options)
    : mesh_(mesh), options_(options), hypre_(std::make_unique<Hypre>()) {
  if (weights.size() != mesh.edges.size())
    throw std::invalid_argument("flow::PressurePoisson: " + std::to_string(weights.size()) +
                                " Laplacian weights for " + std::to_string(mesh.edges.size()) +
                                " edges");
  if (!(options.tolerance > 0) || options.max_iterations < 1)
    throw std::invalid_argument(
        "flow::PressurePoisson: tolerance must be > 0 (got " + std::to_string(options.tolerance) +
        ") and max_iterations >= 1 (got " + std::to_string(options.max_iterations) + ")");
  init_hypre_once();
  auto& h = *hypre_;
  const MPI_Comm comm = mesh.comm.get();
  const HYPRE_BigInt lower = mesh.first_owned;
  const HYPRE_BigInt upper = mesh.first_owned + mesh.num_owned - 1;

  const auto& fixed = options_.dirichlet;
  if (!fixed.empty() && fixed.size() != static_cast<std::size_t>(mesh.num_local()))
    throw std::invalid_argument("flow::PressurePoisson: " + std::to_string(fixed.size()) +
                                " Dirichlet flags for " + std::to_string(mesh.num_local()) +
                                " local nodes");
  auto is_fixed = [&](int i) { return !fixed.empty() && fixed[i] != 0; };
  std::int64_t fixed_count = 0;
  for (int i = 0; i < mesh.num_owned; ++i) fixed_count += is_fixed(i);
  singular_ = mesh.comm.sum(fixed_count) == 0;

  // Rows of -lap(x) V (symmetric positive semi-definite): diagonal sum_k a_jk, off -a_jk;
  // Dirichlet rows keep only their diagonal, Dirichlet columns move to the right-hand side.
  std::vector<std::map<HYPRE_BigInt, double>> rows(mesh.num_owned);
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const double a = weights[e];
    for (const auto& [r, c] : {std::pair{j, k}, std::pair{k, j}}) {
      if (r >= mesh.num_owned) continue;
      rows[r][mesh.global_id[r]] += a;
      if (is_fixed(r)) continue;
      if (is_fixed(c))
        h.couplings.push_back({r, c, a});
      else
        rows[r][mesh.global_id[c]] -= a;
    }
  }
  h.dirichlet_diagonal.assign(mesh.num_owned, 0.0);
  for (int r = 0; r < mesh.num_owned; ++r)
    if (is_fixed(r)) h.dirichlet_diagonal[r] = rows[r][mesh.global_id[r]];
  VALSALVA_HYPRE(HYPRE_IJMatrixCreate(comm, lower, upper, lower, upper, &h.A));
  VALSALVA_HYPRE(HYPRE_IJMatrixSetObjectType(h.A, HYPRE_PARCSR));
  std::vector<HYPRE_Int> sizes(mesh.num_owned);
  for (int i = 0; i < mesh.num_owned; ++i) sizes[i] = static_cast<HYPRE_Int>(rows[i].size());
  VALSALVA_HYPRE(HYPRE_IJMatrixSetRowSizes(h.A, sizes.data()));
  VALSALVA_HYPRE(HYPRE_IJMatrixInitialize(h.A));
  std::vector<HYPRE_BigInt> cols;
  std::vector<double> vals;
  for (int i = 0; i < mesh.num_owned; ++i) {
    cols.clear();
    vals.clear();
    for (const auto& [c, v] : rows[i]) {
      cols.push_back(c);
      vals.push_back(v);
    }
    HYPRE_Int ncols = static_cast<HYPRE_Int>(cols.size());
    HYPRE_BigInt row = mesh.global_id[i];
    VALSALVA_HYPRE(HYPRE_IJMatrixSetValues(h.A, 1, &ncols, &row, cols.data(), vals.data()));
  }
  VALSALVA_HYPRE(HYPRE_IJMatrixAssemble(h.A));
  VALSALVA_HYPRE(HYPRE_IJMatrixGetObject(h.A, reinterpret_cast<void**>(&h.parA)));

  h.rows.resize(mesh.num_owned);
  for (int i = 0; i < mesh.num_owned; ++i) h.rows[i] = mesh.global_id[i];
  h.values.assign(mesh.num_owned, 0.0);
  for (HYPRE_IJVector* v : {&h.b, &h.x, &h.ones}) {
    VALSALVA_HYPRE(HYPRE_IJVectorCreate(comm, lower, upper, v));
    VALSALVA_HYPRE(HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR));
    VALSALVA_HYPRE(HYPRE_IJVectorInitialize(*v));
    VALSALVA_HYPRE(HYPRE_IJVectorSetValues(*v, mesh.num_owned, h.rows.data(), h.values.data()));
    VALSALVA_HYPRE(HYPRE_IJVectorAssemble(*v));
  }
  VALSALVA_HYPRE(HYPRE_IJVectorGetObject(h.b, reinterpret_cast<void**>(&h.parb)));
  VALSALVA_HYPRE(HYPRE_IJVectorGetObject(h.x, reinterpret_cast<void**>(&h.parx)));
  h.values.assign(mesh.num_owned, 1.0);
  VALSALVA_HYPRE(HYPRE_IJVectorSetValues(h.ones, mesh.num_owned, h.rows.data(), h.values.data()));
  VALSALVA_HYPRE(HYPRE_IJVectorGetObject(h.ones, reinterpret_cast<void**>(&h.precond.ones)));
  h.precond.count = static_cast<double>(mesh.global_nodes);

  VALSALVA_HYPRE(HYPRE_BoomerAMGCreate(&h.amg));
  HYPRE_BoomerAMGSetPrintLevel(h.amg, options.print_level);
  HYPRE_BoomerAMGSetCoarsenType(h.amg, options.coarsen_type);
  HYPRE_BoomerAMGSetInterpType(h.amg, options.interp_type);
  HYPRE_BoomerAMGSetRelaxType(h.amg, options.relax_type);
  if (singular_) {
    // The coarsest level is singular too: smooth it instead of the default direct solve.
    HYPRE_BoomerAMGSetCycleRelaxType(h.amg, options.relax_type, 3);
    HYPRE_BoomerAMGSetCycleNumSweeps(h.amg, 4, 3);
  }
  HYPRE_BoomerAMGSetStrongThreshold(h.amg, options.strong_threshold);
  HYPRE_BoomerAMGSetAggNumLevels(h.amg, options.aggressive_levels);
  // Restriction as a stored P^T: the V-cycle's transposed matvec (a scatter) becomes a plain
  // row-wise one; the same operator, only the summation order differs.
  HYPRE_BoomerAMGSetKeepTranspose(h.amg, 1);
  HYPRE_BoomerAMGSetNumSweeps(h.amg, 1);
  HYPRE_BoomerAMGSetMaxIter(h.amg, 1);
  HYPRE_BoomerAMGSetTol(h.amg, 0.0);

  VALSALVA_HYPRE(HYPRE_ParCSRPCGCreate(comm, &h.pcg));
  HYPRE_PCGSetTol(h.pcg, options.tolerance);
  HYPRE_PCGSetMaxIter(h.pcg, options.max_iterations);
  HYPRE_PCGSetTwoNorm(h.pcg, 1);
  HYPRE_PCGSetLogging(h.pcg, 1);
  HYPRE_PCGSetPrintLevel(h.pcg, options.print_level);
  h.precond.amg = h.amg;
  HYPRE_PCGSetPrecond(
      h.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(singular_ ? precondition : precondition_plain),
      reinterpret_cast<HYPRE_PtrToSolverFcn>(precondition_setup),
      reinterpret_cast<HYPRE_Solver>(&h.precond));
  // Set up once (AMG hierarchy included); solve() reuses it.
  VALSALVA_HYPRE(HYPRE_ParCSRPCGSetup(h.pcg, h.parA, h.parb, h.parx));
}

PressurePoisson::~PressurePoisson() = default;

PoissonResult PressurePoisson::solve(const std::vector<double>& f, std::vector<double>& x) {
  const int n = mesh_.num_owned;
  if (f.size() < static_cast<std::size_t>(n) ||
      x.size() != static_cast<std::size_t>(mesh_.num_local()))
    throw std::invalid_argument("flow::PressurePoisson::solve: right-hand side has " +
                                std::to_string(f.size()) + " values and the solution " +
                                std::to_string(x.size()) + ", expected " +
                                std::to_string(mesh_.num_local()));
  auto& h = *hypre_;
  const auto& comm = mesh_.comm;
  // b = -V f; Dirichlet rows d g, eliminated columns a g. Without Dirichlet rows b is made
  // consistent with the constant null space (A symmetric, A 1 = 0).
  core::CompensatedSum sum;
  for (int i = 0; i < n; ++i) {
    h.values[i] = -mesh_.volume[i] * f[i];
    sum.add(h.values[i]);
  }
  if (singular_) {
    const double mean = comm.sum(sum.value()) / static_cast<double>(mesh_.global_nodes);
    for (int i = 0; i < n; ++i) h.values[i] -= mean;
  } else {
    for (int i = 0; i < n; ++i)
      if (h.dirichlet_diagonal[i] != 0) h.values[i] = h.dirichlet_diagonal[i] * x[i];
    for (const auto& c : h.couplings) h.values[c.row] += c.a * x[c.col];
  }
  VALSALVA_HYPRE(HYPRE_IJVectorSetValues(h.b, n, h.rows.data(), h.values.data()));
  VALSALVA_HYPRE(HYPRE_IJVectorSetValues(h.x, n, h.rows.data(), x.data()));

  // PCG on the singular system can stop early (loss of conjugacy, a breakdown test) a little
  // above the tolerance; it is then restarted from where it stopped, within the iteration cap.
  PoissonResult result;
  for (int restart = 0; restart < 4; ++restart) {
    const HYPRE_Int code = HYPRE_ParCSRPCGSolve(h.pcg, h.parA, h.parb, h.parx);
    // hypre flags non-convergence as a (non-fatal) error; the residual is checked below.
    if (code != 0) HYPRE_ClearAllErrors();
    HYPRE_Int iterations = 0;
    HYPRE_PCGGetNumIterations(h.pcg, &iterations);
    HYPRE_PCGGetFinalRelativeResidualNorm(h.pcg, &result.relative_residual);
    result.iterations += iterations;
    if (result.relative_residual <= options_.tolerance ||
        result.iterations >= options_.max_iterations || iterations == 0)
      break;
  }
  const int iterations = result.iterations;
  result.converged = result.relative_residual <= options_.tolerance;
  if (!result.converged)
    throw std::runtime_error(fmt::format(
        "flow::PressurePoisson: PCG stopped after {} iterations (cap {}) with relative residual "
        "{:.3e} > tolerance {:.3e}",
        iterations, options_.max_iterations, result.relative_residual, options_.tolerance));

  VALSALVA_HYPRE(HYPRE_IJVectorGetValues(h.x, n, h.rows.data(), x.data()));
  if (!singular_) {
    // Dirichlet values exactly as given, not to the solver tolerance.
    for (int i = 0; i < n; ++i)
      if (h.dirichlet_diagonal[i] != 0) x[i] = h.values[i] / h.dirichlet_diagonal[i];
    const_cast<mesh::Halo&>(mesh_.halo).exchange(x, mesh::HaloMode::insert);
    return result;
  }
  // Zero volume-weighted mean fixes the free constant.
  core::CompensatedSum xv, vol;
  for (int i = 0; i < n; ++i) {
    xv.add(mesh_.volume[i] * x[i]);
    vol.add(mesh_.volume[i]);
  }
  const double x_mean = comm.sum(xv.value()) / comm.sum(vol.value());
  for (int i = 0; i < n; ++i) x[i] -= x_mean;
  const_cast<mesh::Halo&>(mesh_.halo).exchange(x, mesh::HaloMode::insert);
  return result;
}

}  // namespace valsalva::flow
