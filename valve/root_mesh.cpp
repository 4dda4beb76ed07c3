#include "valve/root_mesh.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "mesh/gmsh_reader.hpp"

namespace valsalva::valve {

namespace {

namespace occ = gmsh::model::occ;
constexpr double pi = 3.14159265358979323846;
// Loft sections of the sinus region: spacing along z and spline points per section.
constexpr double kSectionSpacing = 2e-3;
constexpr int kSectionPoints = 24;

// Radial depth of the frame inside the root wall (see the header).
double bury(const ValveGeometry& g) {
  return std::min(0.5e-3, 0.25 * g.root_radius());
}

// z of the first loft section: below every point of the frame's top edge.
double loft_start(const ValveGeometry& g) {
  return 0.5 * g.ring_height;
}

// Largest frame top near theta (the posts' side faces are vertical).
double frame_top_near(const ValveGeometry& g, double theta) {
  const double d = 1e-6;
  return std::max({g.frame_top(theta - d), g.frame_top(theta), g.frame_top(theta + d)});
}

int circle_wire(double z, double r) {
  return occ::addWire({occ::addCircle(0, 0, z, r)}, -1, true);
}

// Closed periodic spline through r_wall(theta_j, z), starting at theta = 0 like addCircle.
int section_wire(const ValveGeometry& g, double z, int points) {
  std::vector<int> tags;
  for (int j = 0; j < points; ++j) {
    const double th = 2 * pi * j / points, r = g.wall_radius(th, z);
    tags.push_back(occ::addPoint(r * std::cos(th), r * std::sin(th), z));
  }
  tags.push_back(tags.front());
  return occ::addWire({occ::addSpline(tags)}, -1, true);
}

// The lumen up to the STJ (inflow cylinder and sinus loft), and the STJ-to-outlet part (cone and
// aorta): the frame is cut from the first only (booleans with the loft are the slow part).
struct Lumen {
  gmsh::vectorpair valve, aorta;
};

Lumen lumen(const ValveGeometry& g) {
  const double R = g.root_radius(), z0 = loft_start(g), H = g.sinus_height;
  Lumen l;
  l.valve.push_back({3, occ::addCylinder(0, 0, g.inlet_z(), 0, 0, z0 - g.inlet_z(), R)});
  // Sections every 2 mm (the bulge varies over the sinus height as sin^2), joined by ruled
  // surfaces: smooth lofts make the frame cut several times slower.
  const int n = std::max(8, int(std::ceil((H - z0) / kSectionSpacing)));
  std::vector<int> wires{circle_wire(z0, R)};
  for (int k = 1; k < n; ++k)
    wires.push_back(section_wire(g, z0 + (H - z0) * k / n, kSectionPoints));
  wires.push_back(circle_wire(H, g.stj_diameter / 2));
  gmsh::vectorpair sinus;
  occ::addThruSections(wires, sinus, -1, true, true);
  l.valve.insert(l.valve.end(), sinus.begin(), sinus.end());
  const double Rs = g.stj_diameter / 2, Ra = g.aorta_diameter / 2, Lt = g.aorta_transition_length;
  l.aorta.push_back({3, std::abs(Rs - Ra) < 1e-9 * Ra ? occ::addCylinder(0, 0, H, 0, 0, Lt, Ra)
                                                      : occ::addCone(0, 0, H, 0, 0, Lt, Rs, Ra)});
  l.aorta.push_back({3, occ::addCylinder(0, 0, H + Lt, 0, 0, g.outlet_z() - H - Lt, Ra)});
  return l;
}

// Region above the scallop of leaflet i, as a loft through radial rectangles.
int scallop_cutter(const ValveGeometry& g, int i) {
  const double R = g.root_radius(), r0 = R - g.frame_thickness - 0.5e-3, r1 = R + bury(g) + 0.5e-3;
  const double top = g.post_height + 1e-3, c = g.leaflet_centre_angle(i), s = g.leaflet_span();
  const int n = 16;
  std::vector<int> wires;
  for (int k = 0; k <= n; ++k) {
    const double th = c + s * (double(k) / n - 0.5);
    const double za = g.frame_top(th + (k == 0 ? 1e-9 : k == n ? -1e-9 : 0));
    const double cx = std::cos(th), cy = std::sin(th);
    const int p[4] = {occ::addPoint(r0 * cx, r0 * cy, za), occ::addPoint(r1 * cx, r1 * cy, za),
                      occ::addPoint(r1 * cx, r1 * cy, top), occ::addPoint(r0 * cx, r0 * cy, top)};
    wires.push_back(occ::addWire({occ::addLine(p[0], p[1]), occ::addLine(p[1], p[2]),
                                  occ::addLine(p[2], p[3]), occ::addLine(p[3], p[0])},
                                 -1, true));
  }
  gmsh::vectorpair out;
  occ::addThruSections(wires, out, -1, true, false);
  return out.at(0).second;
}

gmsh::vectorpair frame(const ValveGeometry& g) {
  const double R = g.root_radius();
  const int outer = occ::addCylinder(0, 0, 0, 0, 0, g.post_height, R + bury(g));
  const int inner = occ::addCylinder(0, 0, 0, 0, 0, g.post_height, R - g.frame_thickness);
  gmsh::vectorpair tube, out;
  std::vector<gmsh::vectorpair> map;
  occ::cut({{3, outer}}, {{3, inner}}, tube, map);
  gmsh::vectorpair cutters;
  for (int i = 0; i < 3; ++i) cutters.push_back({3, scallop_cutter(g, i)});
  occ::cut(tube, cutters, out, map);
  return out;
}

// Patch name of boundary surface `tag` from all its mesh nodes (boundary nodes included).
std::string classify(const ValveGeometry& g, int tag) {
  std::vector<std::size_t> nodes;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(nodes, xyz, param, 2, tag, true, false);
  const double eps = 1e-6 * g.root_diameter;
  bool inlet = true, outlet = true, on = true;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const double x = xyz[3 * n], y = xyz[3 * n + 1], z = xyz[3 * n + 2];
    inlet = inlet && std::abs(z - g.inlet_z()) < eps;
    outlet = outlet && std::abs(z - g.outlet_z()) < eps;
    on = on && on_frame(g, x, y, z, 10 * eps);
  }
  if (nodes.empty()) return "wall";
  return inlet ? "inlet" : outlet ? "outlet" : on ? "frame" : "wall";
}

// mesh_size inside the valve region, far_mesh_size outside, linear over two far sizes between
// (a Gmsh Box field as background size; the smaller of it and the boundary sizes wins).
void set_valve_region_size(const ValveGeometry& g) {
  namespace field = gmsh::model::mesh::field;
  const int box = field::add("Box");
  const double r = g.refined_region_radius();
  field::setNumber(box, "VIn", g.mesh_size);
  field::setNumber(box, "VOut", g.fluid_far_size());
  field::setNumber(box, "XMin", -r);
  field::setNumber(box, "XMax", r);
  field::setNumber(box, "YMin", -r);
  field::setNumber(box, "YMax", r);
  field::setNumber(box, "ZMin", g.refined_region_z_min());
  field::setNumber(box, "ZMax", g.refined_region_z_max());
  field::setNumber(box, "Thickness", 2 * g.fluid_far_size());
  field::setAsBackgroundMesh(box);
}

}  // namespace

bool on_frame(const ValveGeometry& g, double x, double y, double z, double tol) {
  const double r = std::hypot(x, y), R = g.root_radius();
  return r >= R - g.frame_thickness - tol && r <= R + bury(g) + tol && z >= -tol &&
         z <= frame_top_near(g, std::atan2(y, x)) + tol;
}

double fluid_volume(const ValveGeometry& g) {
  const double R = g.root_radius(), H = g.sinus_height, z0 = g.ring_height;
  const int nt = 1440, nz = 800;
  double sinus = 0;
  for (int i = 0; i < nt; ++i) {
    const double th = 2 * pi * (i + 0.5) / nt;
    for (int k = 0; k < nz; ++k) {
      const double r = g.wall_radius(th, z0 + (H - z0) * (k + 0.5) / nz);
      sinus += 0.5 * r * r;
    }
  }
  sinus *= (2 * pi / nt) * ((H - z0) / nz);
  const double Rs = g.stj_diameter / 2, Ra = g.aorta_diameter / 2, Lt = g.aorta_transition_length;
  const double cone = pi * Lt * (Rs * Rs + Rs * Ra + Ra * Ra) / 3;
  const double aorta = pi * Ra * Ra * (g.outlet_z() - H - Lt);
  const double inflow = pi * R * R * (z0 + g.inlet_length);
  const double scallop_mean =
      g.ring_height + (g.free_edge_z() - g.commissure_attachment - g.ring_height) / 3;
  const double top_integral =
      3 * (g.post_width() * g.post_height + g.leaflet_span() * scallop_mean);
  const double Ri = R - g.frame_thickness;
  const double frame = 0.5 * (R * R - Ri * Ri) * top_integral;
  return inflow + sinus + cone + aorta - frame;
}

RootMeshSummary write_root_mesh(const std::filesystem::path& file, const ValveGeometry& g) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string source = file.string();
  RootMeshSummary s;
  mesh::GmshSession session;
  gmsh::vectorpair fluid;
  mesh::gmsh_call(source + ": building the root geometry (OpenCASCADE)", [&] {
    gmsh::model::add("valve_root");
    const Lumen lum = lumen(g);
    const gmsh::vectorpair fr = frame(g);
    gmsh::vectorpair cut;
    std::vector<gmsh::vectorpair> map;
    occ::cut(lum.valve, fr, cut, map);
    occ::fuse(cut, lum.aorta, fluid, map);
    occ::synchronize();
  });
  if (fluid.empty())
    throw mesh::MeshFileError(source + ": cutting the frame out of the lumen left no fluid volume");
  for (const auto& [dim, tag] : fluid) {
    double v = 0;
    occ::getMass(dim, tag, v);
    s.cad_volume += v;
  }
  auto since = [](auto t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  s.cad_seconds = since(t0);
  mesh::gmsh_call(source + ": meshing the root", [&] {
    gmsh::option::setNumber("Mesh.MeshSizeMax", g.fluid_far_size());
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
    if (g.fluid_far_size() > g.mesh_size) set_valve_region_size(g);
    const auto t1 = std::chrono::steady_clock::now();
    mesh::generate_deterministic_mesh(2);
    s.surface_seconds = since(t1);
    const auto t2 = std::chrono::steady_clock::now();
    mesh::generate_deterministic_mesh(3);
    s.volume_seconds = since(t2);
  });
  mesh::gmsh_call(source + ": writing", [&] {
    gmsh::vectorpair boundary;
    gmsh::model::getBoundary(fluid, boundary, true, false, false);
    std::map<std::string, std::vector<int>> patches;
    for (const auto& [dim, tag] : boundary)
      patches[classify(g, std::abs(tag))].push_back(std::abs(tag));
    for (const char* name : {"inlet", "outlet", "wall", "frame"}) {
      if (patches[name].empty())
        throw mesh::MeshFileError(
            fmt::format("{}: no boundary surface classified as '{}'", source, name));
      const int pg = gmsh::model::addPhysicalGroup(2, patches[name]);
      gmsh::model::setPhysicalName(2, pg, name);
    }
    std::vector<int> volumes;
    for (const auto& [dim, tag] : fluid) volumes.push_back(tag);
    const int pv = gmsh::model::addPhysicalGroup(3, volumes);
    gmsh::model::setPhysicalName(3, pv, "fluid");
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(4, tags, nodes);
    s.tetrahedra = tags.size();
    std::sort(nodes.begin(), nodes.end());
    s.nodes = std::size_t(std::unique(nodes.begin(), nodes.end()) - nodes.begin());
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 1);
    gmsh::write(source);
  });
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace valsalva::valve
