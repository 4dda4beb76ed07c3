#include "io/solid_output.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <span>
#include <stdexcept>
#include <vector>

#include "io/hdf5_file.hpp"

namespace valsalva::io {

using structure::HexOrder;

const std::array<int, 27>& hex27_vtk_to_gmsh() {
  // VTK_TRIQUADRATIC_HEXAHEDRON parametric coordinates (vtkTriQuadraticHexahedron.cxx), mapped to
  // [-1,1]; each is matched to the Gmsh node with the same reference coordinates.
  static const std::array<int, 27> map = [] {
    static constexpr int vtk[27][3] = {
        {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
        {-1, 1, 1},   {0, -1, -1}, {1, 0, -1},  {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
        {0, 1, 1},    {-1, 0, 1},  {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},   {-1, 1, 0}, {-1, 0, 0},
        {1, 0, 0},    {0, -1, 0},  {0, 1, 0},   {0, 0, -1},  {0, 0, 1},   {0, 0, 0}};
    std::array<int, 27> m{};
    for (int i = 0; i < 27; ++i) {
      m[i] = -1;
      for (int a = 0; a < 27; ++a)
        if (structure::hex_reference_node(HexOrder::q2, a) ==
            structure::Vec3(vtk[i][0], vtk[i][1], vtk[i][2]))
          m[i] = a;
      if (m[i] < 0) throw std::logic_error("hex27_vtk_to_gmsh: no Gmsh node for a VTK node");
    }
    return m;
  }();
  return map;
}

namespace {

std::vector<double> rows3(const Eigen::Matrix3Xd& m) {
  return std::vector<double>(m.data(),
                             m.data() + m.size());  // column-major 3 x N = row-major N x 3
}

std::string item(const std::string& h5, const std::string& name, long rows, int cols,
                 const char* type, int precision) {
  const std::string dims = cols > 0 ? fmt::format("{} {}", rows, cols) : fmt::format("{}", rows);
  return fmt::format(
      "<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" "
      "Format=\"HDF\">{}:/{}</DataItem>",
      dims, type, precision, h5, name);
}

}  // namespace

std::string write_solid_h5(const std::filesystem::path& dir, const std::string& basename,
                           const structure::SolidMesh& mesh, const Eigen::Matrix3Xd& x,
                           const structure::NodalStress* stress, const SolidVectors& vectors) {
  const long n = mesh.num_nodes(), ne = mesh.num_elements();
  if (x.cols() != n)
    throw std::invalid_argument(
        fmt::format("write_solid_results: {} positions for a mesh of {} nodes", x.cols(), n));
  for (const auto& [name, v] : vectors)
    if (v->cols() != n)
      throw std::invalid_argument(
          fmt::format("write_solid_results: field '{}' has {} values for a mesh of {} nodes", name,
                      v->cols(), n));
  const bool q2 = mesh.order == HexOrder::q2;
  const int nen = mesh.nodes_per_element();
  std::vector<std::int64_t> topo(static_cast<std::size_t>(ne) * nen);
  for (long e = 0; e < ne; ++e)
    for (int i = 0; i < nen; ++i)
      topo[e * nen + i] =
          mesh.element_nodes(e)[q2 ? hex27_vtk_to_gmsh()[i] : i];  // Q1: Gmsh = VTK order

  const std::string h5name = basename + ".h5";
  h5::File f(dir / h5name, h5::Mode::create);
  f.write_block<double>("geometry", n, 3, 0, rows3(x));
  f.write_block<double>("reference", n, 3, 0, rows3(mesh.X));
  f.write_block<std::int64_t>("topology", ne, nen, 0, topo);
  f.write_block<double>("displacement", n, 3, 0, rows3(x - mesh.X));
  auto attribute = [&](const std::string& name, const char* type, int cols) {
    return fmt::format(
        "      <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n        {}\n"
        "      </Attribute>\n",
        name, type, item(h5name, name, n, cols, "Float", 8));
  };
  std::string attrs = attribute("displacement", "Vector", 3);
  for (const auto& [name, v] : vectors) {
    f.write_block<double>(name, n, 3, 0, rows3(*v));
    attrs += attribute(name, "Vector", 3);
  }
  if (stress) {
    const std::vector<double> vm(stress->von_mises.data(), stress->von_mises.data() + n);
    f.write_block<double>("von_mises", n, 0, 0, vm);
    f.write_block<double>("principal_stress", n, 3, 0, rows3(stress->principal_stress));
    f.write_block<double>("principal_strain", n, 3, 0, rows3(stress->principal_strain));
    std::vector<double> t6(6 * n);
    static constexpr int order[6] = {0, 3, 5,
                                     1, 4, 2};  // Tensor6 xx xy xz yy yz zz from xx yy zz xy yz xz
    for (long i = 0; i < n; ++i)
      for (int k = 0; k < 6; ++k) t6[6 * i + k] = stress->cauchy(order[k], i);
    f.write_block<double>("cauchy", n, 6, 0, t6);
    attrs += attribute("von_mises", "Scalar", 0);
    for (const char* v : {"principal_stress", "principal_strain"})
      attrs += attribute(v, "Vector", 3);
    attrs += attribute("cauchy", "Tensor6", 6);
  }
  f.close();
  return fmt::format(
      "      <Topology TopologyType=\"{}\" NumberOfElements=\"{}\">\n        {}\n      "
      "</Topology>\n"
      "      <Geometry GeometryType=\"XYZ\">\n        {}\n      </Geometry>\n{}",
      q2 ? "Hexahedron_27" : "Hexahedron", ne, item(h5name, "topology", ne, nen, "Int", 8),
      item(h5name, "geometry", n, 3, "Float", 8), attrs);
}

std::filesystem::path write_solid_results(
    const std::filesystem::path& dir, const std::string& basename, const structure::SolidMesh& mesh,
    const Eigen::Matrix3Xd& x, const structure::NodalStress* stress, const SolidVectors& vectors) {
  const std::string grid = write_solid_h5(dir, basename, mesh, x, stress, vectors);
  const auto xmf = dir / (basename + ".xmf");
  std::ofstream out(xmf);
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n    <Grid Name=\"solid\" "
         "GridType=\"Uniform\">\n"
      << grid << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  if (!out)
    throw std::runtime_error(fmt::format("write_solid_results: cannot write {}", xmf.string()));
  return xmf;
}

}  // namespace valsalva::io
