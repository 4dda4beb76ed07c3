// The end-of-run wall shear statistics as a surface ParaView opens: the boundary triangles and
// quads of the [wall_shear] patches with nodal values, through io::XdmfWriter (HDF5 + XDMF):
//   <dir>/wall_shear_surface.xmf, _mesh.h5, _000000.h5
// Fields: tawss (Pa), osi, rrt (1/Pa, nan where undefined), tau (last tau_w, Pa), patch (index
// into [wall_shear] patches), node (dual node id: the row of wall_shear.csv).
// Each patch has its own copy of the mesh nodes it shares with another patch (a node's statistics
// are per patch) and periodic images keep their own nodes (true geometry); nodes are numbered by
// patch, then mesh node, so the files are the same at any rank count.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/wall_shear_rows.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::analysis {

// Serial (rank 0, from gather_wall_rows): `rows` must hold every wall node of every patch.
// Returns the path of the .xmf.
std::filesystem::path write_wall_shear_surface(const std::filesystem::path& dir,
                                               const mesh::Mesh& mesh,
                                               const mesh::DualMetrics& metrics,
                                               const std::vector<std::string>& patches,
                                               const std::vector<WallNodeRow>& rows, double time);

}  // namespace valsalva::analysis
