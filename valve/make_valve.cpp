#include "valve/make_valve.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "mesh/gmsh_reader.hpp"
#include "mesh/point_locator.hpp"
#include "valve/leaflet_mesh.hpp"

namespace valsalva::valve {

namespace fs = std::filesystem;

namespace {

// Writes through a temporary file in the same folder ("<stem>.partial<ext>", so Gmsh still
// knows the format) and renames it when the writer returned.
template <class Write>
void write_atomically(const fs::path& file, Write&& write) {
  const fs::path tmp =
      file.parent_path() / (file.stem().string() + ".partial" + file.extension().string());
  try {
    write(tmp);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, file);
}

}  // namespace

void require_attachment(const AttachmentCheck& c, const fs::path& root_msh,
                        const fs::path& leaflets_msh) {
  if (c.lost > 0)
    throw std::runtime_error(fmt::format(
        "make-valve: {} of {} attachment nodes of '{}' lie neither in the fluid mesh '{}' nor on "
        "the frame (the first: node {} at ({:.6g}, {:.6g}, {:.6g}) m)",
        c.lost, c.nodes, leaflets_msh.string(), root_msh.string(), c.first_lost + 1,
        c.first_lost_at[0], c.first_lost_at[1], c.first_lost_at[2]));
}

AttachmentCheck check_attachment(const fs::path& root_msh, const fs::path& leaflets_msh,
                                 const ValveGeometry& g) {
  const mesh::Mesh fluid = mesh::read_gmsh(root_msh);
  const structure::SolidMesh leaflets = read_valve_leaflets(leaflets_msh);
  const mesh::PointLocator locator(fluid);
  AttachmentCheck c;
  for (int n : leaflets.node_set("attachment")) {
    const Eigen::Vector3d x = leaflets.X.col(n);
    ++c.nodes;
    if (locator.locate(x, 1e-9))
      ++c.inside;
    else if (locator.locate(x, 0.05))
      ++c.on_boundary;
    else if (on_frame(g, x.x(), x.y(), x.z(), 1e-6 * g.root_diameter))
      ++c.on_frame;
    else if (c.lost++ == 0) {
      c.first_lost = n;
      c.first_lost_at = {x.x(), x.y(), x.z()};
    }
  }
  return c;
}

MakeValveResult make_valve(const fs::path& out_dir, const ValveGeometry& g, bool overwrite,
                           bool fluid) {
  validate(g);
  const fs::path toml = out_dir / "valve.toml", leaflets = out_dir / "leaflets.msh",
                 root = out_dir / "root.msh";
  std::vector<fs::path> outputs{toml, leaflets};
  if (fluid) outputs.push_back(root);
  for (const auto& f : outputs)
    if (fs::exists(f) && !overwrite)
      throw std::runtime_error(
          fmt::format("make-valve: '{}' exists (use --overwrite to replace it)", f.string()));
  fs::create_directories(out_dir);
  write_valve_toml(toml, g);

  MakeValveResult r;
  const auto t0 = std::chrono::steady_clock::now();
  const structure::SolidMesh mesh = valve_leaflets(g);
  write_atomically(leaflets, [&](const fs::path& p) { write_leaflets_gmsh(p, mesh); });
  r.leaflet_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.leaflet_elements = mesh.num_elements();
  r.leaflet_nodes = mesh.num_nodes();
  r.fluid = fluid;
  if (fluid) {
    write_atomically(root, [&](const fs::path& p) { r.root = write_root_mesh(p, g); });
    r.attachment = check_attachment(root, leaflets, g);
  }
  return r;
}

}  // namespace valsalva::valve
