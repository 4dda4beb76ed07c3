#include "app/command_close_leaflets.hpp"

#include <fmt/format.h>
#include <mpi.h>
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>

#include "io/solid_gmsh_writer.hpp"
#include "valve/leaflet_closing.hpp"
#include "valve/leaflet_mesh.hpp"
#include "valve/valve_geometry.hpp"

namespace valsalva::app {

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string leaflets, out;
  double annulus_radius = 0;
  bool overwrite = false;
  valve::ClosingOptions closing;
};

fs::path report_path(const fs::path& out) {
  fs::path p = out;
  p.replace_extension(".closing.toml");
  return p;
}

fs::path holes_path(const fs::path& out) {
  fs::path p = out;
  p.replace_extension(".orifice.csv");
  return p;
}

// The grid cells of the annulus disc no leaflet covers, to draw the holes of a closed valve.
void write_holes(const fs::path& path, const structure::OrificeArea& orifice) {
  std::ofstream csv(path);
  csv << "# uncovered cells of the annulus disc (polar grid " << orifice.rings << " x "
      << orifice.sectors << "), in the annulus plane's axes\nx_m,y_m,area_m2\n";
  for (const auto& c : orifice.uncovered)
    csv << fmt::format("{:.6e},{:.6e},{:.6e}\n", c.centre.x(), c.centre.y(), c.area);
  if (!csv) throw std::runtime_error("close-leaflets: cannot write " + path.string());
}

toml::array vec(const structure::Vec3& v) {
  return toml::array{v.x(), v.y(), v.z()};
}

const char* coaptation_name(const valve::ClosingOptions& o) {
  if (!o.contact) return "none";
  switch (o.coaptation) {
    case valve::Coaptation::none:
      return "none";
    case valve::Coaptation::leaflets:
      return "leaflets";
    case valve::Coaptation::planes:
      return "planes";
  }
  return "?";
}

toml::table report_table(const Options& o, const valve::ClosingResult& r) {
  const auto& n = r.newton;
  toml::table t{
      {"leaflets_file", o.leaflets},
      {"pressure_Pa", o.closing.pressure},
      {"converged", n.converged},
      {"load_steps", n.steps},
      {"newton_iterations", n.iterations},
      {"step_cuts", n.cuts},
      {"final_relative_residual", n.last_residuals.empty() ? -1.0 : n.last_residuals.back()},
      {"linear_solver", n.solver},
      {"seconds", r.seconds},
      {"thickness_m", r.thickness},
      {"coaptation_height_m", r.pairs.coaptation_height},
      {"min_mid_surface_distance_m", r.pairs.min_distance},
      {"crossing_triangle_pairs", r.pairs.crossings},
      {"orifice_area_m2", r.orifice.area},
      {"orifice_raster_error_m2", r.orifice.raster_error},
      {"opening_ratio", r.orifice.opening_ratio},
      {"max_von_mises_Pa", r.stress.max},
      {"von_mises_p99_Pa", r.stress.at_percentile},
      {"max_von_mises_element", r.stress.max_element},
      {"max_von_mises_position_m", vec(r.stress.max_position)},
      {"max_von_mises_leaflet", r.max_stress_leaflet + 1},
      {"max_von_mises_distance_to_attachment_m", r.max_stress_to_attachment},
      {"contact", o.closing.contact},
      {"coaptation", coaptation_name(o.closing)}};
  if (o.closing.contact) {
    const auto& c = n.contact;
    t.insert("contact_clearance_m", o.closing.contact_options.clearance);
    t.insert("contact_min_gap_m", std::isfinite(c.min_gap) ? c.min_gap : 1.0);
    t.insert("contact_force_N", c.force);
    t.insert("contact_area_m2", c.area);
    t.insert("contact_max_pressure_Pa", c.max_pressure);
  }
  toml::array mids;
  for (std::size_t k = 0; k < r.free_edge_midpoints.size(); ++k) {
    const auto& m = r.free_edge_midpoints[k];
    mids.push_back(toml::table{
        {"leaflet", int(k) + 1}, {"node", m.node}, {"radius_m", m.radial}, {"axial_m", m.axial}});
  }
  t.insert("free_edge_midpoint", mids);
  toml::array pairs;
  for (const auto& p : r.pairs.pairs)
    pairs.push_back(toml::table{{"leaflets", toml::array{p.a + 1, p.b + 1}},
                                {"crossings", p.crossings},
                                {"crossing_at_m", vec(p.crossing_at)},
                                {"min_distance_m", p.min_distance},
                                {"coaptation_height_m", p.coaptation_height}});
  t.insert("pair", pairs);
  return t;
}

void print_summary(const valve::ClosingResult& r) {
  const auto& n = r.newton;
  fmt::print(
      "close-leaflets: {} leaflets, {} load steps, {} Newton iterations, {} cuts, {:.1f} s\n",
      r.leaflets.size(), n.steps, n.iterations, n.cuts, r.seconds);
  for (std::size_t k = 0; k < r.free_edge_midpoints.size(); ++k)
    fmt::print("  leaflet {}: free-edge midpoint at radius {:.3f} mm, height {:.3f} mm\n", k + 1,
               1e3 * r.free_edge_midpoints[k].radial, 1e3 * r.free_edge_midpoints[k].axial);
  fmt::print(
      "  coaptation height {:.3f} mm; smallest mid-surface distance {:.4f} mm "
      "(thickness {:.4f} mm); {} crossing triangle pairs\n",
      1e3 * r.pairs.coaptation_height, 1e3 * r.pairs.min_distance, 1e3 * r.thickness,
      r.pairs.crossings);
  for (const auto& p : r.pairs.pairs)
    if (p.crossings)
      fmt::print(
          "  leaflets {} and {} cross ({} triangle pairs) about r = {:.3f} mm, z = {:.3f} mm\n",
          p.a + 1, p.b + 1, p.crossings, 1e3 * std::hypot(p.crossing_at.x(), p.crossing_at.y()),
          1e3 * p.crossing_at.z());
  fmt::print(
      "  geometric orifice area {:.4g} mm^2 (raster error {:.2g} mm^2), opening ratio {:.4g}\n",
      1e6 * r.orifice.area, 1e6 * r.orifice.raster_error, r.orifice.opening_ratio);
  if (const auto& c = r.newton.contact; !c.surfaces.empty())
    fmt::print(
        "  contact: smallest gap {:.4g} mm ({:.2f} % of the thickness), force {:.4g} N, "
        "area {:.4g} mm^2, largest pressure {:.4g} kPa\n",
        1e3 * c.min_gap, 100 * c.min_gap / r.thickness, c.force, 1e6 * c.area,
        1e-3 * c.max_pressure);
  fmt::print(
      "  largest von Mises stress {:.4g} MPa (Gauss points; 99th percentile {:.4g} MPa) in "
      "element {} of leaflet {}, {:.3f} mm from the attachment\n",
      1e-6 * r.stress.max, 1e-6 * r.stress.at_percentile, r.stress.max_element,
      r.max_stress_leaflet + 1, 1e3 * r.max_stress_to_attachment);
}

// The frame's inner radius from valve.toml beside the leaflet mesh (make-valve writes both).
double annulus_from_valve_toml(const fs::path& leaflets) {
  const fs::path toml = leaflets.parent_path() / "valve.toml";
  if (!fs::exists(toml))
    throw std::invalid_argument(
        fmt::format("close-leaflets: no {} beside the leaflet mesh: give --annulus-radius (metres)",
                    toml.string()));
  const valve::ValveGeometry g = valve::read_valve_toml(toml);
  return g.root_radius() - g.frame_thickness;
}

int run(const Options& o) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return 0;
  const fs::path out(o.out), report = report_path(out), holes = holes_path(out);
  if (out.extension() != ".msh")
    throw std::invalid_argument(fmt::format("close-leaflets: --out {}: give a .msh file", o.out));
  for (const fs::path& p : {out, report, holes})
    if (fs::exists(p) && !o.overwrite)
      throw std::invalid_argument(
          fmt::format("close-leaflets: {} exists (give --overwrite to replace it)", p.string()));
  const structure::SolidMesh mesh = valve::read_valve_leaflets(o.leaflets);
  structure::ValveFrame frame;
  frame.annulus_radius =
      o.annulus_radius > 0 ? o.annulus_radius : annulus_from_valve_toml(o.leaflets);
  const valve::ClosingResult r = valve::close_leaflets(mesh, frame, o.closing);
  if (!r.newton.converged)
    throw std::runtime_error(fmt::format(
        "close-leaflets: {}: the closing did not converge (reached {:.4g} of {} Pa after {} load "
        "steps): {}; nothing written",
        o.leaflets, r.newton.load_factor, o.closing.pressure, r.newton.steps, r.newton.diagnosis));
  print_summary(r);
  io::write_moved_solid_gmsh(o.leaflets, r.newton.x, out);
  std::ofstream(report) << report_table(o, r) << "\n";
  write_holes(holes, r.orifice);
  fmt::print("close-leaflets: wrote {}, {} and {}\n", out.string(), report.string(),
             holes.string());
  return 0;
}

}  // namespace

CLI::App* add_close_leaflets(CLI::App& cli, std::function<int()>& action) {
  auto o = std::make_shared<Options>();
  auto* c = cli.add_subcommand("close-leaflets",
                               "Close manufactured leaflets by a pressure on their aortic faces");
  c->add_option("leaflets", o->leaflets, "Leaflet mesh (valsalva make-valve's leaflets.msh)")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("--out", o->out, "Closed leaflet mesh to write (.msh)")->required();
  c->add_option("--pressure", o->closing.pressure,
                "Pressure on the aortic faces [Pa] (default 12400, 93 mmHg)");
  c->add_option("--annulus-radius", o->annulus_radius,
                "Radius of the annulus disc for the orifice area [m] (default: the frame's inner "
                "radius from valve.toml beside the leaflet mesh)");
  c->add_option("--load-steps", o->closing.load_steps, "Initial pressure increments (default 10)");
  c->add_option("--shear-modulus", o->closing.shear_modulus, "Neo-Hookean G [Pa] (2.4e6)");
  c->add_option("--bulk-modulus", o->closing.bulk_modulus, "Neo-Hookean K [Pa] (1.6e6)");
  c->add_flag("!--no-contact", o->closing.contact, "Let the leaflets pass through each other");
  const std::map<std::string, valve::Coaptation> coaptations{
      {"leaflets", valve::Coaptation::leaflets}, {"planes", valve::Coaptation::planes}};
  c->add_option("--coaptation", o->closing.coaptation,
                "How the leaflets are kept apart: planes (default: each leaflet against the planes "
                "through the axis and its commissures, where a symmetric valve's leaflets meet) or "
                "leaflets (every pair of leaflets in contact, for valves that are not symmetric)")
      ->transform(CLI::CheckedTransformer(coaptations, CLI::ignore_case));
  c->add_option("--penalty-factor", o->closing.contact_options.penalty_factor,
                "Contact penalty eps = factor * E / h (default 100)");
  c->add_option("--contact-smoothing", o->closing.contact_options.smoothing,
                "Width of the penalty's C1 smoothing near zero gap, as a fraction of the face size "
                "(default 0: none)")
      ->check(CLI::Range(0.0, 0.999));
  c->add_option("--contact-clearance", o->closing.contact_options.clearance,
                "Distance the leaflets are held apart where they coapt [m] (default 0: they touch; "
                "an FSI run needs about the fluid mesh size, docs/valve.md)")
      ->check(CLI::NonNegativeNumber);
  c->add_flag("--overwrite", o->overwrite, "Replace CLOSED.msh and its report");
  c->add_flag("--verbose", o->closing.verbose, "Print the Newton iterations");
  action = [o] { return run(*o); };
  return c;
}

}  // namespace valsalva::app
