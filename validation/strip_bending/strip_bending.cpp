// Thin-strip bending in the leaflet regime: a cantilever strip 0.15 mm thick with ONE Q2
// element through the thickness and elements up to 7 times longer than thick, leaflet
// neo-Hookean law (G = 2.4 MPa, K = 1.6 MPa, i.e. nu = 0 and E = 4.8 MPa, so beam theory needs no
// plate or Poisson correction). A dead tip load P (uniform traction on the tip face):
//  - small load: tip deflection vs Euler–Bernoulli P L^3 / (3 E I), within 2%;
//  - large loads alpha = P L^2/(EI) up to 5: tip deflection vs the elastica (shooting method in
//    elastica.cpp), within 2% of the reference deflection (aspect ratio 7 up to alpha = 2, the
//    finest mesh of the run for every alpha).
// Measured numbers, their run conditions and what they show: README.md in this folder.
#include <fmt/format.h>
#include <fmt/os.h>

#include <array>
#include <cmath>

#include "structure/mesh_generators.hpp"
#include "structure/static_solver.hpp"
#include "validation/case.hpp"
#include "validation/strip_bending/elastica.hpp"

namespace valsalva::validation {

namespace {

using namespace valsalva::structure;

constexpr double kT = 0.15e-3, kB = 1.0e-3, kL = 10.5e-3, kG = 2.4e6, kK = 1.6e6;

struct Tip {
  double v, u;  // transverse and axial tip displacement of the mid-surface centre line
  int iterations;
};

struct StripOptions {
  std::array<int, 3> gauss{3, 3, 3};  // along length, thickness, width
  double length = kL;
  int steps_per_alpha = 3;
  double rtol = 1e-9;
};

Tip solve_strip(int n_length, double alpha, const StripOptions& so = {}) {
  const double L = so.length;
  Bar b;
  b.length = L;
  b.height = kT;  // thickness along y, deflection along y
  b.depth = kB;
  b.n_length = n_length;
  b.n_height = 1;
  b.n_depth = 1;
  const SolidMesh m = straight_bar(HexOrder::q2, b);
  const auto mat = make_neo_hookean(kG, kK);
  SolidForces forces(m, *mat, so.gauss);
  const double E = 9 * kK * kG / (3 * kK + kG), I = kB * kT * kT * kT / 12;
  const double P = alpha * E * I / (L * L);
  StaticProblem prob;
  prob.forces = &forces;
  prob.dirichlet.push_back({m.node_set("clamped"), {true, true, true}, {}});
  prob.tractions.push_back({m.surface_set("tip"), Vec3(0, -P / (kB * kT), 0)});
  NewtonOptions o;
  o.load_steps = alpha < 0.1 ? 1 : static_cast<int>(std::ceil(so.steps_per_alpha * alpha));
  o.rtol = so.rtol;
  const NewtonResult r = solve_static(prob, o);
  if (!r.converged) throw std::runtime_error("strip_bending: " + r.diagnosis);
  for (int n : m.node_set("tip"))
    if (std::abs(m.X(1, n) - kT / 2) < 1e-12 && std::abs(m.X(2, n) - kB / 2) < 1e-12)
      return {m.X(1, n) - r.x(1, n), r.x(0, n) - m.X(0, n), r.iterations};
  throw std::logic_error("strip_bending: no tip centre node");
}

// alpha = 5 at aspect ratio 7 (10 elements): what changes the 2.2% error and what does not.
void locking_study(const Context& ctx, Report& report) {
  const double a = 5;
  const double ref = elastica_tip(a).deflection;
  auto out = fmt::output_file((ctx.out_dir / "strip_bending_locking.csv").string());
  out.print("setting,n_length,aspect_ratio,length_over_thickness,rel_error\n");
  struct Row {
    const char* setting;
    int n;
    StripOptions so;
  };
  const Row rows[] = {
      {"3x3x3 (case setting)", 10, {}},
      {"3x3x3; 4x load steps; rtol 1e-12", 10, {{3, 3, 3}, kL, 12, 1e-12}},
      {"4x4x4", 10, {{4, 4, 4}}},
      {"2 points through thickness (leaflet 3x3x2)", 10, {{3, 2, 3}}},
      {"2 points along length (2x3x3)", 10, {{2, 3, 3}}},
      {"3x3x3; strip twice as long", 20, {{3, 3, 3}, 2 * kL}},
      {"3x3x3; 20 elements (aspect 3.5)", 20, {}},
  };
  for (const Row& r : rows) {
    const Tip t = solve_strip(r.n, a, r.so);
    const double err = t.v / r.so.length / ref - 1;
    out.print("{},{},{:.2f},{:.0f},{:.4e}\n", r.setting, r.n, r.so.length / r.n / kT,
              r.so.length / kT, err);
    if (r.so.gauss[0] == 2)
      report.add("alpha=5 aspect 7 with 2x3x3 (locking diagnostic, not a leaflet setting)", 1 + err,
                 1.0, 0.02);
  }
}

void run(const Context& ctx, Report& report) {
  auto out = fmt::output_file((ctx.out_dir / "strip_bending.csv").string());
  out.print("alpha,n_length,aspect_ratio,deflection_over_L,reference_over_L,rel_error,reference\n");
  const std::vector<int> meshes = ctx.quick ? std::vector<int>{10} : std::vector<int>{10, 20};
  // Small load: linear beam theory delta/L = alpha/3.
  const double a0 = 1e-3;
  for (int n : meshes) {
    const Tip t = solve_strip(n, a0);
    const double ref = a0 / 3;
    out.print("{},{},{:.2f},{:.8e},{:.8e},{:.3e},beam\n", a0, n, kL / n / kT, t.v / kL, ref,
              t.v / kL / ref - 1);
    if (n == meshes.front())
      report.add(
          fmt::format("small load tip deflection / beam theory, aspect ratio {:.0f}", kL / n / kT),
          t.v / kL / ref, 1.0, 0.02);
  }
  const std::vector<double> alphas =
      ctx.quick ? std::vector<double>{2.0} : std::vector<double>{1.0, 2.0, 5.0};
  for (double a : alphas) {
    const ElasticaTip ref = elastica_tip(a);
    for (int n : meshes) {
      const Tip t = solve_strip(n, a);
      out.print("{},{},{:.2f},{:.8e},{:.8e},{:.3e},elastica\n", a, n, kL / n / kT, t.v / kL,
                ref.deflection, t.v / kL / ref.deflection - 1);
      // Asserted on the finest mesh of the run, and at aspect ratio 7 up to alpha = 2 (aspect
      // ratio 7 at alpha = 5: -2.2%, see the header comment and the locking study).
      if (n == meshes.back() || a <= 2)
        report.add(
            fmt::format("alpha={} tip deflection / elastica, aspect ratio {:.1f}", a, kL / n / kT),
            t.v / kL / ref.deflection, 1.0, 0.02);
    }
  }
  if (!ctx.quick) locking_study(ctx, report);
  // The shooting reference itself against Bisshopp & Drucker's tabulated value at alpha = 1.
  report.add("elastica shooting: deflection/L at alpha=1 (Bisshopp-Drucker 0.30172)",
             elastica_tip(1.0).deflection, 0.30172, 5e-5);
}

}  // namespace

Case strip_bending_case() {
  return {"strip_bending",
          "Cantilever strip 0.15 mm thick, one Q2 element through the thickness: beam theory and "
          "elastica",
          run};
}

}  // namespace valsalva::validation
