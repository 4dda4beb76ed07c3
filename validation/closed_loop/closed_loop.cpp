// Lumped inlets (issue 22), through run::Simulation with the case's scene files:
// 1. pressure_pipe.toml: a straight pipe between a pressure_inlet and a pressure_outlet at 0.
//    Steady p_in: the developed flux against Poiseuille's pi R^4 dp / (8 mu L). Sine p_in =
//    p0 + pa sin(w t): the flux over the last period, fitted by a + b sin + c cos, against
//    Womersley's for the pressure gradient (p_in - 0) / L (flow/womersley.hpp).
// 2. closed_loop.toml: an elastance_inlet ventricle, the pipe, an rcr_outlet whose distal flow
//    returns to the ventricle. V + C p_d (outlets.csv) from cycle to cycle: conserved; the
//    end-diastolic volume V(k T): periodic.
#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "flow/womersley.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double kPi = std::numbers::pi;
// pressure_pipe.toml
constexpr double kRadius = 0.005, kLength = 0.03, kRho = 1000, kMu = 0.1, kDp = 1.0;
constexpr double kAmplitude = 0.5, kSinePeriod = 0.5;  // Pa, s (the sine level)
// closed_loop.toml
constexpr double kCycle = 0.5, kCapacitance = 1e-9;

double poiseuille_flux(double dp) {
  return kPi * std::pow(kRadius, 4) * dp / (8 * kMu * kLength);
}

// The complex flux amplitude of Womersley flow under the pressure difference amplitude dp_h
// (p_in - p_out = Re[dp_h e^{i w t}]): G_h = dp_h / (rho L), Qh = G_h pi R^2 (1 - 2 J1(L) /
// (L J0(L))) / (i w), L = i^{3/2} Wo (the inverse of Womersley::pressure_gradient).
std::complex<double> womersley_flux(std::complex<double> dp_h, double omega) {
  const double wo = kRadius * std::sqrt(omega * kRho / kMu);
  const std::complex<double> l = std::pow(std::complex<double>(0, 1), 1.5) * wo;
  const auto shape = 1.0 - 2.0 * flow::bessel_j1(l) / (l * flow::bessel_j0(l));
  return dp_h / (kRho * kLength) * kPi * kRadius * kRadius * shape / std::complex<double>(0, omega);
}

struct Table {
  std::vector<double> t, q_in, volume, distal;
};

Table read_outlets(const std::filesystem::path& file, bool ventricle) {
  const auto table = core::read_numeric_table(file, core::TableHeader::required);
  Table out{table.column("time"), table.column("flux_inlet"), {}, {}};
  if (ventricle) {
    out.volume = table.column("volume_inlet");
    out.distal = table.column("distal_pressure_outlet");
  }
  return out;
}

void broadcast(MPI_Comm comm, std::initializer_list<double*> values) {
  for (double* x : values) core::Comm(comm).broadcast(*x);
}

// The steady inflow / Poiseuille's - 1 on a pipe of mesh size `size`.
double steady_error(const Context& ctx, int rank, double size, double dt) {
  const auto dir = ctx.out_dir / "runs" / fmt::format("steady_h{}", size);
  run_scene_file(case_scene("closed_loop", "pressure_pipe.toml"),
                 {fmt::format("mesh.pipe.size={}", size), fmt::format("time.dt={}", dt)}, dir,
                 ctx.comm);
  double error = 0;
  if (rank == 0)
    error = -read_outlets(dir / "outlets.csv", false).q_in.back() / poiseuille_flux(kDp) - 1;
  broadcast(ctx.comm, {&error});
  return error;
}

void pressure_pipe(const Context& ctx, int rank, Report& report) {
  const double omega = 2 * kPi / kSinePeriod;
  const auto sine_dir = ctx.out_dir / "runs" / "sine";
  run_scene_file(case_scene("closed_loop", "pressure_pipe.toml"),
                 {"boundary.inlet.pressure_waveform=\"sine\"",
                  fmt::format("boundary.inlet.pressure_amplitude={}", kAmplitude),
                  fmt::format("boundary.inlet.pressure_period={}", kSinePeriod),
                  fmt::format("time.end={}", 2 * kSinePeriod)},
                 sine_dir, ctx.comm);
  double amplitude = 0, phase = 0, mean = 0;
  if (rank == 0) {
    const auto s = read_outlets(sine_dir / "outlets.csv", false);
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k < s.t.size(); ++k) {
      if (s.t[k] <= s.t.back() - kSinePeriod * (1 - 1e-9)) continue;
      const Eigen::Vector3d basis(1, std::sin(omega * s.t[k]), std::cos(omega * s.t[k]));
      normal += basis * basis.transpose();
      rhs += basis * -s.q_in[k];
    }
    const Eigen::Vector3d abc = normal.ldlt().solve(rhs);
    mean = abc[0] / poiseuille_flux(kDp) - 1;
    // b sin + c cos = Re[(c - i b) e^{i w t}]
    const std::complex<double> measured(abc[2], -abc[1]);
    const auto exact = womersley_flux(std::complex<double>(0, -kAmplitude), omega);
    amplitude = std::abs(measured) / std::abs(exact) - 1;
    phase = std::arg(measured / exact);
  }
  broadcast(ctx.comm, {&amplitude, &phase, &mean});
  // Tolerance: the flux of the P1 field through the polygonal section of a tetrahedral pipe
  // falls short by O(h^2) (poiseuille_pipe: 0.80 % at D/16 on prisms, order 1.9); on this Gmsh
  // pipe the full level measures the order from D/8 to D/12. 8 % bounds that deficit at D/8
  // (README). The inflow stabilisation removes the inlet's momentum flux, a loss of about
  // (4/3) rho U^2 = Re R / (12 L) dp = 1.4e-3 dp here (Re 0.1).
  const double coarse = steady_error(ctx, rank, 0.00125, 1.25e-3);
  report.add("steady, h = D/8: inflow / (pi R^4 dp / (8 mu L)) - 1", coarse, 0, 0.08,
             Check::within);
  if (!ctx.quick) {
    const double fine = steady_error(ctx, rank, 0.00125 / 1.5, 5.5e-4);
    report.add("steady, h = D/12: inflow / Poiseuille's - 1", fine, 0, 0.04, Check::within);
    report.add("steady: order of the flux deficit, D/8 -> D/12",
               std::log(coarse / fine) / std::log(1.5), 1.5, 0, Check::at_least);
  }
  report.add("sine, h = D/8: mean inflow / Poiseuille's - 1", mean, 0, 0.08, Check::within);
  // The oscillating profile (flatter at Wo 1.8) has its own O(h^2) deficit: 10 % for the
  // amplitude itself; divided by the steady run's ratio, the mesh's conductance deficit drops
  // out to first order and what remains is the Womersley dynamics (2 %).
  report.add("sine, h = D/8: inflow amplitude / Womersley's - 1", amplitude, 0, 0.1, Check::within);
  report.add("sine, h = D/8: (amplitude / Womersley's) / (steady inflow / Poiseuille's) - 1",
             (1 + amplitude) / (1 + coarse) - 1, 0, 0.02, Check::within);
  // Phase: Womersley's lag at Wo 1.8 is 0.44 rad behind the pressure; the discrete one differs
  // by the mesh's O(h^2) and the time step's O((w dt)^2).
  report.add("sine, h = D/8: inflow phase - Womersley's, rad", phase, 0, 0.05, Check::within);
}

void closed_loop(const Context& ctx, int rank, Report& report) {
  const int cycles = 4;
  const auto dir = ctx.out_dir / "runs" / "closed_loop";
  run_scene_file(case_scene("closed_loop", "closed_loop.toml"),
                 {fmt::format("time.end={}", cycles * kCycle)}, dir, ctx.comm);
  double drift = 0, periodic = 0, swing = 0, ejection = 0;
  if (rank == 0) {
    const auto s = read_outlets(dir / "outlets.csv", true);
    auto total = [&](std::size_t k) { return s.volume[k] + kCapacitance * s.distal[k]; };
    std::vector<std::size_t> starts;  // rows at t = k T (end-diastole)
    for (std::size_t k = 0; k < s.t.size(); ++k)
      if (std::abs(s.t[k] / kCycle - std::round(s.t[k] / kCycle)) < 1e-6) starts.push_back(k);
    for (std::size_t c = 1; c < starts.size(); ++c)
      drift = std::max(drift, std::abs(total(starts[c]) - total(starts[c - 1])) / total(0));
    const std::size_t a = starts[starts.size() - 2], b = starts.back();
    double lo = s.volume[a], hi = s.volume[a];
    for (std::size_t k = a; k <= b; ++k)
      lo = std::min(lo, s.volume[k]), hi = std::max(hi, s.volume[k]);
    swing = hi - lo;
    ejection = swing / s.volume[a];
    periodic = std::abs(s.volume[b] - s.volume[a]) / swing;
  }
  broadcast(ctx.comm, {&drift, &periodic, &swing, &ejection});
  // V + C p_d changes over a step by dt/2 times the sum of the two patches' fluxes at both ends
  // of the step, the mass imbalance after the mass correction (round-off); 1e-8 is the issue's.
  report.add("closed loop: max per-cycle |d(V + C p_d)| / (V + C p_d)(0)", drift, 0, 1e-8,
             Check::at_most);
  report.add("closed loop: |V(4T) - V(3T)| / stroke volume (periodic state)", periodic, 0, 1e-3,
             Check::at_most);
  report.add("closed loop: ejection fraction of the last cycle (> 0: the ventricle pumps)",
             ejection, 0.05, 0, Check::at_least);
}

void run_case(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  pressure_pipe(ctx, rank, report);
  closed_loop(ctx, rank, report);
}

}  // namespace

Case closed_loop_case() {
  return {"closed_loop",
          "Lumped inlets: a pressure_inlet pipe against Poiseuille and Womersley, and a closed "
          "loop (elastance ventricle, pipe, RCR with venous return): volume conservation and a "
          "periodic state",
          run_case};
}

}  // namespace valsalva::validation
