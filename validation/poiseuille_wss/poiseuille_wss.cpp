// Wall shear stress and pressure drop of steady Poiseuille flow in a rigid pipe (Gmsh
// tetrahedra) through the scene-level analysis (io::RunAnalysis: [wall_shear], [pressure_drop]),
// against tau_w = 4 mu Q / (pi R^3) and dp = 8 mu L Q / (pi R^4) (Hagen-Poiseuille). The run
// starts from the exact parabola (the steady discrete state differs from it only by the
// discretisation error) with the Poiseuille inlet profile and a pressure outlet, and runs for
// 3 viscous times R^2 / (j_01^2 nu) so that the start-up difference has decayed below 1e-3 of
// itself; TAWSS is taken over the last half. Levels R/h = 5, 7, 10 (quick: 5, 7); the mean over
// the wall nodes of the middle half of the pipe must be within 2 % on the finest level. Also
// OSI (0 for a steady direction) and the node-to-node scatter of tau_w (the tetrahedra are
// irregular). Table: poiseuille_wss.csv.
#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "flow/dual_metrics.hpp"
#include "flow/local_mesh.hpp"
#include "flow/run_loop.hpp"
#include "io/pipe_generator.hpp"
#include "io/pressure_drop.hpp"
#include "io/run_analysis.hpp"
#include "validation/case.hpp"

namespace valsalva::validation {

namespace {

constexpr double kRadius = 0.005, kLength = 0.03, kRho = 1000, kMu = 0.1, kQ = 2e-6;

struct Level {
  double resolution;  // R / h
  std::int64_t nodes = 0;
  double wss_error = 0, wss_min = 0, wss_max = 0, osi_max = 0, dp_error = 0;
};

void run_level(const Context& ctx, Level& level) {
  const double nu = kMu / kRho;
  const auto mesh = io::generate_pipe_mesh(kRadius, kLength, kRadius / level.resolution);
  const auto metrics = flow::compute_dual_metrics(mesh);
  const auto local = flow::distribute(mesh, metrics, ctx.comm);
  const double viscous_time = kRadius * kRadius / (2.405 * 2.405 * nu);

  flow::RunOptions o;
  o.projection.density = kRho;
  o.projection.viscosity = nu;
  o.projection.poisson.tolerance = 1e-10;
  o.time.end = 3 * viscous_time;
  o.output.print = false;
  auto inlet = flow::boundary_spec("inlet", flow::BoundaryType::inlet);
  inlet.profile = flow::InletProfile::poiseuille;
  inlet.flow_rate.mean = kQ;
  o.boundary = {inlet, flow::boundary_spec("outlet", flow::BoundaryType::pressure_outlet),
                flow::boundary_spec("wall", flow::BoundaryType::wall)};

  io::AnalysisOptions a;
  a.wall_shear.patches = {"wall"};
  a.wall_shear.start_time = 1.5 * viscous_time;
  const double z_up = kLength / 4, z_down = 3 * kLength / 4;
  a.pressure_drops = {
      {"pipe", Eigen::Vector3d(0, 0, z_up), Eigen::Vector3d(0, 0, z_down), 0.5 * kRadius, 1}};
  const auto dir = ctx.out_dir / fmt::format("level_{:g}", level.resolution);
  if (local.comm.root()) std::filesystem::create_directories(dir);
  local.comm.barrier();
  io::RunAnalysis analysis(mesh, metrics, local, a, kRho, kMu, dir, false);

  flow::RunLoop loop(mesh, metrics, local, o);
  flow::FlowState start;  // the exact parabola, mean velocity Q / (pi R^2)
  const double u_max = 2 * kQ / (M_PI * kRadius * kRadius);
  for (int j = 0; j < local.num_local(); ++j) {
    const auto& x = local.position[j];
    const double s = std::min(1.0, std::hypot(x.x(), x.y()) / kRadius);
    start.velocity.emplace_back(0, 0, u_max * (1 - s * s));
    start.pressure.push_back(0.0);
  }
  loop.resume(start, 0);
  flow::RunHooks hooks;
  hooks.after_step = [&](const flow::FlowState& state, std::int64_t step) {
    analysis.sample(state, step);
  };
  loop.set_hooks(hooks);
  const auto& state = loop.state();
  loop.run();
  analysis.finish();

  // Mean tau_w over the wall nodes of the middle half, weighted like the scene's history.
  const auto* wall = analysis.wall_shear();
  const auto tawss = wall->statistics().front().tawss();
  const auto osi = wall->statistics().front().osi();
  double sum = 0, lo = INFINITY, hi = -INFINITY, osi_max = 0;
  std::int64_t n = 0;
  for (std::size_t i = 0; i < tawss.size(); ++i) {
    const auto& x = local.position[wall->nodes().front()[i]];
    if (std::abs(x.z() - kLength / 2) > kLength / 4) continue;
    sum += tawss[i], ++n;
    lo = std::min(lo, tawss[i]), hi = std::max(hi, tawss[i]);
    osi_max = std::max(osi_max, osi[i]);
  }
  const auto& comm = local.comm;
  const double exact = 4 * kMu * kQ / (M_PI * std::pow(kRadius, 3));
  level.nodes = metrics.num_nodes();
  level.wss_error = comm.sum(sum) / double(comm.sum(n)) / exact - 1;
  level.wss_min = -comm.max(-lo) / exact - 1;
  level.wss_max = comm.max(hi) / exact - 1;
  level.osi_max = comm.max(osi_max);
  const io::RegionMean up(local, Eigen::Vector3d(0, 0, z_up), 0.5 * kRadius, "upstream");
  const io::RegionMean down(local, Eigen::Vector3d(0, 0, z_down), 0.5 * kRadius, "downstream");
  const double dp_exact = 8 * kMu * (z_down - z_up) * kQ / (M_PI * std::pow(kRadius, 4));
  level.dp_error = (up(state.pressure) - down(state.pressure)) / dp_exact - 1;
}

}  // namespace

Case poiseuille_wss_case() {
  return {"poiseuille_wss",
          "Wall shear stress, OSI and pressure drop of Poiseuille pipe flow vs Hagen-Poiseuille",
          [](const Context& ctx, Report& report) {
            std::vector<Level> levels{{5}, {7}};
            if (!ctx.quick) levels.push_back({10});
            for (auto& l : levels) run_level(ctx, l);
            int rank = 0;
            MPI_Comm_rank(ctx.comm, &rank);
            if (rank == 0) {
              std::ofstream csv(ctx.out_dir / "poiseuille_wss.csv");
              csv << "r_over_h,nodes,wss_mean_error,wss_min_error,wss_max_error,osi_max,"
                     "dp_error\n";
              for (const auto& l : levels)
                csv << fmt::format("{},{},{:.6e},{:.6e},{:.6e},{:.3e},{:.6e}\n", l.resolution,
                                   l.nodes, l.wss_error, l.wss_min, l.wss_max, l.osi_max,
                                   l.dp_error);
            }
            for (const auto& l : levels) {
              const auto tag = fmt::format("R/h {:g}", l.resolution);
              // Finest level: the 2 %; coarser ones report (measured 4.6 % at R/h 5,
              // 2.3 % at 7: about second order, so a 6 % / 3.5 % bound still catches a loss
              // of order).
              const double tol = l.resolution >= 10 ? 0.02 : l.resolution >= 7 ? 0.035 : 0.06;
              report.add("tawss_mean_error " + tag, l.wss_error, 0, tol);
              report.add("osi_max " + tag, l.osi_max, 0, 1e-3, Check::at_most);
              report.add("pressure_drop_error " + tag, l.dp_error, 0, 0.08);
            }
            const auto& a = levels[0];
            const auto& b = levels[1];
            report.add("tawss_observed_order (R/h 5 -> 7)",
                       std::log(std::abs(a.wss_error / b.wss_error)) /
                           std::log(b.resolution / a.resolution),
                       1.5, 0, Check::at_least);
          }};
}

}  // namespace valsalva::validation
