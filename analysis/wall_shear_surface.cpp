#include "analysis/wall_shear_surface.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "io/xdmf_writer.hpp"

namespace valsalva::analysis {

std::filesystem::path write_wall_shear_surface(const std::filesystem::path& dir,
                                               const mesh::Mesh& mesh,
                                               const mesh::DualMetrics& metrics,
                                               const std::vector<std::string>& patches,
                                               const std::vector<WallNodeRow>& rows, double time) {
  std::map<std::pair<int, std::int64_t>, const WallNodeRow*> row_of;
  for (const auto& r : rows) row_of[{r.patch, r.node}] = &r;

  std::vector<std::int64_t> ids;
  std::vector<Eigen::Vector3d> coords, tau;
  std::vector<double> tawss, osi, rrt, support, patch_index, dual;
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> offsets{0}, cell_nodes;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const int mp = mesh.patch_index(patches[p]);
    std::vector<std::int64_t> faces;
    for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f)
      if (mesh.face_patches[std::size_t(f)] == mp) faces.push_back(f);
    std::vector<mesh::GlobalIndex> nodes;  // this patch's mesh nodes, ascending
    for (auto f : faces)
      for (auto m : mesh.face(f)) nodes.push_back(m);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const auto first = static_cast<std::int64_t>(ids.size());
    for (auto m : nodes) {
      const auto d = metrics.dual_of_mesh_node[std::size_t(m)];
      const auto it = row_of.find({int(p), d});
      if (it == row_of.end())
        throw std::logic_error(fmt::format(
            "wall_shear surface: mesh node {} of patch '{}' has no wall node", m, patches[p]));
      const WallNodeRow& r = *it->second;
      ids.push_back(std::int64_t(ids.size()));
      coords.push_back(mesh.nodes[std::size_t(m)]);
      tawss.push_back(r.tawss);
      osi.push_back(r.osi);
      rrt.push_back(r.rrt);
      support.push_back(r.support);
      tau.push_back(r.tau);
      patch_index.push_back(double(p));
      dual.push_back(double(d));
    }
    for (auto f : faces) {
      const auto face = mesh.face(f);
      types.push_back(face.size() == 3 ? io::kTriangleCell : io::kQuadCell);
      for (auto m : face)
        cell_nodes.push_back(first +
                             (std::lower_bound(nodes.begin(), nodes.end(), m) - nodes.begin()));
      offsets.push_back(std::int64_t(cell_nodes.size()));
    }
  }
  // The rows were gathered on this rank: write them alone (MPI_COMM_SELF).
  io::XdmfWriter writer(MPI_COMM_SELF, dir, "wall_shear_surface", std::int64_t(ids.size()), ids,
                        coords, types, offsets, cell_nodes);
  const std::vector<io::ScalarField> scalars{{"tawss", tawss},       {"osi", osi},
                                             {"rrt", rrt},           {"support_fraction", support},
                                             {"patch", patch_index}, {"node", dual}};
  const std::vector<io::VectorField> vectors{{"tau", tau}};
  writer.write_step(time, scalars, vectors);
  return writer.xmf_file();
}

}  // namespace valsalva::analysis
