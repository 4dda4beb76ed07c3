// 2D Taylor-Green vortex, Re = 100, periodic slab, t = 1 (issue 3, verification 1), for the
// 2nd-order scheme (central2 convection, 2nd-order operators) and the 4th-order scheme (central4
// convection with the 4th-order viscous, pressure-gradient and divergence operators of
// flow/operators_order4.hpp, ProjectionOptions::fourth_order_operators): velocity L2/Linf errors
// against the exact decaying solution on structured hexahedra, Kuhn-split tetrahedra and
// tetrahedra perturbed by 20% of h; observed orders from the two finest levels. Besides the full
// runs, the truncation error of each momentum term on the exact fields (convection, viscous,
// pressure gradient, divergence of u) is measured: the velocity error of this flow is set by the
// solenoidal part of the lowest-order term, so central4 with the 2nd-order viscous Laplacian
// stays at order 2 (hexa n 32, CFL 0.1: 4.5e-5 against 5.1e-6 with the 4th-order operators).
// Time step of the 4th-order runs: dt ~ h^2 (validation::fourth_order_spec; projection + RK4 has
// an O(dt^2) error ~0.012 dt^2 at Re 100 that a fixed CFL would show as order 2).
//
// CSV: errors.csv (error vs h and vs wall time), terms.csv; plot.py makes taylor_green.png.
// Measured numbers, their run conditions and what they show: README.md in this folder.
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
        "mesh,scheme,operators,n,h,nodes,steps,dt,velocity_l2,velocity_linf,pressure_l2,"
        "max_divergence,poisson_iterations,wall_seconds\n");
    terms = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "terms.csv").string()));
    terms->print("mesh,scheme,n,h,convection_l2,viscous_l2,pressure_gradient_l2,divergence_l2\n");
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
      // The 4th-order scheme: central4 convection with the 4th-order viscous, pressure-gradient
      // and divergence operators (ProjectionOptions::fourth_order_operators).
      const bool order4 = scheme == "central4";
      const std::string label = kind.name + " " + scheme;
      std::vector<TgvResult> results;
      std::vector<TgvTermErrors> term_errors;
      for (int n : levels) {
        TgvSpec spec = order4 ? fourth_order_spec(kind.type, kind.perturbation, n) : TgvSpec{};
        spec.cell_type = kind.type;
        spec.perturbation = kind.perturbation;
        spec.n = n;
        if (!order4) spec.cfl = kind.cfl;
        spec.scheme = scheme;
        spec.poisson.tolerance = 1e-10;
        const auto r = run_taylor_green(spec, ctx.comm);
        results.push_back(r);
        term_errors.push_back(taylor_green_term_errors(spec, ctx.comm));
        const auto& t = term_errors.back();
        if (csv) {
          csv->print("{},{},{},{},{:.6e},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{},{:.4f}\n",
                     kind.name, scheme, order4 ? "4th" : "2nd", n, r.h, r.nodes, r.steps, r.dt,
                     r.velocity_l2, r.velocity_linf, r.pressure_l2, r.max_divergence,
                     r.max_poisson_iterations, r.wall_seconds);
          terms->print("{},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e}\n", kind.name, scheme, n, r.h,
                       t.convection, t.viscous, t.pressure_gradient, t.divergence);
        }
      }
      const auto& a = results[results.size() - 2];
      const auto& b = results.back();
      const auto& ta = term_errors[term_errors.size() - 2];
      const auto& tb = term_errors.back();
      // Full solver: central2 2nd order (viscous term, pressure operators) and central4 with
      // the 4th-order operators (dt ~ h^2) 4th order; >= 1.9 and >= 3.5 asserted on the
      // uniform meshes, >= 1 on the perturbed ones (measured there: see the report).
      const double min_order = !kind.uniform ? 1.0 : order4 ? 3.5 : 1.9;
      report.add(label + ": observed order, velocity L2",
                 order(a.velocity_l2, b.velocity_l2, a.h, b.h), min_order, 0.0, Check::at_least);
      report.add(label + ": observed order, velocity Linf",
                 order(a.velocity_linf, b.velocity_linf, a.h, b.h), min_order, 0.0,
                 Check::at_least);
      // Per-term truncation orders on the exact fields. Convection: >= 3.5 for central4 on
      // the uniform meshes (the scheme's design order), >= 1.9 for central2; viscous and
      // pressure-gradient operators: >= 1.9 (2nd-order operators), >= 3.5 (4th-order ones). On
      // perturbed tetrahedra truncation errors converge slowly (Diskin & Thomas, NASA 2011):
      // measured orders ~1.0 for convection and pressure gradient (>= 0.8 asserted), and an
      // O(1) viscous truncation error for both operators (two-point + correction: 9.7e-4 at n 64
      // and 128, bounded by 2e-3; 4th-order on the P1 weights: 2.0e-3 at n 64, bounded by
      // 4e-3), while the velocity error still converges.
      const double conv_min = kind.uniform ? (order4 ? 3.5 : 1.9) : 0.8;
      report.add(label + ": truncation order, convection",
                 order(ta.convection, tb.convection, a.h, b.h), conv_min, 0.0, Check::at_least);
      const std::string ops =
          kind.name + (order4 ? " 4th-order operators" : " 2nd-order operators");
      if (kind.uniform)
        report.add(ops + ": truncation order, viscous", order(ta.viscous, tb.viscous, a.h, b.h),
                   order4 ? 3.5 : 1.9, 0.0, Check::at_least);
      else
        report.add(ops + fmt::format(": viscous truncation error (L2), n {}", b.n), tb.viscous,
                   order4 ? 4e-3 : 2e-3, 0.0, Check::at_most);
      report.add(ops + ": truncation order, pressure gradient",
                 order(ta.pressure_gradient, tb.pressure_gradient, a.h, b.h),
                 kind.uniform ? (order4 ? 3.5 : 1.9) : 0.8, 0.0, Check::at_least);
      // Finest-level error: bounded by the measured value at n 64 (central2: 1.2e-5 hexa,
      // 3.9e-4 tetra, 9.0e-4 perturbed; central4 + 4th-order operators: 4.5e-8 hexa, 4.3e-6
      // tetra, 1.2e-3 perturbed) with a factor 2 margin, so a regression shows.
      const double bound = order4 ? (kind.name == "hexa"    ? 9e-8
                                     : kind.name == "tetra" ? 8.6e-6
                                                            : 2.4e-3)
                                  : (kind.name == "hexa"    ? 2.4e-5
                                     : kind.name == "tetra" ? 8e-4
                                                            : 1.8e-3);
      report.add(label + fmt::format(": velocity L2 error, n {}", b.n), b.velocity_l2, bound, 0.0,
                 Check::at_most);
    }
  // The time error of the 4th-order runs: n 32 again with dt / 2. The error changes by less
  // than 20% when dt halves (measured ratio 0.934 hexa, 0.99994 tetra), i.e. the measured
  // orders are those of the spatial discretisation.
  for (const auto& kind : kinds) {
    if (!kind.uniform) continue;
    TgvSpec spec = fourth_order_spec(kind.type, kind.perturbation, 32);
    spec.poisson.tolerance = 1e-10;
    const double e = run_taylor_green(spec, ctx.comm).velocity_l2;
    spec.dt_max /= 2;
    const double e_half = run_taylor_green(spec, ctx.comm).velocity_l2;
    report.add(kind.name + " central4 4th-order operators n 32: L2 error with dt / 2 over L2 error",
               e_half / e, 1.0, 0.2);
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
