// A coarse valve (mesh_size 3 mm) through make_valve: the three files, the fluid patches and
// region, the fluid volume and the inlet area against the parametrisation, the attachment check,
// and the refusal to overwrite. Linear tetrahedra inscribed in a wall of radius R with edges h
// miss a fraction of about (h/R)^2 / 6 of the volume and of a circular section's area (the
// inscribed-polygon deficit, 1 - sin(x)/x ~ x^2/6 for the angle x = h/R per edge): the
// tolerance below, 0.96 % at 3 mm.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "io/gmsh_reader.hpp"
#include "io/mesh_info.hpp"
#include "valve/leaflet_mesh.hpp"
#include "valve/make_valve.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

TEST_CASE("make_valve at 3 mm: files, patches, volume, attachment") {
  const fs::path dir = "test_output/make_valve_3mm";
  fs::remove_all(dir);
  const auto g = valve::parse_valve_settings({"mesh_size=3e-3"});
  const valve::MakeValveResult r = valve::make_valve(dir, g, false);
  for (const char* f : {"valve.toml", "leaflets.msh", "root.msh"})
    CHECK(fs::is_regular_file(dir / f));
  CHECK(!fs::exists(dir / "root.partial.msh"));
  CHECK(r.leaflet_elements == 45);
  MESSAGE("3 mm root: " << r.root.tetrahedra << " tetrahedra, " << r.root.seconds << " s");

  const flow::Mesh mesh = io::read_gmsh(dir / "root.msh");
  const io::MeshInfo info = io::summarize_mesh(mesh);
  CHECK(info.cells == flow::GlobalIndex(r.root.tetrahedra));
  REQUIRE(info.regions.size() == 1);
  CHECK(info.regions[0].first == "fluid");
  std::map<std::string, double> area;
  for (const auto& p : info.patches) {
    CHECK(p.faces > 0);
    area[p.name] = p.area;
  }
  CHECK(area.size() == 4);
  for (const char* name : {"inlet", "outlet", "wall", "frame"}) CHECK(area.count(name));

  const double R = g.root_radius(), tol = std::pow(g.mesh_size / R, 2) / 6;
  const double exact = valve::fluid_volume(g);
  MESSAGE("fluid volume: mesh " << info.volume << ", CAD " << r.root.cad_volume
                                << ", parametrisation " << exact);
  CHECK(info.volume == doctest::Approx(exact).epsilon(tol));
  CHECK(info.volume <= exact * (1 + 1e-3));  // inscribed: never much more than the domain
  CHECK(area["inlet"] == doctest::Approx(M_PI * R * R).epsilon(tol));
  const double Ra = g.aorta_diameter / 2;
  CHECK(area["outlet"] == doctest::Approx(M_PI * Ra * Ra).epsilon(tol));

  // Every attachment node is in the fluid mesh, on its boundary or on the frame.
  CHECK(r.attachment.nodes ==
        int(valve::read_valve_leaflets(dir / "leaflets.msh").node_set("attachment").size()));
  CHECK(r.attachment.lost == 0);
  CHECK(r.attachment.inside > 0);

  CHECK(valve::read_valve_toml(dir / "valve.toml").mesh_size == g.mesh_size);
  CHECK_THROWS_WITH_AS(valve::make_valve(dir, g, false), doctest::Contains("use --overwrite"),
                       std::runtime_error);
}
