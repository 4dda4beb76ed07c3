// Study tool (not a test): one inlet-driven Womersley pipe run (validation/womersley/
// womersley_run.hpp) with the set-up choices open, printing per phase the slab error and the
// mean flux over the middle third of the run and of the exact nodal values against Q(t); with
// --csv FILE every node's sample (t, x, y, z, r, u_z, u_exact, u_x, u_y) at the 8 phases.
// --periodic 1: the streamwise-periodic pipe instead (validation/womersley_periodic; --split 1
// tetrahedra, --flux_driven 1 a flow-rate driven run). --mesh_stats 1: node density and edge
// lengths of the Gmsh pipe and of the extruded disk, no run. Used to find where the D/20 error
// of validation/womersley sits (its header has the findings).
//   bench_womersley_study [--wo 17] [--npd 10] [--cfl 0.4] [--tol 1e-10] [--length 2]
//                         [--damping 1] [--stiffness 0] [--outlet pressure|convective]
//                         [--unscaled 0] [--size_factor 1] [--wall_size 0 --wall_distance 0]
//                         [--algorithm3d 1] [--period 3] [--csv FILE]
//                         [--extruded 0 [--dz 1] [--bl_first 0 --bl_ratio 1.2 --bl_thickness 0]]
//   (--size_factor scales Gmsh's size D / npd; wall sizes, the layer height --dz and the
//   boundary-layer rows --bl_* are in units of that scaled size; --extruded 1: the disk extruded
//   into split prism layers, mesh/extruded_pipe_generator.hpp, graded by --wall_size/--bl_*)
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
#include "validation/bench/periodic_run.hpp"
#include "validation/bench/womersley_run.hpp"

namespace {

namespace bench = valsalva::bench;

// The command line (defaults as in the header).
struct Args {
  double wo = 17, npd = 10, cfl = 0.4, tol = 1e-10, length = 2, size_factor = 1;
  double wall_size = 0, wall_distance = 0, dz = 1, bl_first = 0, bl_ratio = 1.2, bl_thickness = 0;
  int period = 3, algorithm3d = 1;
  bool damping = true, stiffness = false, unscaled = false, periodic = false, split = false;
  bool mesh_stats = false, flux_driven = false, extruded = false;
  std::string outlet = "pressure", csv;
};

void add_options(bench::App& app, Args& a) {
  const auto& positive = bench::positive;
  const auto& non_negative = bench::non_negative;
  app.add_option("--wo", a.wo, "Womersley number")->check(positive);
  app.add_option("--npd", a.npd, "Nodes per diameter (h = D / npd)")->check(positive);
  app.add_option("--cfl", a.cfl, "CFL number of the time step")->check(positive);
  app.add_option("--tol", a.tol, "Poisson tolerance")->check(positive);
  app.add_option("--length", a.length, "Pipe length in diameters")->check(positive);
  app.add_option("--damping", a.damping, "Pressure damping");
  app.add_option("--stiffness", a.stiffness, "Stiffness (P1) viscous weights");
  app.add_option("--outlet", a.outlet, "Outlet condition")
      ->check(CLI::IsMember({"pressure", "convective"}));
  app.add_option("--csv", a.csv, "Write every node's sample at the 8 phases to this file");
  app.add_option("--period", a.period, "Sampled period, 0-based (3: the 4th)")->check(non_negative);
  app.add_option("--unscaled", a.unscaled, "Inlet profile not rescaled to the discrete flow rate");
  app.add_option("--periodic", a.periodic, "The streamwise-periodic pipe instead");
  app.add_option("--split", a.split, "Periodic pipe: tetrahedra split from prisms");
  app.add_option("--flux_driven", a.flux_driven, "Periodic pipe: flow-rate driven");
  app.add_option("--mesh_stats", a.mesh_stats, "Node density and edge lengths of the mesh, no run");
  app.add_option("--algorithm3d", a.algorithm3d,
                 "Gmsh Mesh.Algorithm3D (1 Delaunay, 4 Frontal, 10 HXT)")
      ->check(CLI::IsMember({1, 3, 4, 7, 9, 10}));
  app.add_option("--size_factor", a.size_factor, "Factor on Gmsh's size D / npd")->check(positive);
  app.add_option("--wall_size", a.wall_size, "Mesh size at the wall (scaled size; 0: uniform)")
      ->check(non_negative);
  app.add_option("--wall_distance", a.wall_distance, "Distance of the wall grading (scaled size)")
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

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::App app{"bench_womersley_study",
                 "One inlet-driven (or periodic) Womersley pipe run with the set-up choices "
                 "open, or the edge lengths of its mesh"};
  add_options(app, args);
  return bench::mpi_main(app, argc, argv, [&](int rank, int) {
    valsalva::validation::WomersleySetup s;
    s.womersley = args.wo;
    s.nodes_per_diameter = args.npd;
    s.mesh_size_factor = args.size_factor;
    s.mesh.algorithm3d = args.algorithm3d;
    s.mesh.wall_size = args.wall_size;
    s.mesh.wall_distance = args.wall_distance;
    s.extruded = args.extruded;
    s.layer_height = args.dz;
    s.grading.wall_size = s.mesh.wall_size, s.grading.wall_distance = s.mesh.wall_distance;
    s.grading.layer_first = args.bl_first;
    s.grading.layer_ratio = args.bl_ratio;
    s.grading.layer_thickness = args.bl_thickness;
    s.length_in_diameters = args.length;
    if (args.mesh_stats) {
      // The run's mesh, no run: node density and edge lengths / h (h = D / npd), the nodes of
      // the sampled slab |z - L/2| <= h/2 and the nodes per diameter an equilateral section
      // triangulation with that many nodes would have (extruded: the slab is one layer).
      const auto m = valsalva::validation::womersley_mesh(s, MPI_COMM_WORLD);
      const double R = valsalva::validation::womersley_radius(s.womersley);
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
      return;
    }
    if (args.periodic) {
      // The streamwise-periodic pipe (validation/womersley_periodic), same resolution and cfl.
      valsalva::validation::PeriodicSetup p;
      p.womersley = args.wo;
      p.nodes_per_diameter = args.npd;
      p.cfl = args.cfl;
      p.split = args.split;
      p.flux_driven = args.flux_driven;
      const auto r = valsalva::validation::run_periodic_womersley(p, MPI_COMM_WORLD);
      if (rank == 0) {
        fmt::print(
            "womersley_study periodic: D/{} split {} flux-driven {}: {} nodes, max {:.4f} L2 "
            "{:.4f}\n",
            p.nodes_per_diameter, p.split, p.flux_driven, r.nodes, r.max_error, r.l2_error);
        const double a = std::numbers::pi * r.radius * r.radius * r.u_peak;
        for (std::size_t i = 0; i < r.flow_rate.size(); ++i)
          fmt::print(
              "  phase {}: (Q - mean flux) / (pi R^2 u_peak): run {:+.4f}, exact nodal {:+.4f}\n",
              i, (r.flow_rate[i] - r.mean_flux[i]) / a,
              (r.flow_rate[i] - r.exact_mean_flux[i]) / a);
        std::ofstream f(args.csv.empty() ? "/dev/null" : args.csv);
        f << "time,x,y,z,r,u,u_exact,ux,uy,u_peak,radius,length,h\n";
        for (std::size_t i = 0; i + 3 < r.samples.size(); i += 4)
          f << fmt::format("{:.6f},0,0,0,{:.6e},{:.9e},{:.9e},0,0,{:.9e},{:.9e},0,{:.9e}\n",
                           r.samples[i], r.samples[i + 1], r.samples[i + 2], r.samples[i + 3],
                           r.u_peak, r.radius, r.h);
      }
      return;
    }
    s.cfl = args.cfl;
    s.poisson_tolerance = args.tol;
    s.pressure_damping = args.damping;
    s.stiffness_viscous = args.stiffness;
    s.sample_period = args.period;
    s.unscaled_inlet = args.unscaled;
    const std::string& outlet = args.outlet;
    s.outlet = outlet == "convective" ? valsalva::flow::BoundaryType::convective_outlet
                                      : valsalva::flow::BoundaryType::pressure_outlet;
    const std::string& csv = args.csv;
    s.sample_whole_pipe = !csv.empty();
    const auto r = valsalva::validation::run_womersley(s, MPI_COMM_WORLD);
    if (rank == 0) {
      fmt::print(
          "womersley_study: Wo {} D/{} cfl {} tol {:g} L {} D damping {} stiffness {} outlet {} "
          "unscaled inlet {} size factor {} wall size {} over {} extruded {} (dz {}, rows {} x "
          "{} to {}): {} nodes, {} steps dt {:.3e}, max {:.4f} L2 {:.4f} transverse {:.4f}, "
          "{:.0f} s\n",
          s.womersley, s.nodes_per_diameter, s.cfl, s.poisson_tolerance, s.length_in_diameters,
          s.pressure_damping, s.stiffness_viscous, outlet, s.unscaled_inlet, s.mesh_size_factor,
          s.mesh.wall_size, s.mesh.wall_distance, s.extruded, s.layer_height, s.grading.layer_first,
          s.grading.layer_ratio, s.grading.layer_thickness, r.nodes, r.steps, r.dt, r.max_error,
          r.l2_error, r.transverse, r.wall);
      for (const auto& p : r.phases)
        fmt::print(
            "  t {:.4f}: max {:.4f} L2 {:.4f} transverse {:.4f}; (Q - mean flux) / (pi R^2 "
            "u_peak): run {:+.4f}, exact nodal {:+.4f}\n",
            p.time, p.max_error, p.l2_error, p.transverse,
            (p.flow_rate - p.mean_flux) / (std::numbers::pi * r.radius * r.radius * r.u_peak),
            (p.flow_rate - p.exact_mean_flux) /
                (std::numbers::pi * r.radius * r.radius * r.u_peak));
      if (!csv.empty()) {
        std::ofstream f(csv);
        f << "time,x,y,z,r,u,u_exact,ux,uy,u_peak,radius,length,h\n";
        for (const auto& p : r.phases)
          for (std::size_t i = 0; i < p.r.size(); ++i)
            f << fmt::format(
                "{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.9e},{:.9e},{:.6e},{:.6e},"
                "{:.9e},{:.9e},{:.9e},{:.9e}\n",
                p.time, p.x[i], p.y[i], p.z[i], p.r[i], p.u[i], p.exact[i], p.ux[i], p.uy[i],
                r.u_peak, r.radius, r.length, r.h);
      }
    }
  });
}
