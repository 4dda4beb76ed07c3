// Solid results to HDF5 + XDMF: every dataset reads back exactly, and the Hexahedron_27
// topology follows VTK's triquadratic-hexahedron order, checked geometrically on an affinely
// deformed mesh: VTK's edge nodes 8..19 are the midpoints of edges (0,1) (1,2) (2,3) (3,0)
// (4,5) (5,6) (6,7) (7,4) (0,4) (1,5) (2,6) (3,7), its face nodes 20..25 the centres of the
// faces -x, +x, -y, +y, -z, +z, node 26 the centroid (vtkTriQuadraticHexahedron documentation).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/hdf5_file.hpp"
#include "io/solid_output.hpp"
#include "structure/mesh_generators.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

TEST_CASE("solid results: datasets read back, Hexahedron_27 in VTK order") {
  structure::Bar b;
  b.length = 2e-3;
  b.height = 0.5e-3;
  b.depth = 0.3e-3;
  b.n_length = 3;
  b.n_height = 2;
  const structure::SolidMesh mesh = structure::straight_bar(structure::HexOrder::q2, b);
  structure::Mat3 F;
  F << 1.1, 0.2, 0.05, -0.1, 0.95, 0.1, 0.03, 0.07, 1.02;
  const Eigen::Matrix3Xd x =
      F * mesh.X + Eigen::Vector3d(1e-3, 0, 2e-3).replicate(1, mesh.num_nodes());
  const auto mat = structure::make_neo_hookean(2.4e6, 1.6e6);
  const structure::SolidForces forces(mesh, *mat);
  const structure::NodalStress s = structure::nodal_stress(forces, x);

  const fs::path dir = fs::path("test_output") / "solid_output";
  fs::create_directories(dir);
  const fs::path xmf = io::write_solid_results(dir, "bar", mesh, x, &s);

  io::h5::File f(dir / "bar.h5", io::h5::Mode::read);
  const long n = mesh.num_nodes(), ne = mesh.num_elements();
  CHECK(f.dims("topology") == std::vector<std::int64_t>{ne, 27});
  CHECK(f.dims("cauchy") == std::vector<std::int64_t>{n, 6});
  const auto geo = f.read_all<double>("geometry"), ref = f.read_all<double>("reference");
  const auto disp = f.read_all<double>("displacement"), vm = f.read_all<double>("von_mises");
  const auto ps = f.read_all<double>("principal_stress"), t6 = f.read_all<double>("cauchy");
  for (long i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      CHECK(geo[3 * i + k] == x(k, i));
      CHECK(ref[3 * i + k] == mesh.X(k, i));
      CHECK(disp[3 * i + k] == doctest::Approx(x(k, i) - mesh.X(k, i)).epsilon(1e-14));
      CHECK(ps[3 * i + k] == s.principal_stress(k, i));
    }
    CHECK(vm[i] == s.von_mises[i]);
    CHECK(t6[6 * i + 1] == s.cauchy(3, i));  // xy
    CHECK(t6[6 * i + 2] == s.cauchy(5, i));  // xz
    CHECK(t6[6 * i + 3] == s.cauchy(1, i));  // yy
    CHECK(t6[6 * i + 4] == s.cauchy(4, i));  // yz
  }
  const auto topo = f.read_all<std::int64_t>("topology");
  auto P = [&](long e, int i) { return Eigen::Vector3d(x.col(topo[27 * e + i])); };
  static constexpr int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                       {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  static constexpr int faces[6][4] = {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                      {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
  const double tol = 1e-12 * 2e-3;
  for (long e = 0; e < ne; ++e) {
    // Corners in VTK order: a positively oriented hexahedron, 0-1 along reference x, 0-3 along y.
    CHECK((P(e, 1) - P(e, 0)).cross(P(e, 3) - P(e, 0)).dot(P(e, 4) - P(e, 0)) > 0);
    for (int k = 0; k < 12; ++k)
      CHECK((P(e, 8 + k) - 0.5 * (P(e, edges[k][0]) + P(e, edges[k][1]))).norm() < tol);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 6; ++k) {
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for (int v : faces[k]) m += 0.25 * P(e, v);
      CHECK((P(e, 20 + k) - m).norm() < tol);
    }
    for (int v = 0; v < 8; ++v) c += P(e, v) / 8;
    CHECK((P(e, 26) - c).norm() < tol);
  }
  std::stringstream text;
  text << std::ifstream(xmf).rdbuf();
  CHECK(text.str().find("TopologyType=\"Hexahedron_27\" NumberOfElements=\"6\"") !=
        std::string::npos);
  for (const char* name :
       {"displacement", "von_mises", "principal_stress", "principal_strain", "cauchy"})
    CHECK(text.str().find(fmt::format("bar.h5:/{}<", name)) != std::string::npos);
}

TEST_CASE("solid results: position count must match the mesh") {
  const structure::SolidMesh mesh = structure::straight_bar(structure::HexOrder::q1, {});
  const Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, 2);
  CHECK_THROWS_WITH_AS(io::write_solid_results("test_output", "bad", mesh, x, nullptr),
                       doctest::Contains("2 positions for a mesh of"), std::invalid_argument);
}
