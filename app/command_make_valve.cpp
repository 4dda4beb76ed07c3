// `valsalva make-valve OUT_DIR [--set key=value ...] [--overwrite] [--leaflets-only]`: writes
// OUT_DIR/valve.toml, OUT_DIR/leaflets.msh and OUT_DIR/root.msh (valve/make_valve.hpp) and prints
// the counts, the attachment check and the times. Settings are checked on every rank (so every
// rank fails alike); Gmsh runs on rank 0 only.
#include "app/command_make_valve.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "valve/leaflet_mesh.hpp"
#include "valve/make_valve.hpp"
#include "valve/valve_geometry.hpp"

namespace valsalva::app {

namespace {

struct Options {
  std::string out;
  std::vector<std::string> settings;
  bool overwrite = false, leaflets_only = false;
};

int run(const Options& o) {
  const valve::ValveGeometry g = valve::parse_valve_settings(o.settings);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return 0;
  const valve::MakeValveResult r = valve::make_valve(o.out, g, o.overwrite, !o.leaflets_only);
  fmt::print("make-valve: {}/valve.toml (mesh_size = {:g} m)\n", o.out, g.mesh_size);
  fmt::print(
      "make-valve: {}/leaflets.msh: {} Q2 hexahedra (3 leaflets of {} x {}), {} nodes, "
      "{:.2f} s\n",
      o.out, r.leaflet_elements, valve::leaflet_elements(g)[0], valve::leaflet_elements(g)[1],
      r.leaflet_nodes, r.leaflet_seconds);
  if (r.fluid) {
    fmt::print(
        "make-valve: {}/root.msh: {} tetrahedra, {} nodes, {:.1f} s; fluid volume {:.6e} "
        "m^3 (CAD {:.6e}, parametrisation {:.6e})\n",
        o.out, r.root.tetrahedra, r.root.nodes, r.root.seconds, r.root.cad_volume,
        r.root.cad_volume, valve::fluid_volume(g));
    fmt::print(
        "make-valve: root.msh times: CAD {:.1f} s, surface mesh {:.1f} s, volume mesh {:.1f} s\n",
        r.root.cad_seconds, r.root.surface_seconds, r.root.volume_seconds);
    const auto& a = r.attachment;
    fmt::print(
        "make-valve: attachment nodes: {} in all, {} inside the fluid mesh, {} on its "
        "boundary, {} on the frame (its edge or its part within the root wall), {} elsewhere\n",
        a.nodes, a.inside, a.on_boundary, a.on_frame, a.lost);
    valve::require_attachment(a, std::filesystem::path(o.out) / "root.msh",
                              std::filesystem::path(o.out) / "leaflets.msh");
  }
  return 0;
}

}  // namespace

CLI::App* add_make_valve(CLI::App& cli, std::function<int()>& action) {
  auto o = std::make_shared<Options>();
  auto* c = cli.add_subcommand(
      "make-valve", "Write the parametric valve: root.msh (fluid), leaflets.msh, valve.toml");
  c->add_option("out_dir", o->out, "Output folder")->required();
  c->add_option("--set", o->settings, "Geometry key=value (repeatable; see docs/valve.md)")
      ->allow_extra_args(false);
  c->add_flag("--overwrite", o->overwrite, "Replace existing files");
  c->add_flag("--leaflets-only", o->leaflets_only, "Write valve.toml and leaflets.msh only");
  action = [o] { return run(*o); };
  return c;
}

}  // namespace valsalva::app
