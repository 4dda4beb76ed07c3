// 2D Taylor-Green vortex, Re = 100, periodic slab, t = 1 (issue 3, verification 1), for the
// convective schemes central2 and central4: velocity L2/Linf errors against the exact decaying
// solution on structured hexahedra, Kuhn-split tetrahedra and tetrahedra perturbed by 20% of h;
// observed orders from the two finest levels. Besides the full runs, the truncation error of
// each momentum term on the exact fields (convection, viscous, pressure gradient) is measured,
// because the velocity error of this flow is set by the solenoidal part of the lowest-order
// term: convection is balanced by the pressure gradient (both gradients here), so with central4
// the 2nd-order viscous Laplacian limits the velocity order to 2 (see the report metrics).
// CSV: errors.csv (error vs h and vs wall time), terms.csv; plot.py makes taylor_green.png.
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <memory>

#include "validation/case.hpp"
#include "validation/taylor_green/tgv_run.hpp"

namespace valsalva::validation {

namespace {

double order(double e_coarse, double e_fine, double h_coarse, double h_fine) {
  return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
}

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::unique_ptr<fmt::ostream> csv, terms;
  if (rank == 0) {
    csv = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "errors.csv").string()));
    csv->print(
        "mesh,scheme,n,h,nodes,steps,dt,velocity_l2,velocity_linf,pressure_l2,max_divergence,"
        "poisson_iterations,wall_seconds\n");
    terms = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "terms.csv").string()));
    terms->print("mesh,scheme,n,h,convection_l2,viscous_l2,pressure_gradient_l2\n");
  }
  struct Kind {
    std::string name, type;
    double perturbation;
    bool uniform;
    double cfl;
  };
  // Hexahedra at CFL 0.1: their spatial error is so small that the O(dt^2) time error of
  // CFL 0.5 would dominate it (see tests/flow/test_taylor_green.cpp).
  const std::vector<Kind> kinds = {{"hexa", "hexa", 0.0, true, 0.1},
                                   {"tetra", "tetra", 0.0, true, 0.5},
                                   {"tetra_perturbed", "tetra", 0.2, false, 0.5}};
  const std::vector<int> levels =
      ctx.quick ? std::vector<int>{16, 32, 64} : std::vector<int>{16, 32, 64, 128};
  for (const auto& kind : kinds)
    for (const std::string scheme : {"central2", "central4"}) {
      const std::string label = kind.name + " " + scheme;
      std::vector<TgvResult> results;
      std::vector<TgvTermErrors> term_errors;
      for (int n : levels) {
        TgvSpec spec;
        spec.cell_type = kind.type;
        spec.perturbation = kind.perturbation;
        spec.n = n;
        // central4 on split tetrahedra: its spatial error is 13x below central2's, and at
        // CFL 0.5 the O(dt^2) time error pollutes the order (measured 1.6 from 32 to 64).
        spec.cfl = scheme == "central4" && kind.uniform ? 0.1 : kind.cfl;
        spec.scheme = scheme;
        spec.poisson.tolerance = 1e-10;
        const auto r = run_taylor_green(spec, ctx.comm);
        results.push_back(r);
        term_errors.push_back(taylor_green_term_errors(spec, ctx.comm));
        const auto& t = term_errors.back();
        if (csv) {
          csv->print("{},{},{},{:.6e},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{},{:.4f}\n",
                     kind.name, scheme, n, r.h, r.nodes, r.steps, r.dt, r.velocity_l2,
                     r.velocity_linf, r.pressure_l2, r.max_divergence, r.max_poisson_iterations,
                     r.wall_seconds);
          terms->print("{},{},{},{:.6e},{:.6e},{:.6e},{:.6e}\n", kind.name, scheme, n, r.h,
                       t.convection, t.viscous, t.pressure_gradient);
        }
      }
      const auto& a = results[results.size() - 2];
      const auto& b = results.back();
      const auto& ta = term_errors[term_errors.size() - 2];
      const auto& tb = term_errors.back();
      // Full solver: 2nd order for both schemes (viscous term); >= 1.9 asserted on the
      // uniform meshes, >= 1 on the perturbed ones (measured there: see the report).
      const double min_order = kind.uniform ? 1.9 : 1.0;
      report.add(label + ": observed order, velocity L2",
                 order(a.velocity_l2, b.velocity_l2, a.h, b.h), min_order, 0.0, Check::at_least);
      report.add(label + ": observed order, velocity Linf",
                 order(a.velocity_linf, b.velocity_linf, a.h, b.h), min_order, 0.0,
                 Check::at_least);
      // Per-term truncation orders on the exact fields. Convection: >= 3.5 for central4 on
      // the uniform meshes (the scheme's design order), >= 1.9 for central2; viscous and
      // pressure-gradient operators are 2nd order for both schemes (>= 1.9). On perturbed
      // tetrahedra truncation errors converge slowly (Diskin & Thomas, NASA 2011): measured
      // orders ~1.0 for convection and pressure gradient (>= 0.8 asserted), and an O(1)
      // viscous truncation error (9.7e-4 at n 64 and 128; bounded by 2e-3), while the velocity
      // error still converges at order > 2.
      const double conv_min = kind.uniform ? (scheme == "central4" ? 3.5 : 1.9) : 0.8;
      report.add(label + ": truncation order, convection",
                 order(ta.convection, tb.convection, a.h, b.h), conv_min, 0.0, Check::at_least);
      if (scheme == "central2") {
        if (kind.uniform)
          report.add(kind.name + ": truncation order, viscous",
                     order(ta.viscous, tb.viscous, a.h, b.h), 1.9, 0.0, Check::at_least);
        else
          report.add(kind.name + fmt::format(": viscous truncation error (L2), n {}", b.n),
                     tb.viscous, 2e-3, 0.0, Check::at_most);
        report.add(kind.name + ": truncation order, pressure gradient",
                   order(ta.pressure_gradient, tb.pressure_gradient, a.h, b.h),
                   kind.uniform ? 1.9 : 0.8, 0.0, Check::at_least);
      }
      // Finest-level error: bounded by the measured value (n 64 central2: 1.2e-5 hexa,
      // 3.9e-4 tetra, 9.0e-4 perturbed) with a factor 2 margin, so a regression shows.
      const double bound = kind.name == "hexa" ? 2.4e-5 : kind.name == "tetra" ? 8e-4 : 1.8e-3;
      report.add(label + fmt::format(": velocity L2 error, n {}", b.n), b.velocity_l2, bound, 0.0,
                 Check::at_most);
    }
  // The viscous operator on tetrahedra: the P1 stiffness weights without correction
  // (ProjectionOptions::stiffness_viscous, which the DFG slab needs) against the default
  // two-point weights + non-orthogonal correction, central2, n 64. Measured: L2 velocity error
  // 4.00e-4 vs 3.93e-4 (split), 9.58e-4 vs 9.00e-4 (perturbed): no gain on these isotropic
  // tetrahedra, so the default stays; the ratio is checked so that a change of either shows.
  for (const auto& kind : kinds) {
    if (kind.type != "tetra") continue;
    TgvSpec spec;
    spec.cell_type = kind.type;
    spec.perturbation = kind.perturbation;
    spec.n = 64;
    spec.cfl = kind.cfl;
    spec.poisson.tolerance = 1e-10;
    const double two_point = run_taylor_green(spec, ctx.comm).velocity_l2;
    spec.stiffness_viscous = true;
    const double p1 = run_taylor_green(spec, ctx.comm).velocity_l2;
    report.add(kind.name +
                   " central2 n 64: L2 error with P1 viscous weights / two-point + "
                   "correction (measured 1.02 split, 1.06 perturbed)",
               p1 / two_point, 1.0, 0.1);
  }
}

}  // namespace

Case taylor_green_case() {
  return {"taylor_green",
          "2D Taylor-Green vortex Re 100, t 1: velocity error orders on hexa, split and perturbed "
          "tetra for central2 and central4 (projection + RK4), with per-term truncation orders",
          run};
}

}  // namespace valsalva::validation
