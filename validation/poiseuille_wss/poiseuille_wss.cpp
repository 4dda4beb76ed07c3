// Wall shear stress and pressure drop of steady Poiseuille flow in a rigid pipe (Gmsh
// tetrahedra): validation/poiseuille_wss/poiseuille_wss.toml through run::Simulation, its
// [wall_shear] output (wall_shear.csv) and the final pressure,
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

#include "analysis/pressure_drop.hpp"
#include "core/comm.hpp"
#include "core/numeric_table.hpp"
#include "run/simulation.hpp"
#include "scene/scene.hpp"
#include "validation/case.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double kRadius = 0.005, kLength = 0.03, kRho = 1000, kMu = 0.1, kQ = 2e-6;

struct Level {
  double resolution;  // R / h
  std::int64_t nodes = 0;
  double wss_error = 0, wss_min = 0, wss_max = 0, osi_max = 0, dp_error = 0;
};

void run_level(const Context& ctx, Level& level) {
  const double z_up = kLength / 4, z_down = 3 * kLength / 4;
  const auto dir = ctx.out_dir / fmt::format("level_{:g}", level.resolution);
  const double u_max = 2 * kQ / (M_PI * kRadius * kRadius);
  // The scene (validation/poiseuille_wss/poiseuille_wss.toml) at this level, through
  // run::Simulation; started from the exact parabola, mean velocity Q / (pi R^2).
  const auto scene =
      scene::load_scene(case_scene("poiseuille_wss", "poiseuille_wss.toml"),
                        {fmt::format("mesh.pipe.size={:.17g}", kRadius / level.resolution)});
  run::Simulation sim(scene, level_request(dir), ctx.comm);
  sim.set_initial_velocity([&](const Eigen::Vector3d& x) {
    const double s = std::min(1.0, std::hypot(x.x(), x.y()) / kRadius);
    return Eigen::Vector3d(0, 0, u_max * (1 - s * s));
  });
  sim.run();
  const auto& local = sim.local();
  const auto& comm = local.comm;
  const analysis::RegionMean up(local, Eigen::Vector3d(0, 0, z_up), 0.5 * kRadius, "upstream");
  const analysis::RegionMean down(local, Eigen::Vector3d(0, 0, z_down), 0.5 * kRadius,
                                  "downstream");
  const double dp_exact = 8 * kMu * (z_down - z_up) * kQ / (M_PI * std::pow(kRadius, 4));
  level.dp_error = (up(sim.state().pressure) - down(sim.state().pressure)) / dp_exact - 1;
  level.nodes = sim.metrics().num_nodes();
  // Mean TAWSS over the wall nodes of the middle half, from the run's wall_shear.csv.
  if (comm.rank() == 0) {
    // patch (a name), node, x, y, z, area, tawss, osi, rrt, tau_x, tau_y, tau_z,
    // support_fraction: the numbers read strictly.
    core::TableLines lines(dir / "wall_shear.csv", {});
    std::vector<double> z, tawss, osi;
    for (bool header = true; lines.next(); header = false) {
      const auto fields = lines.fields();
      if (header || fields.size() != 13) {
        if (!header) throw lines.error(1, "expected 13 columns");
        continue;
      }
      z.push_back(lines.number(fields[4], "z"));
      tawss.push_back(lines.number(fields[6], "tawss"));
      osi.push_back(lines.number(fields[7], "osi"));
    }
    const double exact = 4 * kMu * kQ / (M_PI * std::pow(kRadius, 3));
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    int n = 0;
    for (std::size_t i = 0; i < z.size(); ++i) {
      if (std::abs(z[i] - kLength / 2) > kLength / 4) continue;
      sum += tawss[i], ++n;
      lo = std::min(lo, tawss[i]), hi = std::max(hi, tawss[i]);
      level.osi_max = std::max(level.osi_max, osi[i]);
    }
    level.wss_error = sum / n / exact - 1;
    level.wss_min = lo / exact - 1;
    level.wss_max = hi / exact - 1;
  }
  for (double* x : {&level.wss_error, &level.wss_min, &level.wss_max, &level.osi_max})
    core::Comm(ctx.comm).broadcast(*x);
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
