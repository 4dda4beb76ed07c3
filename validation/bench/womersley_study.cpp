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
//   into split prism layers, io/extruded_pipe_generator.hpp, graded by --wall_size/--bl_*)
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

#include "validation/bench/bench_util.hpp"
#include "validation/womersley/womersley_run.hpp"
#include "validation/womersley_periodic/periodic_run.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, status = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  try {
    const auto o = valsalva::bench::parse_options(
        argc, argv, {"wo",          "npd",         "cfl",       "tol",           "length",
                     "damping",     "stiffness",   "outlet",    "csv",           "period",
                     "unscaled",    "periodic",    "split",     "mesh_stats",    "algorithm3d",
                     "size_factor", "flux_driven", "wall_size", "wall_distance", "extruded",
                     "dz",          "bl_first",    "bl_ratio",  "bl_thickness"});
    const auto get = [&](const char* key, const char* def) {
      return o.count(key) ? o.at(key) : std::string(def);
    };
    valsalva::validation::WomersleySetup s;
    s.womersley = std::stod(get("wo", "17"));
    s.nodes_per_diameter = std::stod(get("npd", "10"));
    s.mesh_size_factor = std::stod(get("size_factor", "1"));
    s.mesh.algorithm3d = std::stoi(get("algorithm3d", "1"));
    s.mesh.wall_size = std::stod(get("wall_size", "0"));
    s.mesh.wall_distance = std::stod(get("wall_distance", "0"));
    s.extruded = get("extruded", "0") != "0";
    s.layer_height = std::stod(get("dz", "1"));
    s.grading.wall_size = s.mesh.wall_size, s.grading.wall_distance = s.mesh.wall_distance;
    s.grading.layer_first = std::stod(get("bl_first", "0"));
    s.grading.layer_ratio = std::stod(get("bl_ratio", "1.2"));
    s.grading.layer_thickness = std::stod(get("bl_thickness", "0"));
    s.length_in_diameters = std::stod(get("length", "2"));
    if (get("mesh_stats", "0") != "0") {
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
      MPI_Finalize();
      return 0;
    }
    if (get("periodic", "0") != "0") {
      // The streamwise-periodic pipe (validation/womersley_periodic), same resolution and cfl.
      valsalva::validation::PeriodicSetup p;
      p.womersley = std::stod(get("wo", "17"));
      p.nodes_per_diameter = std::stod(get("npd", "10"));
      p.cfl = std::stod(get("cfl", "0.4"));
      p.split = get("split", "0") != "0";
      p.flux_driven = get("flux_driven", "0") != "0";
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
        const std::string csv = get("csv", "");
        std::ofstream f(csv.empty() ? "/dev/null" : csv);
        f << "time,x,y,z,r,u,u_exact,ux,uy,u_peak,radius,length,h\n";
        for (std::size_t i = 0; i + 3 < r.samples.size(); i += 4)
          f << fmt::format("{:.6f},0,0,0,{:.6e},{:.9e},{:.9e},0,0,{:.9e},{:.9e},0,{:.9e}\n",
                           r.samples[i], r.samples[i + 1], r.samples[i + 2], r.samples[i + 3],
                           r.u_peak, r.radius, r.h);
      }
      MPI_Finalize();
      return 0;
    }
    s.cfl = std::stod(get("cfl", "0.4"));
    s.poisson_tolerance = std::stod(get("tol", "1e-10"));
    s.pressure_damping = get("damping", "1") != "0";
    s.stiffness_viscous = get("stiffness", "0") != "0";
    s.sample_period = std::stoi(get("period", "3"));
    s.unscaled_inlet = get("unscaled", "0") != "0";
    const std::string outlet = get("outlet", "pressure");
    if (outlet != "pressure" && outlet != "convective")
      throw std::invalid_argument("--outlet " + outlet + ": expected pressure or convective");
    s.outlet = outlet == "convective" ? valsalva::flow::BoundaryType::convective_outlet
                                      : valsalva::flow::BoundaryType::pressure_outlet;
    const std::string csv = get("csv", "");
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
  } catch (const std::exception& e) {
    if (rank == 0) fmt::print(stderr, "bench_womersley_study: {}\n", e.what());
    status = 2;
  }
  MPI_Finalize();
  return status;
}
