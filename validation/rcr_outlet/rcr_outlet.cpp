// Lumped-parameter outlets (issue 22), through run::Simulation with the case's scene files:
// 1. rcr_pipe.toml: a rigid pipe with a Womersley inflow Q(t) = Q0 + Qa sin(w t) and an RCR
//    outlet, at w tau = 0.5, 2 and 8 (tau = R_d C). The outlet pressure P(t) (log.csv,
//    pressure_outlet: the patch's own pressure, where the lumped law holds) is fitted by
//    a + b sin(w t) + c cos(w t) over the last period (outlets.csv) and its amplitude sqrt(b^2 +
//    c^2) and phase atan2(c, b) compared with Qa |Z| and arg Z, Z(w) = R_p + R_d / (1 + i w tau)
//    (the periodic solution of C dp_d/dt = Q - p_d / R_d, P = p_d + R_p Q). The run starts on the
//    periodic solution (distal_pressure = p_d(0)), so that no transient of time tau remains;
//    what is left is the time discretisation of the exponential integrator, O((w dt)^2).
// 2. rcr_split.toml: two RCR outlets in parallel on a box channel, R_d and C swept over the
//    physiological range, on hexahedra (and, full level, 20 % perturbed tetrahedra); each run
//    must stay smooth (the second difference of the outlet flux
//    against its range) where an explicit coupling would have the amplification
//    rho(diag(dP/dQ) dQ/dP) of the last step, reported next to it.
#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>

#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "flow/lumped_outlets.hpp"
#include "run/simulation.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double kQ0 = 2e-6, kQa = 1.5e-6;         // m^3/s (rcr_pipe.toml)
constexpr double kRp = 1e7, kRd = 1e8, kC = 1e-9;  // Pa s/m^3, m^3/Pa
constexpr double kTau = kRd * kC;                  // 0.1 s
constexpr double kTwoPi = 2 * std::numbers::pi;

std::complex<double> impedance(double omega) {
  return kRp + kRd / std::complex<double>(1, omega * kTau);
}

struct Frequency {
  double omega_tau = 0;
  double amplitude_error = 0, phase_error = 0, mean_error = 0, law_residual = 0;
  double amplitude = 0, phase = 0;  // measured, Pa and rad
};

// rank 0: fits the last period of log.csv and fills the errors.
void fit_pressure(const std::filesystem::path& outlets, double period, Frequency& f) {
  const auto table = core::read_numeric_table(outlets, core::TableHeader::required);
  const auto t = table.column("time"), p = table.column("pressure_outlet");
  const auto q = table.column("flux_outlet"), pd = table.column("distal_pressure_outlet");
  const double omega = kTwoPi / period, end = t.back();
  // Least squares for [a, b, c]: uniform samples over one period make the normal equations
  // diagonal up to round-off, but the full 3 x 3 system is solved anyway.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  // Row 0 is the initial state, P^0 = p_d(0) (the law at zero flux, lumped_outlets.hpp).
  for (std::size_t k = 1; k < t.size(); ++k) {
    f.law_residual = std::max(f.law_residual, std::abs(p[k] - pd[k] - kRp * q[k]) / std::abs(p[k]));
    if (t[k] <= end - period * (1 - 1e-9)) continue;  // one period: (end - T, end]
    const Eigen::Vector3d basis(1, std::sin(omega * t[k]), std::cos(omega * t[k]));
    normal += basis * basis.transpose();
    rhs += basis * p[k];
  }
  const Eigen::Vector3d abc = normal.ldlt().solve(rhs);
  const auto z = impedance(omega);
  f.amplitude = std::hypot(abc[1], abc[2]);
  f.phase = std::atan2(abc[2], abc[1]);
  f.amplitude_error = std::abs(f.amplitude / (kQa * std::abs(z)) - 1);
  f.phase_error = std::abs(f.phase / std::arg(z) - 1);
  f.mean_error = std::abs(abc[0] / ((kRp + kRd) * kQ0) - 1);
}

void run_frequency(const Context& ctx, Frequency& f) {
  const double omega = f.omega_tau / kTau, period = kTwoPi / omega;
  const int steps_per_period = ctx.quick ? 200 : 400, periods = ctx.quick ? 1 : 2;
  // p_d(0) of the periodic solution: R_d Q0 + Qa Im[R_d / (1 + i w tau)].
  const double distal0 = kRd * kQ0 + kQa * std::imag(kRd / std::complex<double>(1, f.omega_tau));
  const auto dir = ctx.out_dir / "runs" / fmt::format("pipe_wtau_{}", f.omega_tau);
  run_scene_file(case_scene("rcr_outlet", "rcr_pipe.toml"),
                 {fmt::format("boundary.inlet.period={:.17g}", period),
                  fmt::format("boundary.outlet.distal_pressure={:.17g}", distal0),
                  fmt::format("time.dt={:.17g}", period / steps_per_period),
                  fmt::format("time.end={:.17g}", periods * period),
                  fmt::format("mesh.pipe.size={}", ctx.quick ? 0.002 : 0.001)},
                 dir, ctx.comm);
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (rank == 0) fit_pressure(dir / "outlets.csv", period, f);
  for (double* x :
       {&f.amplitude_error, &f.phase_error, &f.mean_error, &f.law_residual, &f.amplitude, &f.phase})
    core::Comm(ctx.comm).broadcast(*x);
}

struct SweepPoint {
  double distal_resistance = 0, capacitance = 0;
  std::string cells = "hexa";  // hexa, or tetra with 20 % perturbed nodes (full level)
  bool finished = false;
  double roughness = 0;               // max |Q^{n+1} - 2 Q^n + Q^{n-1}| / (max Q - min Q), xmax
  double explicit_amplification = 0;  // spectral radius of diag(slope) M, last step
  double split = 0;                   // mean flux share of xmax over the run
  std::string failure;
};

void run_sweep_point(const Context& ctx, SweepPoint& s) {
  const auto dir =
      ctx.out_dir / "runs" /
      fmt::format("split_{}_rd{:.0e}_c{:.0e}", s.cells, s.distal_resistance, s.capacitance);
  SceneRun measure;
  measure.at_end = [&](const run::Simulation& sim) {
    const auto* lumped = sim.loop().solver().lumped_outlets();
    Eigen::MatrixXd amplification = lumped->response();
    for (int j = 0; j < lumped->count(); ++j) amplification.row(j) *= lumped->steps()[j].slope;
    s.explicit_amplification = amplification.eigenvalues().cwiseAbs().maxCoeff();
  };
  try {
    run_scene_file(case_scene("rcr_outlet", "rcr_split.toml"),
                   {fmt::format("boundary.xmax.resistance={:.17g}", 0.1 * s.distal_resistance),
                    fmt::format("boundary.xmax.distal_resistance={:.17g}", s.distal_resistance),
                    fmt::format("boundary.xmax.capacitance={:.17g}", s.capacitance),
                    fmt::format("boundary.ymax.resistance={:.17g}", 0.2 * s.distal_resistance),
                    fmt::format("boundary.ymax.distal_resistance={:.17g}", 2 * s.distal_resistance),
                    fmt::format("boundary.ymax.capacitance={:.17g}", s.capacitance),
                    fmt::format("time.end={}", ctx.quick ? 1.0 : 2.0),
                    fmt::format("mesh.box.cell_type={}", s.cells),
                    fmt::format("mesh.box.perturbation={}", s.cells == "tetra" ? 0.2 : 0.0)},
                   dir, ctx.comm, measure);
    s.finished = true;
  } catch (const std::exception& e) {
    s.failure = e.what();
    return;
  }
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  if (rank == 0) {
    const auto table = core::read_numeric_table(dir / "log.csv", core::TableHeader::required);
    const auto qa = table.column("flux_xmax"), qin = table.column("flux_xmin");
    double lo = qa[0], hi = qa[0], share = 0;
    for (std::size_t k = 0; k < qa.size(); ++k) {
      lo = std::min(lo, qa[k]), hi = std::max(hi, qa[k]);
      share += qa[k] / -qin[k] / static_cast<double>(qa.size());
      // The first steps start the split from rest (its time constant is a few steps at small
      // R): the stability measure starts after a tenth of the run.
      if (k >= std::max<std::size_t>(2, qa.size() / 10))
        s.roughness = std::max(s.roughness, std::abs(qa[k] - 2 * qa[k - 1] + qa[k - 2]));
    }
    s.roughness /= hi - lo;
    s.split = share;
  }
  for (double* x : {&s.roughness, &s.split}) core::Comm(ctx.comm).broadcast(*x);
}

void run_case(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::vector<Frequency> frequencies = {{0.5}, {2.0}, {8.0}};
  for (auto& f : frequencies) run_frequency(ctx, f);
  const std::vector<double> resistances =
      ctx.quick ? std::vector<double>{1e7, 1e10} : std::vector<double>{1e7, 1e8, 1e9, 1e10};
  const std::vector<double> capacitances =
      ctx.quick ? std::vector<double>{1e-11, 1e-8} : std::vector<double>{1e-11, 1e-10, 1e-9, 1e-8};
  std::vector<SweepPoint> sweep;
  for (const char* cells : {"hexa", "tetra"}) {
    if (ctx.quick && std::string(cells) == "tetra") continue;
    for (double r : resistances)
      for (double c : capacitances) {
        SweepPoint point;
        point.distal_resistance = r;
        point.capacitance = c;
        point.cells = cells;
        sweep.push_back(point);
      }
  }
  for (auto& s : sweep) run_sweep_point(ctx, s);
  if (rank == 0) {
    std::ofstream csv(ctx.out_dir / "frequencies.csv");
    csv << "omega_tau,amplitude,amplitude_exact,phase,phase_exact,amplitude_error,phase_error,"
           "mean_error\n";
    for (const auto& f : frequencies) {
      const auto z = impedance(f.omega_tau / kTau);
      csv << fmt::format("{},{:.9e},{:.9e},{:.9e},{:.9e},{:.3e},{:.3e},{:.3e}\n", f.omega_tau,
                         f.amplitude, kQa * std::abs(z), f.phase, std::arg(z), f.amplitude_error,
                         f.phase_error, f.mean_error);
    }
    std::ofstream st(ctx.out_dir / "stability.csv");
    st << "cells,distal_resistance,capacitance,finished,roughness,explicit_amplification,"
          "split_xmax,failure\n";
    for (const auto& s : sweep)
      st << fmt::format("{},{:.3e},{:.3e},{},{:.3e},{:.3e},{:.4f},\"{}\"\n", s.cells,
                        s.distal_resistance, s.capacitance, s.finished ? 1 : 0, s.roughness,
                        s.explicit_amplification, s.split, s.failure);
  }
  // Tolerances: the 1 % on amplitude and phase. The exponential integrator with Q
  // linear over a step errs by about (w dt)^2 / 12 = 8e-5 at 200 steps per period.
  for (const auto& f : frequencies) {
    report.add(fmt::format("w tau = {}: outlet pressure amplitude / (Qa |Z|) - 1", f.omega_tau),
               f.amplitude_error, 0, 0.01, Check::at_most);
    report.add(fmt::format("w tau = {}: outlet pressure phase / arg Z - 1", f.omega_tau),
               f.phase_error, 0, 0.01, Check::at_most);
    report.add(fmt::format("w tau = {}: mean outlet pressure / ((R_p + R_d) Q0) - 1", f.omega_tau),
               f.mean_error, 0, 0.01, Check::at_most);
    // P = p_d + R_p Q holds at every step (the law is solved, not lagged): to round-off in
    // outlets.csv's 17 digits.
    report.add(fmt::format("w tau = {}: |P - p_d - R_p Q| / |P| in outlets.csv", f.omega_tau),
               f.law_residual, 0, 1e-13, Check::at_most);
  }
  // Stable: a smooth flux is a sine sampled 200 times a period, second difference (w dt)^2 /2
  // of its range = 5e-4; an instability of the coupling alternates from step to step (order 1).
  for (const auto& s : sweep) {
    const auto label = fmt::format("{} R_d {:.0e} Pa s/m3, C {:.0e} m3/Pa", s.cells,
                                   s.distal_resistance, s.capacitance);
    report.add(label + ": run finished (1 = yes)", s.finished ? 1.0 : 0.0, 1, 0, Check::at_least);
    report.add(label + fmt::format(": flux roughness (explicit coupling's amplification {:.3g})",
                                   s.explicit_amplification),
               s.finished ? s.roughness : 1.0, 0, 1e-2, Check::at_most);
  }
}

}  // namespace

Case rcr_outlet_case() {
  return {"rcr_outlet",
          "Resistance/RCR outlets: the outlet pressure of a pipe against the RCR impedance at "
          "three frequencies, and a stability sweep of R and C with two outlets in parallel",
          run_case};
}

}  // namespace valsalva::validation
