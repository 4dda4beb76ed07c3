// Solid (structure) results for ParaView: one HDF5 file with the mesh and nodal fields and an
// XDMF 3 file that describes it. Serial: the solid is small (thousands of nodes) and every rank
// holds all of it, so the caller writes from one rank.
//
// <dir>/<basename>.h5:
//   /geometry [N x 3] current positions x; /reference [N x 3] reference positions X
//   /topology [E x 27] for Q2, XDMF "Hexahedron_27" (VTK triquadratic-hexahedron node order:
//             8 corners, 12 edge mid-nodes, faces -x +x -y +y -z +z, centre), the full curved
//             element; [E x 8] "Hexahedron" for Q1. Node ids are 0-based.
//   /displacement [N x 3] = x - X
//   with stresses: /von_mises [N], /principal_stress [N x 3], /principal_strain [N x 3]
//   (decreasing order), /cauchy [N x 6] as XDMF Tensor6 (xx, xy, xz, yy, yz, zz)
// <dir>/<basename>.xmf: one uniform grid with those attributes, geometry = current positions.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "structure/solid_mesh.hpp"
#include "structure/stress_recovery.hpp"

namespace valsalva::io {

// Permutation from XDMF/VTK local node order to Gmsh order: vtk node i is Gmsh node map[i].
const std::array<int, 27>& hex27_vtk_to_gmsh();

// Extra nodal vectors (3 x N each), e.g. marker velocity and force: /<name> [N x 3].
using SolidVectors = std::vector<std::pair<std::string, const Eigen::Matrix3Xd*>>;

// Writes both files; returns the path of the .xmf. `stress` may be null (geometry and
// displacement only). Throws with the file name on any I/O failure.
std::filesystem::path write_solid_results(const std::filesystem::path& dir,
                                          const std::string& basename,
                                          const structure::SolidMesh& mesh,
                                          const Eigen::Matrix3Xd& x,
                                          const structure::NodalStress* stress,
                                          const SolidVectors& vectors = {});

// Writes only <dir>/<basename>.h5 and returns the XDMF <Topology>, <Geometry> and <Attribute>
// elements that describe it (for a grid of a temporal collection, io/solid_series.hpp).
std::string write_solid_h5(const std::filesystem::path& dir, const std::string& basename,
                           const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                           const structure::NodalStress* stress, const SolidVectors& vectors = {});

}  // namespace valsalva::io
