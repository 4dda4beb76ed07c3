// Scene keys of what a run measures while it runs ([probe.<name>], [probes], [sample.<name>],
// [statistics.<name>], [wall_shear], [pressure_drop.<name>]) and their reader; [section.<name>]
// in scene/scene_keys_sections.cpp. Each section is
// optional: a scene that has none of them computes none of it (analysis/run_analysis.hpp).
#include "scene/scene_keys_analysis.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <regex>
#include <set>

#include "core/allocation_limit.hpp"
#include "mesh/plane_cut.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_keys_sections.hpp"

namespace valsalva::scene {

namespace {

void declare_every_steps(Schema& s, const std::string& table, const std::string& what) {
  s.integer(table + ".every_steps")
      .def(1)
      .at_least(1)
      .unit_of("-")
      .doc("Sample " + what + " every this many time steps");
}

template <class Inside>
bool any_node(const mesh::Mesh& mesh, Inside inside) {
  return std::any_of(mesh.nodes.begin(), mesh.nodes.end(), inside);
}

std::string format_vector(const Eigen::Vector3d& v) {
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", v.x(), v.y(), v.z());
}

// "(x0, y0, z0) to (x1, y1, z1) m": the mesh's bounding box, for a region that misses it.
std::string mesh_span(const mesh::Mesh& mesh) {
  Eigen::Vector3d lo = mesh.nodes.front(), hi = lo;
  for (const auto& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return format_vector(lo) + " to " + format_vector(hi) + " m";
}

}  // namespace

void declare_analysis_keys(Schema& s) {
  s.section("probe.<name>",
            "A point where u, v, w and p are recorded (probes.csv in the run directory, one "
            "column per component, named <name>_u ...); a point outside the mesh is an error.");
  s.real3("probe.<name>.position").required().unit_of("m").doc("Position of the probe");

  s.section("probes", "When the probe points are sampled.");
  declare_every_steps(s, "probes", "the probes");

  const std::string m = "sample.<name>";
  s.section(m,
            "Instantaneous u, v, w, p on a line or a plane of points, one small CSV file per "
            "sample (samples/<name>_<step>.csv); points outside the mesh are left out.");
  s.choice(m + ".type", {"line", "plane"}).required().unit_of("-").doc("Line or plane of points");
  s.real3(m + ".origin").required().unit_of("m").doc("First point (line) or corner (plane)");
  s.real3(m + ".end").required().unit_of("m").doc("Last point of the line");
  s.when(m + ".end", m + ".type", {"line"});
  s.real3(m + ".u").required().unit_of("m").doc("Plane: first edge vector from the origin");
  s.when(m + ".u", m + ".type", {"plane"});
  s.real3(m + ".v").required().unit_of("m").doc("Plane: second edge vector from the origin");
  s.when(m + ".v", m + ".type", {"plane"});
  s.int3(m + ".points")
      .def(std::array{50, 1, 1})
      .at_least(1)
      .unit_of("-")
      .doc("Points along the line (first entry) or along u and v (first two entries)");
  s.real(m + ".interval")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc(
          "Sample every this much simulated time (at the first step at or after it); 0 = every "
          "step");
  s.real(m + ".start_time").def(0.0).at_least(0).unit_of("s").doc("No samples before this time");

  const std::string st = "statistics.<name>";
  s.section(st,
            "Phase-averaged (or plain time-averaged) mean and RMS of u, v, w, p, Reynolds "
            "stresses and k = rho/2 (u'^2 + v'^2 + w'^2), accumulated on the fly, saved in "
            "checkpoints and written at the end (statistics/<name>.xmf, one step per phase bin, "
            "and <name>_phases.csv; on a line statistics/<name>.csv, one row per bin and point). "
            "Memory: 88 bytes per covered node (or line point) and bin.");
  s.real(st + ".period")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc("Cycle period; 0 = plain time average (bins must be 1)");
  s.integer(st + ".bins")
      .def(1)
      .at_least(1)
      .unit_of("-")
      .doc("Phase bins per period; with a fixed time.dt, bins no narrower than dt");
  s.real(st + ".start_time")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc("Samples before this time are ignored; it is phase 0 of cycle 0");
  declare_every_steps(s, st, "the statistics");
  s.real(st + ".write_interval")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc(
          "Also write the statistics files every this much simulated time after start_time "
          "(e.g. one period, to follow the convergence over cycles); 0 = at the end of the run "
          "only. Each write costs about 2-3 time steps per bin on the whole mesh "
          "(docs/analysis.md)");
  s.choice(st + ".region", {"all", "plane", "box", "line", "section"})
      .def("all")
      .unit_of("-")
      .doc(
          "Nodes covered: the whole mesh, a slab around a plane, an axis-aligned box, or the "
          "section of a plane within a box (the nodes of every cell the plane cuts there: what "
          "interpolation on the plane needs, e.g. by `valsalva compare-piv` or `export-piv`); or "
          "points along a line, where u, v, w, p are interpolated from the mesh");
  s.real3(st + ".point").required().unit_of("m").doc("A point of the plane");
  s.when(st + ".point", st + ".region", {"plane", "section"});
  s.real3(st + ".normal").required().unit_of("-").doc("Normal of the plane");
  s.when(st + ".normal", st + ".region", {"plane", "section"});
  s.real(st + ".half_thickness")
      .required()
      .above(0)
      .unit_of("m")
      .doc("Nodes within this distance of the plane are covered (about half a cell)");
  s.when(st + ".half_thickness", st + ".region", {"plane"});
  s.real3(st + ".lo")
      .required()
      .unit_of("m")
      .doc("Lower corner of the box (section: of the window the cut cells must overlap)");
  s.when(st + ".lo", st + ".region", {"box", "section"});
  s.real3(st + ".hi").required().unit_of("m").doc("Upper corner of the box");
  s.when(st + ".hi", st + ".region", {"box", "section"});
  s.real3(st + ".origin").required().unit_of("m").doc("First point of the line");
  s.when(st + ".origin", st + ".region", {"line"});
  s.real3(st + ".end").required().unit_of("m").doc("Last point of the line");
  s.when(st + ".end", st + ".region", {"line"});
  s.integer(st + ".points")
      .def(50)
      .at_least(2)
      .unit_of("-")
      .doc(
          "Evenly spaced points from origin to end (both included); those outside the mesh are "
          "left out (the run log counts them), a line with none inside is an error");
  s.when(st + ".points", st + ".region", {"line"});

  s.section(
      "wall_shear",
      "Wall shear stress tau_w on wall patches (residual-force method, flow/wall_force.hpp), "
      "the area-weighted mean |tau_w| per patch after every sample "
      "(wall_shear_history.csv), and from start_time its time integrals (saved in "
      "checkpoints): TAWSS = mean |tau_w| (Pa), OSI = (1 - |mean tau_w| / TAWSS) / 2 and "
      "RRT = 1 / ((1 - 2 OSI) TAWSS) = 1 / |mean tau_w| (1/Pa, Himburg et al. 2004). At the "
      "end of the run: wall_shear.csv, per wall node (patch, node, x, y, z, area, tawss, osi, "
      "rrt, tau_x, tau_y, tau_z = the last tau_w, support_fraction = the share of the window "
      "the node spent inside an immersed structure's kernel support, where tau_w carries the "
      "spread force and the smeared pressure jump of the structure rather than the flow's "
      "shear); wall_shear_summary.csv, per patch (area, window_start, window_end of the "
      "averaging, area-weighted mean and max of TAWSS and OSI, area-weighted mean RRT over the "
      "nodes where it is defined and the area fraction they cover, and clear_area_fraction, "
      "clear_mean_tawss, clear_max_tawss over the nodes never inside a kernel support), also "
      "printed one line per patch; wall_shear_surface.xmf (+ .h5), the patches' faces with "
      "tawss, osi, rrt, support_fraction, tau, patch and node for ParaView. A node on two "
      "patches (a rim) keeps the viscous part of its reaction but not the other patch's "
      "pressure load. RRT is "
      "undefined (infinite) where the mean tau_w vector is zero (OSI = 1/2 or no shear): "
      "written as nan, which ParaView draws in its NaN colour and leaves out of colour "
      "ranges and pandas/numpy read as NaN. The files are the same at any rank count.");
  s.string_list("wall_shear.patches")
      .def(std::vector<std::string>{})
      .unit_of("-")
      .doc("Wall patches (type = \"wall\") to evaluate; empty = no wall shear stress");
  s.real("wall_shear.start_time")
      .def(0.0)
      .at_least(0)
      .unit_of("s")
      .doc(
          "TAWSS and OSI integrate from this time (e.g. after the first cycles). A restart may "
          "move it past the checkpoint's averaging window (`valsalva run --restart latest --set "
          "wall_shear.start_time=T`): the window then starts afresh at T");
  declare_every_steps(s, "wall_shear", "the wall shear stress");

  const std::string pd = "pressure_drop.<name>";
  s.section(pd,
            "Pressure difference between two spherical regions (volume-weighted mean pressure of "
            "the nodes inside each), e.g. the transvalvular pressure gradient, in Pa and mmHg "
            "(pressure_drop.csv: <name>_upstream, <name>_downstream, <name>_mmHg).");
  s.real3(pd + ".upstream").required().unit_of("m").doc("Centre of the upstream region");
  s.real3(pd + ".downstream").required().unit_of("m").doc("Centre of the downstream region");
  s.real(pd + ".radius").required().above(0).unit_of("m").doc("Radius of both regions");
  declare_every_steps(s, pd, "the pressure difference");
}

Eigen::Vector3d scene_vector(const Scene& scene, const std::string& key) {
  const auto a = scene.get<std::array<double, 3>>(key);
  return {a[0], a[1], a[2]};
}

// Names become file names and CSV columns: keep them plain.
void check_plain_name(const Scene& scene, const std::string& table, const std::string& name) {
  static const std::regex plain("[A-Za-z0-9_]+");
  if (!std::regex_match(name, plain))
    throw scene.error(
        table + "." + name,
        fmt::format("name '{}' has characters other than letters, digits and _", name),
        "[A-Za-z0-9_]+");
}

analysis::AnalysisOptions read_analysis_options(const Scene& scene, const mesh::Mesh& mesh) {
  analysis::AnalysisOptions o;
  for (const auto& name : scene.names("probe")) {
    check_plain_name(scene, "probe", name);
    o.probes.points.push_back({name, scene_vector(scene, "probe." + name + ".position")});
  }
  o.probes.every_steps = scene.get<int>("probes.every_steps");

  for (const auto& name : scene.names("sample")) {
    check_plain_name(scene, "sample", name);
    const std::string k = "sample." + name;
    analysis::SampleOptions s;
    s.name = name;
    s.plane = scene.get<std::string>(k + ".type") == "plane";
    s.origin = scene_vector(scene, k + ".origin");
    const auto n = scene.get<std::array<int, 3>>(k + ".points");
    s.points = {n[0], s.plane ? n[1] : 1};
    // Each point keeps at least its position and u, v, w, p (56 bytes).
    if (const auto problem =
            core::allocation_problem(fmt::format("{} x {} points", s.points[0], s.points[1]),
                                     double(s.points[0]) * s.points[1], 56);
        !problem.empty())
      throw scene.error(k + ".points", problem);
    if (s.plane) {
      s.u = scene_vector(scene, k + ".u");
      s.v = scene_vector(scene, k + ".v");
      if (!(s.u.cross(s.v).norm() > 0))
        throw scene.error(k + ".v", "the plane's edge vectors u and v are parallel or zero");
    } else {
      s.u = scene_vector(scene, k + ".end") - s.origin;
      if (!(s.u.norm() > 0)) throw scene.error(k + ".end", "the line has zero length");
    }
    s.interval = scene.get<double>(k + ".interval");
    s.start_time = scene.get<double>(k + ".start_time");
    o.samples.push_back(s);
  }

  const double rho = scene.get<double>("flow.density");
  for (const auto& name : scene.names("statistics")) {
    check_plain_name(scene, "statistics", name);
    const std::string k = "statistics." + name;
    analysis::StatisticsOptions s;
    s.phase.period = scene.get<double>(k + ".period");
    s.phase.bins = scene.get<int>(k + ".bins");
    if (s.phase.period == 0 && s.phase.bins != 1)
      throw scene.error(k + ".bins", "a plain time average (period = 0) has one bin", "1");
    // A bin narrower than a fixed time step stays empty in most cycles.
    if (const double dt = scene.get<double>("time.dt");
        s.phase.period > 0 && dt > 0 && s.phase.period / s.phase.bins < dt)
      throw scene.error(
          k + ".bins",
          fmt::format("{} bins of period {:g} s are {:.3g} s wide, less than time.dt = {:g} s: "
                      "most bins would get no sample",
                      s.phase.bins, s.phase.period, s.phase.period / s.phase.bins, dt),
          fmt::format("<= period / time.dt = {}", static_cast<long>(s.phase.period / dt)));
    s.phase.start_time = scene.get<double>(k + ".start_time");
    s.phase.density = rho;
    s.phase.name = name;
    s.every_steps = scene.get<int>(k + ".every_steps");
    s.write_interval = scene.get<double>(k + ".write_interval");
    const auto region = scene.get<std::string>(k + ".region");
    s.region = region == "all"       ? analysis::StatisticsOptions::Region::all
               : region == "plane"   ? analysis::StatisticsOptions::Region::plane
               : region == "line"    ? analysis::StatisticsOptions::Region::line
               : region == "section" ? analysis::StatisticsOptions::Region::section
                                     : analysis::StatisticsOptions::Region::box;
    if (s.region == analysis::StatisticsOptions::Region::plane) {
      s.a = scene_vector(scene, k + ".point");
      s.b = scene_vector(scene, k + ".normal");
      if (!(s.b.norm() > 0)) throw scene.error(k + ".normal", "the normal is zero");
      s.half_thickness = scene.get<double>(k + ".half_thickness");
      const Eigen::Vector3d n = s.b.normalized();
      if (!any_node(mesh, [&](const Eigen::Vector3d& x) {
            return std::abs((x - s.a).dot(n)) <= s.half_thickness;
          }))
        throw scene.error(
            k + ".point",
            fmt::format("the plane through {} (normal {}, half thickness {:g} m) "
                        "misses the mesh: no node within reach; the mesh spans {}",
                        format_vector(s.a), format_vector(s.b), s.half_thickness, mesh_span(mesh)),
            "a point of a plane through the mesh");
    } else if (s.region == analysis::StatisticsOptions::Region::box) {
      s.a = scene_vector(scene, k + ".lo");
      s.b = scene_vector(scene, k + ".hi");
      if (!(s.a.array() < s.b.array()).all())
        throw scene.error(k + ".hi",
                          "the box's upper corner must exceed its lower corner in x, "
                          "y and z");
      if (!any_node(mesh, [&](const Eigen::Vector3d& x) {
            return (x.array() >= s.a.array()).all() && (x.array() <= s.b.array()).all();
          }))
        throw scene.error(k + ".lo",
                          fmt::format("the box {} to {} holds no node of the mesh; the mesh "
                                      "spans {}",
                                      format_vector(s.a), format_vector(s.b), mesh_span(mesh)),
                          "a box overlapping the mesh");
    } else if (s.region == analysis::StatisticsOptions::Region::section) {
      s.a = scene_vector(scene, k + ".point");
      s.b = scene_vector(scene, k + ".normal");
      s.lo = scene_vector(scene, k + ".lo");
      s.hi = scene_vector(scene, k + ".hi");
      if (!(s.b.norm() > 0)) throw scene.error(k + ".normal", "the normal is zero");
      if (!(s.lo.array() < s.hi.array()).all())
        throw scene.error(k + ".hi",
                          "the window's upper corner must exceed its lower corner in x, y and z");
      if (mesh::cells_cut_by_plane(mesh, s.a, s.b, s.lo, s.hi).empty())
        throw scene.error(
            k + ".point",
            fmt::format("the plane through {} (normal {}) cuts no mesh cell within the window "
                        "{} to {}; the mesh spans {}",
                        format_vector(s.a), format_vector(s.b), format_vector(s.lo),
                        format_vector(s.hi), mesh_span(mesh)),
            "a plane through the mesh inside the window");
    } else if (s.region == analysis::StatisticsOptions::Region::line) {
      s.line = {scene_vector(scene, k + ".origin"), scene_vector(scene, k + ".end"),
                scene.get<int>(k + ".points")};
      if (!((s.line.end - s.line.origin).norm() > 0))
        throw scene.error(k + ".end", "the line has zero length (end = origin)",
                          "a point other than origin");
    }
    o.statistics.push_back(s);
  }

  const auto patches = scene.get<std::vector<std::string>>("wall_shear.patches");
  if (!patches.empty()) {
    for (const auto& p : patches) {
      const bool is_wall = scene.has("boundary." + p + ".type") &&
                           scene.get<std::string>("boundary." + p + ".type") == "wall";
      if (mesh.patch_index(p) < 0 || !is_wall)
        throw scene.error("wall_shear.patches",
                          fmt::format("'{}' is not a wall patch of the scene", p),
                          "patches with a [boundary.<patch>] table of type = \"wall\"");
    }
    o.wall_shear.patches = patches;
    o.wall_shear.start_time = scene.get<double>("wall_shear.start_time");
    o.wall_shear.every_steps = scene.get<int>("wall_shear.every_steps");
  }

  for (const auto& name : scene.names("pressure_drop")) {
    check_plain_name(scene, "pressure_drop", name);
    const std::string k = "pressure_drop." + name;
    o.pressure_drops.push_back(
        {name, scene_vector(scene, k + ".upstream"), scene_vector(scene, k + ".downstream"),
         scene.get<double>(k + ".radius"), scene.get<int>(k + ".every_steps")});
  }
  o.sections = read_section_options(scene);
  return o;
}

}  // namespace valsalva::scene
