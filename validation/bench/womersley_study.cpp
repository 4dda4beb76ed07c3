// Study tool (not a test): one inlet-driven Womersley pipe run (validation/bench/
// womersley_run.hpp: the scene of validation/womersley with overrides, run by run::Simulation)
// with the set-up choices open, printing per phase the slab error and the
// mean flux over the middle third of the run and of the exact nodal values against Q(t); with
// --csv FILE every node's sample (t, x, y, z, r, u_z, u_exact, u_x, u_y) at the 8 phases.
// --periodic 1: the streamwise-periodic pipe instead (a level of validation/womersley_periodic,
// 4 periods; --split 1 tetrahedra, --flux_driven 1 its flow-rate drive, forcing.type =
// flow_rate). --mesh_stats 1: node density and edge
// lengths of the Gmsh pipe and of the extruded disk, no run. Used to find where the D/20 error
// of validation/womersley sits (its header has the findings).
//   bench_womersley_study [--wo 17] [--npd 10] [--cfl 0.4] [--tol 1e-10] [--length 2]
//                         [--stiffness 0] [--outlet pressure|convective] [--les none]
//                         [--size_factor 1] [--period 3] [--csv FILE]
//                         [--extruded 0 [--dz 1] [--wall_size 0 --wall_distance 0]
//                                       [--bl_first 0 --bl_ratio 1.2 --bl_thickness 0]]
//   (--size_factor scales Gmsh's size D / npd; wall sizes, the layer height --dz and the
//   boundary-layer rows --bl_* are in units of that scaled size; --extruded 1: the disk extruded
//   into split prism layers, mesh/extruded_pipe_generator.hpp, graded by --wall_size/--bl_*;
//   every choice is a scene key of validation/womersley/womersley*.toml)
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

#include "validation/bench/bench_cli.hpp"
#include "validation/bench/womersley_run.hpp"
#include "validation/scene_run.hpp"
#include "validation/womersley_periodic/womersley_periodic_scene.hpp"

namespace {

namespace bench = valsalva::bench;

// The command line (defaults as in the header).
struct Args {
  double wo = 17, npd = 10, cfl = 0.4, tol = 1e-10, length = 2, size_factor = 1;
  double wall_size = 0, wall_distance = 0, dz = 1, bl_first = 0, bl_ratio = 1.2, bl_thickness = 0;
  int period = 3;
  bool stiffness = false, periodic = false, split = false;
  bool mesh_stats = false, flux_driven = false, extruded = false;
  std::string outlet = "pressure", les = "none", csv;
};

void add_options(bench::App& app, Args& a) {
  const auto& positive = bench::positive;
  const auto& non_negative = bench::non_negative;
  app.add_option("--wo", a.wo, "Womersley number")->check(positive);
  app.add_option("--npd", a.npd, "Nodes per diameter (h = D / npd)")->check(positive);
  app.add_option("--cfl", a.cfl, "CFL number of the time step")->check(positive);
  app.add_option("--tol", a.tol, "Poisson tolerance")->check(positive);
  app.add_option("--length", a.length, "Pipe length in diameters")->check(positive);
  app.add_option("--stiffness", a.stiffness, "Stiffness (P1) viscous weights");
  app.add_option("--outlet", a.outlet, "Outlet condition")
      ->check(CLI::IsMember({"pressure", "convective"}));
  app.add_option("--les", a.les, "LES model (les.model)")
      ->check(CLI::IsMember({"none", "sigma", "wale", "smagorinsky"}));
  app.add_option("--csv", a.csv, "Write every node's sample at the 8 phases to this file");
  app.add_option("--period", a.period, "Sampled period, 0-based (3: the 4th)")->check(non_negative);
  app.add_option("--periodic", a.periodic, "The streamwise-periodic pipe instead");
  app.add_option("--split", a.split, "Periodic pipe: tetrahedra split from prisms");
  app.add_option("--flux_driven", a.flux_driven, "Periodic pipe: flow-rate driven");
  app.add_option("--mesh_stats", a.mesh_stats, "Node density and edge lengths of the mesh, no run");
  app.add_option("--size_factor", a.size_factor, "Factor on Gmsh's size D / npd")->check(positive);
  app.add_option("--wall_size", a.wall_size,
                 "Extruded: mesh size at the wall (scaled size; 0: uniform)")
      ->check(non_negative);
  app.add_option("--wall_distance", a.wall_distance,
                 "Extruded: distance of the wall grading (scaled size)")
      ->check(non_negative);
  app.add_option("--extruded", a.extruded, "The disk extruded into split prism layers");
  app.add_option("--dz", a.dz, "Extruded: layer height (scaled size)")->check(positive);
  app.add_option("--bl_first", a.bl_first, "Extruded: first boundary-layer row (0: none)")
      ->check(non_negative);
  app.add_option("--bl_ratio", a.bl_ratio, "Extruded: boundary-layer growth ratio")
      ->check(positive);
  app.add_option("--bl_thickness", a.bl_thickness, "Extruded: boundary-layer thickness")
      ->check(non_negative);
}

// The run's mesh, no run (time.end = 0): node density and edge lengths / h (h = D / npd), the
// nodes of the sampled slab |z - L/2| <= h/2 and the nodes per diameter an equilateral section
// triangulation with that many nodes would have (extruded: the slab is one layer).
void print_mesh_stats(const valsalva::validation::WomersleySetup& s, int rank) {
  namespace validation = valsalva::validation;
  auto overrides = validation::womersley_setup_overrides(s);
  overrides.push_back("time.end=0");
  validation::SceneRun measure;
  measure.at_start = [&](const valsalva::run::Simulation& sim) {
    const auto& m = sim.mesh();
    const double R = validation::womersley_radius(s.womersley);
    const double h = 2 * R / s.nodes_per_diameter, L = s.length_in_diameters * 2 * R;
    std::set<std::pair<long, long>> edges;
    for (long c = 0; c < m.num_cells(); ++c) {
      const auto n = m.cell(c);
      for (std::size_t a = 0; a < n.size(); ++a)
        for (std::size_t b = a + 1; b < n.size(); ++b)
          edges.insert({std::min(n[a], n[b]), std::max(n[a], n[b])});
    }
    std::vector<double> len, section;  // all edges, edges within a z = const section
    for (const auto& [a, b] : edges) {
      const auto d = m.nodes[a] - m.nodes[b];
      len.push_back(d.norm() / h);
      if (std::abs(d.z()) < 1e-12 * R) section.push_back(d.norm() / h);
    }
    std::sort(len.begin(), len.end());
    std::sort(section.begin(), section.end());
    long slab = 0;
    for (const auto& x : m.nodes) slab += std::abs(x.z() - L / 2) <= h / 2;
    const double area = std::numbers::pi * R * R;
    if (rank == 0)
      fmt::print(
          "{}: {} nodes ({:.3f} per h^3), edges / h: median {:.3f} p10 {:.3f} p90 {:.3f}, "
          "D / median edge {:.1f}; in-section edges median {:.3f}; slab {} nodes, "
          "equilateral-section nodes per diameter {:.1f}\n",
          m.source, m.num_nodes(), m.num_nodes() / (area * L) * h * h * h, len[len.size() / 2],
          len[len.size() / 10], len[9 * len.size() / 10],
          s.nodes_per_diameter / len[len.size() / 2],
          section.empty() ? 0.0 : section[section.size() / 2], slab,
          2 * R * std::sqrt(std::sqrt(3.0) / 2 * slab / area));
  };
  validation::run_scene_file(validation::womersley_scene(s), overrides, {}, MPI_COMM_WORLD,
                             measure);
}

void run_periodic(const Args& args, int rank) {
  // A level of the case validation/womersley_periodic, same resolution and cfl.
  namespace validation = valsalva::validation;
  validation::PeriodicLevel p;
  p.npd = args.npd, p.cfl = args.cfl, p.split = args.split, p.flow_rate = args.flux_driven;
  p.les = args.les, p.periods = 4;
  const auto exact = validation::periodic_womersley_exact(args.wo);
  const auto r = validation::run_periodic_level(p, exact, {}, MPI_COMM_WORLD);
  if (rank != 0) return;
  fmt::print(
      "womersley_study periodic: D/{} split {} flux-driven {}: {} nodes, {} steps dt {:.3e}, "
      "max {:.4f} L2 {:.4f} transverse {:.2e}, {:.0f} s\n",
      p.npd, p.split, p.flow_rate, r.nodes, r.steps, r.dt, r.max_error, r.l2_error, r.transverse,
      r.wall);
  const double a = std::numbers::pi * exact.radius * exact.radius * r.u_peak;
  for (std::size_t i = 0; i < r.phase_time.size(); ++i) {
    const double q = exact.mean * (1 + std::sin(2 * std::numbers::pi * r.phase_time[i]));
    fmt::print("  phase {}: (Q - mean flux) / (pi R^2 u_peak): run {:+.4f}, exact nodal {:+.4f}\n",
               i, (q - r.mean_flux[i]) / a, (q - r.exact_mean_flux[i]) / a);
  }
  std::ofstream f(args.csv.empty() ? "/dev/null" : args.csv);
  f << "time,x,y,z,r,u,u_exact,ux,uy,u_peak,radius,length,h\n";
  for (std::size_t i = 0; i + 3 < r.samples.size(); i += 4)
    f << fmt::format("{:.6f},0,0,0,{:.6e},{:.9e},{:.9e},0,0,{:.9e},{:.9e},0,{:.9e}\n", r.samples[i],
                     r.samples[i + 1], r.samples[i + 2], r.samples[i + 3], r.u_peak, exact.radius,
                     2 * exact.radius / p.npd);
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::App app{"bench_womersley_study",
                 "One inlet-driven (or periodic) Womersley pipe run with the set-up choices "
                 "open, or the edge lengths of its mesh"};
  add_options(app, args);
  return bench::mpi_main(app, argc, argv, [&](int rank, int) {
    if (args.periodic) return run_periodic(args, rank);
    valsalva::validation::WomersleySetup s;
    s.womersley = args.wo;
    s.nodes_per_diameter = args.npd;
    s.mesh_size_factor = args.size_factor;
    s.extruded = args.extruded;
    if (!s.extruded && (args.wall_size > 0 || args.wall_distance > 0))
      throw std::invalid_argument("--wall_size and --wall_distance grade the extruded pipe only");
    s.layer_height = args.dz;
    s.wall_size = args.wall_size, s.wall_distance = args.wall_distance;
    s.layer_first = args.bl_first;
    s.layer_ratio = args.bl_ratio;
    s.layer_thickness = args.bl_thickness;
    s.length_in_diameters = args.length;
    s.cfl = args.cfl;
    s.poisson_tolerance = args.tol;
    s.stiffness_viscous = args.stiffness;
    s.sample_period = args.period;
    s.les_model = args.les;
    s.outlet = args.outlet == "convective" ? "convective_outlet" : "pressure_outlet";
    if (args.mesh_stats) return print_mesh_stats(s, rank);
    const std::string& csv = args.csv;
    s.sample_whole_pipe = !csv.empty();
    const auto r = valsalva::validation::run_womersley(s, MPI_COMM_WORLD);
    if (rank != 0) return;
    fmt::print(
        "womersley_study: Wo {} D/{} cfl {} tol {:g} L {} D stiffness {} outlet {} les {} size "
        "factor {} extruded {} (dz {}, wall size {} over {}, rows {} x {} to {}): {} nodes, {} "
        "steps dt {:.3e}, max {:.4f} L2 {:.4f} transverse {:.4f}, {:.0f} s\n",
        s.womersley, s.nodes_per_diameter, s.cfl, s.poisson_tolerance, s.length_in_diameters,
        s.stiffness_viscous, args.outlet, s.les_model, s.mesh_size_factor, s.extruded,
        s.layer_height, s.wall_size, s.wall_distance, s.layer_first, s.layer_ratio,
        s.layer_thickness, r.nodes, r.steps, r.dt, r.max_error, r.l2_error, r.transverse, r.wall);
    if (s.les_model != "none")
      fmt::print(
          "  nu_sgs / nu (last RK stage of each step): max {:.4g} mean {:.4g} middle third "
          "{:.4g}\n",
          r.max_nu_ratio, r.mean_nu_ratio, r.interior_nu_ratio);
    const double a = std::numbers::pi * r.radius * r.radius * r.u_peak;
    for (const auto& p : r.phases)
      fmt::print(
          "  t {:.4f}: max {:.4f} L2 {:.4f} transverse {:.4f}; (Q - mean flux) / (pi R^2 "
          "u_peak): run {:+.4f}, exact nodal {:+.4f}\n",
          p.time, p.max_error, p.l2_error, p.transverse, (p.flow_rate - p.mean_flux) / a,
          (p.flow_rate - p.exact_mean_flux) / a);
    if (csv.empty()) return;
    std::ofstream f(csv);
    f << "time,x,y,z,r,u,u_exact,ux,uy,u_peak,radius,length,h\n";
    for (const auto& p : r.phases)
      for (std::size_t i = 0; i < p.r.size(); ++i)
        f << fmt::format(
            "{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.9e},{:.9e},{:.6e},{:.6e},"
            "{:.9e},{:.9e},{:.9e},{:.9e}\n",
            p.time, p.x[i], p.y[i], p.z[i], p.r[i], p.u[i], p.exact[i], p.ux[i], p.uy[i], r.u_peak,
            r.radius, r.length, r.h);
  });
}
