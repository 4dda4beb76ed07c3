// check_mesh and the cell geometry on hand-made meshes: exact volumes of the four cell types,
// a valid mesh accepted, an out-of-range node index reported.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <string>

#include "mesh/mesh_check.hpp"

using namespace valsalva;
using mesh::CellType;
using mesh::GlobalIndex;

namespace {

// One cell of the given type on the unit-cube corner nodes (Gmsh order), after an affine map x
// -> A x + b with det A = 6, all its faces on patch "wall".
mesh::Mesh single_cell(CellType type, const Eigen::Matrix3d& A) {
  mesh::Mesh mesh;
  mesh.source = std::string("single ") + mesh::name(type);
  const std::vector<Eigen::Vector3d> corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                                {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                                                {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 1}};
  std::vector<GlobalIndex> nodes;
  switch (type) {
    case CellType::tetra:
      nodes = {0, 1, 3, 4};
      break;
    case CellType::pyramid:
      nodes = {0, 1, 2, 3, 8};
      break;
    case CellType::prism:
      nodes = {0, 1, 3, 4, 5, 7};
      break;
    case CellType::hexa:
      nodes = {0, 1, 2, 3, 4, 5, 6, 7};
      break;
  }
  for (GlobalIndex n : nodes) mesh.nodes.push_back(A * corners[n] + Eigen::Vector3d(1, -2, 3));
  std::vector<GlobalIndex> local(nodes.size());
  for (std::size_t k = 0; k < local.size(); ++k) local[k] = static_cast<GlobalIndex>(k);
  mesh.add_cell(type, local, mesh.add_region("fluid"));
  const int wall = mesh.add_patch("wall");
  for (const auto& face : mesh::cell_faces(type)) {
    std::vector<GlobalIndex> f(face.begin(), face.end());
    mesh.add_face(f, wall);
  }
  return mesh;
}

}  // namespace

TEST_CASE("cell volumes are exact for affine images of the reference cells") {
  Eigen::Matrix3d A;
  A << 2, 0.3, -0.2, 0.1, 1.5, 0.4, -0.3, 0.2, 2.0;
  const double det = A.determinant();
  const std::pair<CellType, double> cells[] = {{CellType::tetra, 1.0 / 6},
                                               {CellType::pyramid, 1.0 / 3},
                                               {CellType::prism, 0.5},
                                               {CellType::hexa, 1.0}};
  for (auto [type, reference] : cells) {
    CAPTURE(mesh::name(type));
    const mesh::Mesh mesh = single_cell(type, A);
    CHECK_NOTHROW(mesh::check_mesh(mesh));
    CHECK(mesh::cell_volume(mesh, 0) == doctest::Approx(reference * det).epsilon(1e-14));
    CHECK(mesh::min_subtet_volume(mesh, 0) > 0);
    // Closed cell: the outward face area vectors sum to zero.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (GlobalIndex f = 0; f < mesh.num_faces(); ++f) sum += mesh::face_area(mesh, mesh.face(f));
    CHECK(sum.norm() < 1e-14 * std::cbrt(det * det));
  }
}

TEST_CASE("check_mesh names the problem on hand-made bad meshes") {
  auto message = [](const mesh::Mesh& mesh) {
    try {
      mesh::check_mesh(mesh);
    } catch (const mesh::MeshError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  mesh::Mesh mesh = single_cell(CellType::hexa, Eigen::Matrix3d::Identity());
  mesh.cell_nodes[5] = 12;
  std::string m = message(mesh);
  CHECK(m.find("single hexahedron") != std::string::npos);
  CHECK(m.find("cell 0 (hexahedron) refers to node index 12 out of range [0, 8)") !=
        std::string::npos);

  mesh = single_cell(CellType::prism, Eigen::Matrix3d::Identity());
  mesh.face_nodes[2] = -1;
  m = message(mesh);
  CHECK(m.find("boundary face 0 (patch 'wall') refers to node index -1 out of range") !=
        std::string::npos);

  mesh = single_cell(CellType::tetra, Eigen::Matrix3d::Identity());
  mesh.nodes[3].z() = -1;  // apex through the base: inverted
  CHECK(message(mesh).find("inverted cell 0 (tetrahedron") != std::string::npos);

  mesh = single_cell(CellType::pyramid, Eigen::Matrix3d::Identity());
  mesh.face_patches.back() = 3;
  CHECK(message(mesh).find("patch index 3 but the mesh has 1 patches") != std::string::npos);

  mesh = single_cell(CellType::hexa, Eigen::Matrix3d::Identity());
  mesh.nodes[6] = {1, 1, -0.5};  // a bow-tie hexahedron: positive total, one corner inverted
  m = message(mesh);
  CHECK(m.find("inverted cell 0 (hexahedron") != std::string::npos);
  CHECK(m.find("at node 6") != std::string::npos);
}
