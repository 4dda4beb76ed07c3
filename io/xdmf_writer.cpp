#include "io/xdmf_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <set>
#include <stdexcept>

#include "core/comm.hpp"
#include "io/hdf5_file.hpp"

namespace valsalva::io {

static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d arrays must be flat");

namespace {

// MPI_Exscan leaves rank 0's result undefined.
std::int64_t exclusive_prefix(const core::Comm& comm, std::int64_t value) {
  std::int64_t before = 0;
  VALSALVA_MPI(MPI_Exscan(&value, &before, 1, MPI_INT64_T, MPI_SUM, comm.get()));
  return comm.rank() == 0 ? 0 : before;
}

// XDMF topology codes and the VTK node order XDMF uses. VTK's wedge has its first triangle
// pointing away from the second one, Gmsh's prism towards it: swap two nodes of each triangle.
// Types 0-3 are mesh::CellType; 4 and 5 are boundary faces (surface output, e.g. wall shear).
struct XdmfCell {
  std::int64_t code;
  int nodes;
  const char* name;
  std::array<int, 8> order;
};
constexpr std::array<XdmfCell, 6> kXdmfCells = {{
    {6, 4, "tetra", {0, 1, 2, 3}},
    {7, 5, "pyramid", {0, 1, 2, 3, 4}},
    {8, 6, "prism", {0, 2, 1, 3, 5, 4}},  // -> wedge
    {9, 8, "hexa", {0, 1, 2, 3, 4, 5, 6, 7}},
    {4, 3, "triangle", {0, 1, 2}},
    {5, 4, "quad", {0, 1, 2, 3}},
}};

std::string check_mesh(const std::string& who, std::int64_t global_nodes,
                       std::span<const std::int64_t> ids, std::span<const Eigen::Vector3d> coords,
                       std::span<const std::uint8_t> types, std::span<const std::int64_t> offsets,
                       std::span<const std::int64_t> cell_nodes) {
  if (ids.size() != coords.size())
    return fmt::format("{}: {} owned node ids but {} coordinates", who, ids.size(), coords.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] < 0 || ids[i] >= global_nodes)
      return fmt::format("{}: owned node {} has global id {} outside [0, {})", who, i, ids[i],
                         global_nodes);
  if (offsets.size() != types.size() + 1 || offsets.front() != 0 ||
      offsets.back() != static_cast<std::int64_t>(cell_nodes.size()))
    return fmt::format(
        "{}: cell_offsets must have cells + 1 = {} entries from 0 to {} "
        "(got {} entries)",
        who, types.size() + 1, cell_nodes.size(), offsets.size());
  for (std::size_t c = 0; c < types.size(); ++c) {
    if (types[c] >= kXdmfCells.size())
      return fmt::format(
          "{}: cell {} has type {}; expected 0 tetra, 1 pyramid, 2 prism, 3 hexa, 4 triangle, "
          "5 quad",
          who, c, int(types[c]));
    const XdmfCell& xc = kXdmfCells[types[c]];
    if (offsets[c + 1] - offsets[c] != xc.nodes)
      return fmt::format("{}: cell {} ({}) has {} nodes, expected {}", who, c, xc.name,
                         offsets[c + 1] - offsets[c], xc.nodes);
    for (std::int64_t k = offsets[c]; k < offsets[c + 1]; ++k)
      if (cell_nodes[k] < 0 || cell_nodes[k] >= global_nodes)
        return fmt::format("{}: cell {} has node {} outside [0, {})", who, c, cell_nodes[k],
                           global_nodes);
  }
  return {};
}

bool valid_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '_' || ch == '.' || ch == '-';
  });
}

std::span<const double> flat(std::span<const Eigen::Vector3d> v) {
  return {reinterpret_cast<const double*>(v.data()), 3 * v.size()};
}

}  // namespace

XdmfWriter::XdmfWriter(MPI_Comm comm, std::filesystem::path dir, std::string basename,
                       std::int64_t global_nodes,
                       std::span<const std::int64_t> owned_node_global_ids,
                       std::span<const Eigen::Vector3d> owned_node_coords,
                       std::span<const std::uint8_t> cell_types,
                       std::span<const std::int64_t> cell_offsets,
                       std::span<const std::int64_t> cell_nodes_global)
    : comm_(comm),
      dir_(std::move(dir)),
      basename_(std::move(basename)),
      global_nodes_(global_nodes),
      owned_ids_(owned_node_global_ids.begin(), owned_node_global_ids.end()) {
  const core::Comm world(comm_);
  rank_ = world.rank();
  const std::string who = fmt::format("XdmfWriter '{}'", (dir_ / basename_).string());
  std::string error;
  if (!valid_name(basename_))
    error = fmt::format("{}: basename must be non-empty and use only [A-Za-z0-9_.-]", who);
  if (error.empty())
    error = check_mesh(who, global_nodes, owned_node_global_ids, owned_node_coords, cell_types,
                       cell_offsets, cell_nodes_global);
  h5::settle(comm_, error);
  const std::int64_t owned_total = world.sum(static_cast<std::int64_t>(owned_ids_.size()));
  const std::int64_t lo = -world.max(-global_nodes), hi = world.max(global_nodes);
  if (lo != hi)
    h5::settle(comm_, fmt::format("{}: ranks disagree on global_nodes ({}..{})", who, lo, hi));
  if (owned_total != global_nodes)
    h5::settle(comm_, fmt::format("{}: ranks own {} nodes in total, expected global_nodes = {}",
                                  who, owned_total, global_nodes));

  if (rank_ == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec)
      error = fmt::format("{}: cannot create directory '{}': {}", who, dir_.string(), ec.message());
  }
  h5::settle(comm_, error);

  // XDMF Mixed topology: per cell its type code, then its nodes in XDMF (VTK) order.
  std::vector<std::int64_t> topology;
  topology.reserve(cell_types.size() + cell_nodes_global.size());
  for (std::size_t c = 0; c < cell_types.size(); ++c) {
    const XdmfCell& xc = kXdmfCells[cell_types[c]];
    topology.push_back(xc.code);
    const auto n = cell_offsets[c + 1] - cell_offsets[c];
    for (std::int64_t k = 0; k < n; ++k)
      topology.push_back(cell_nodes_global[cell_offsets[c] + xc.order[k]]);
  }
  const auto local_cells = static_cast<std::int64_t>(cell_types.size());
  const auto local_topology = static_cast<std::int64_t>(topology.size());
  global_cells_ = world.sum(local_cells);
  topology_size_ = world.sum(local_topology);
  const std::vector<std::int32_t> partition(cell_types.size(), rank_);

  h5::File file(comm_, mesh_file(), h5::Mode::create);
  file.write_attribute("global_nodes", static_cast<double>(global_nodes_));
  file.write_rows<double>("coordinates", global_nodes_, 3, owned_ids_, flat(owned_node_coords));
  file.write_block<std::int64_t>("topology", topology_size_, 0,
                                 exclusive_prefix(world, local_topology), topology);
  file.write_block<std::int32_t>("partition", global_cells_, 0,
                                 exclusive_prefix(world, local_cells), partition);
  file.close();
}

std::filesystem::path XdmfWriter::write_step(double time, std::span<const ScalarField> scalars,
                                             std::span<const VectorField> vectors) {
  const std::string who = fmt::format("XdmfWriter '{}' step {} (t = {})",
                                      (dir_ / basename_).string(), steps_.size(), time);
  std::string error;
  std::set<std::string> names;
  Step step{time, fmt::format("{}_{:06d}.h5", basename_, steps_.size()), {}};
  auto check_field = [&](const std::string& name, std::size_t size, int components) {
    if (!error.empty()) return;
    if (!valid_name(name))
      error = fmt::format("{}: field name '{}' must be non-empty and use only [A-Za-z0-9_.-]", who,
                          name);
    else if (!names.insert(name).second)
      error = fmt::format("{}: field '{}' given twice", who, name);
    else if (size != owned_ids_.size())
      error = fmt::format("{}: field '{}' has {} values, expected one per owned node ({})", who,
                          name, size, owned_ids_.size());
    step.fields.emplace_back(name, components);
  };
  for (const ScalarField& f : scalars) check_field(f.name, f.values.size(), 1);
  for (const VectorField& f : vectors) check_field(f.name, f.values.size(), 3);
  h5::settle(comm_, error);

  const std::filesystem::path path = dir_ / step.file;
  h5::File file(comm_, path, h5::Mode::create);
  file.write_attribute("time", time);
  file.write_attribute("global_nodes", static_cast<double>(global_nodes_));
  for (const ScalarField& f : scalars)
    file.write_rows<double>(f.name, global_nodes_, 0, owned_ids_, f.values);
  for (const VectorField& f : vectors)
    file.write_rows<double>(f.name, global_nodes_, 3, owned_ids_, flat(f.values));
  file.close();
  steps_.push_back(std::move(step));

  if (rank_ == 0) {
    try {
      write_xmf();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  h5::settle(comm_, error);
  return path;
}

// The heavy data are referenced by file name relative to the .xmf, so the directory can move.
void XdmfWriter::write_xmf() const {
  const std::string mesh = basename_ + "_mesh.h5";
  std::string xml =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"" +
      basename_ + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t s = 0; s < steps_.size(); ++s) {
    const Step& step = steps_[s];
    xml += fmt::format(
        "      <Grid Name=\"step_{:06d}\" GridType=\"Uniform\">\n"
        "        <Time Value=\"{:.17g}\"/>\n"
        "        <Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\">\n"
        "          <DataItem Dimensions=\"{}\" NumberType=\"Int\" Precision=\"8\" "
        "Format=\"HDF\">{}:/topology</DataItem>\n"
        "        </Topology>\n"
        "        <Geometry GeometryType=\"XYZ\">\n"
        "          <DataItem Dimensions=\"{} 3\" NumberType=\"Float\" Precision=\"8\" "
        "Format=\"HDF\">{}:/coordinates</DataItem>\n"
        "        </Geometry>\n"
        "        <Attribute Name=\"partition\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        "          <DataItem Dimensions=\"{}\" NumberType=\"Int\" Precision=\"4\" "
        "Format=\"HDF\">{}:/partition</DataItem>\n"
        "        </Attribute>\n",
        s, step.time, global_cells_, topology_size_, mesh, global_nodes_, mesh, global_cells_,
        mesh);
    for (const auto& [name, components] : step.fields)
      xml += fmt::format(
          "        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n"
          "          <DataItem Dimensions=\"{}{}\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"HDF\">{}:/{}</DataItem>\n"
          "        </Attribute>\n",
          name, components == 3 ? "Vector" : "Scalar", global_nodes_, components == 3 ? " 3" : "",
          step.file, name);
    xml += "      </Grid>\n";
  }
  xml += "    </Grid>\n  </Domain>\n</Xdmf>\n";

  // Write then rename, so a reader (or a crash) never sees half a file.
  const std::filesystem::path target = xmf_file();
  std::filesystem::path tmp = target;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << xml;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("XdmfWriter: cannot write '{}'", tmp.string()));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec)
    throw std::runtime_error(fmt::format("XdmfWriter: cannot rename '{}' to '{}': {}", tmp.string(),
                                         target.string(), ec.message()));
}

namespace {
// A nodal field has one row per node of the mesh (attribute "global_nodes" of the file).
void check_nodal_shape(const h5::File& file, const std::string& name) {
  const std::vector<std::int64_t> d = file.dims(name);
  const auto nodes = static_cast<std::int64_t>(file.read_attribute("global_nodes"));
  if (!((d.size() == 1 || (d.size() == 2 && d[1] == 3)) && d[0] == nodes))
    throw std::runtime_error(fmt::format(
        "HDF5 file '{}', dataset '{}': not a nodal field ([{} x 1] or [{} x 3] expected, got "
        "[{}{}])",
        file.path().string(), name, nodes, nodes, d.empty() ? 0 : d[0],
        d.size() == 2 ? fmt::format(" x {}", d[1]) : ""));
}
}  // namespace

std::vector<double> read_nodal_field(const std::filesystem::path& path, const std::string& name) {
  const h5::File file(path, h5::Mode::read);
  check_nodal_shape(file, name);
  return file.read_all<double>(name);
}

std::vector<double> read_nodal_field(MPI_Comm comm, const std::filesystem::path& path,
                                     const std::string& name,
                                     std::span<const std::int64_t> global_ids) {
  const h5::File file(comm, path, h5::Mode::read);
  check_nodal_shape(file, name);
  return file.read_rows<double>(name, global_ids);
}

}  // namespace valsalva::io
