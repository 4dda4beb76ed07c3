// XdmfWriter: a hybrid mesh (hexahedra, prisms, pyramids, tetrahedra) with nodes owned by ranks
// in a scattered, shuffled order is written with two steps; coordinates, fields, topology,
// partition and times are read back by global id and compared exactly (the HDF5 files store
// the same doubles, so any difference is a bug, not round-off). The .xmf is checked to reference
// existing datasets with the stated dimensions, in C++ and with Python's xml.etree + h5py
// (and, where python3-vtk9 is installed, that every cell is positively oriented in VTK's node
// order, which XDMF uses: the check of the Gmsh-prism to VTK-wedge reordering).
#include <doctest/doctest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "io/hdf5_file.hpp"
#include "io/xdmf_writer.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

struct World {
  int rank = 0;
  int size = 1;
  World() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  }
};

constexpr int kCubes = 3;  // per direction
constexpr int kPts = kCubes + 1;
constexpr std::int64_t kNodes = kPts * kPts * kPts;

std::int64_t node_id(int i, int j, int k) {
  return i + kPts * (j + kPts * k);
}

Eigen::Vector3d coord(std::int64_t id) {
  const double i = id % kPts, j = (id / kPts) % kPts, k = id / (kPts * kPts);
  // Irregular values so that a swapped or shifted row cannot compare equal by accident.
  return {0.1 * i + 1e-3 * std::sin(double(id)), 0.1 * j + 1e-3 * std::cos(double(id)),
          0.1 * k + 1e-3 * std::sin(3.0 * id)};
}

int node_owner(std::int64_t id, int size) {
  return static_cast<int>((7 * id + 3) % size);
}

// Cells of cube (i, j, k) in Gmsh order: a hexahedron, two prisms, three pyramids with apex at
// the far corner, or six Kuhn tetrahedra around the main diagonal, by cube index.
struct CellList {
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> nodes;
  std::vector<std::vector<std::int64_t>> xdmf;  // expected XDMF form: code, VTK-ordered nodes
  void add(std::uint8_t type, std::vector<std::int64_t> n, std::vector<std::int64_t> vtk) {
    static constexpr std::int64_t code[] = {6, 7, 8, 9};
    types.push_back(type);
    nodes.insert(nodes.end(), n.begin(), n.end());
    offsets.push_back(static_cast<std::int64_t>(nodes.size()));
    vtk.insert(vtk.begin(), code[type]);
    xdmf.push_back(std::move(vtk));
  }
};

CellList cells_of_rank(int rank, int size) {
  CellList list;
  int cube = 0;
  for (int k = 0; k < kCubes; ++k)
    for (int j = 0; j < kCubes; ++j)
      for (int i = 0; i < kCubes; ++i, ++cube) {
        if (cube % size != rank) continue;
        const std::int64_t v[8] = {node_id(i, j, k),
                                   node_id(i + 1, j, k),
                                   node_id(i + 1, j + 1, k),
                                   node_id(i, j + 1, k),
                                   node_id(i, j, k + 1),
                                   node_id(i + 1, j, k + 1),
                                   node_id(i + 1, j + 1, k + 1),
                                   node_id(i, j + 1, k + 1)};
        switch (cube % 4) {
          case 0:
            list.add(3, {v, v + 8}, {v, v + 8});
            break;
          case 1:  // VTK wedge: first triangle points away from the second
            list.add(2, {v[0], v[1], v[2], v[4], v[5], v[6]}, {v[0], v[2], v[1], v[4], v[6], v[5]});
            list.add(2, {v[0], v[2], v[3], v[4], v[6], v[7]}, {v[0], v[3], v[2], v[4], v[7], v[6]});
            break;
          case 2:
            list.add(1, {v[0], v[1], v[2], v[3], v[6]}, {v[0], v[1], v[2], v[3], v[6]});
            list.add(1, {v[0], v[4], v[5], v[1], v[6]}, {v[0], v[4], v[5], v[1], v[6]});
            list.add(1, {v[0], v[3], v[7], v[4], v[6]}, {v[0], v[3], v[7], v[4], v[6]});
            break;
          default:
            // Ordered for a positive volume (base normal towards the apex v6).
            static constexpr int paths[6][2] = {{1, 2}, {5, 1}, {2, 3}, {3, 7}, {4, 5}, {7, 4}};
            for (const auto& p : paths)
              list.add(0, {v[0], v[p[0]], v[p[1]], v[6]}, {v[0], v[p[0]], v[p[1]], v[6]});
        }
      }
  return list;
}

double pressure(std::int64_t id, double t) {
  return std::exp(-t) * std::cos(0.37 * id) + t;
}
Eigen::Vector3d velocity(std::int64_t id, double t) {
  return {std::sin(0.1 * id + t), 1.0 / (1.0 + id + t), -std::sqrt(double(id)) * t};
}

struct Written {
  fs::path dir;
  std::vector<std::int64_t> owned;
  std::vector<fs::path> steps;
  std::int64_t cells = 0;
  std::vector<int> cells_per_rank;
};

// Writes the mesh and steps at t = 0.5 and 1.25 into a directory of its own per rank count.
Written write_case(const World& w) {
  Written out;
  out.dir = fs::path("test_output") / ("xdmf_np" + std::to_string(w.size));
  for (std::int64_t id = 0; id < kNodes; ++id)
    if (node_owner(id, w.size) == w.rank) out.owned.push_back(id);
  std::shuffle(out.owned.begin(), out.owned.end(), std::mt19937(42 + w.rank));
  std::vector<Eigen::Vector3d> xyz;
  for (std::int64_t id : out.owned) xyz.push_back(coord(id));
  const CellList cells = cells_of_rank(w.rank, w.size);
  for (int r = 0; r < w.size; ++r)
    out.cells_per_rank.push_back(static_cast<int>(cells_of_rank(r, w.size).types.size()));

  io::XdmfWriter writer(MPI_COMM_WORLD, out.dir, "flow", kNodes, out.owned, xyz, cells.types,
                        cells.offsets, cells.nodes);
  out.cells = writer.global_cells();
  for (double t : {0.5, 1.25}) {
    std::vector<double> p;
    std::vector<Eigen::Vector3d> u;
    for (std::int64_t id : out.owned) {
      p.push_back(pressure(id, t));
      u.push_back(velocity(id, t));
    }
    const io::ScalarField scalars[] = {{"p", p}};
    const io::VectorField vectors[] = {{"velocity", u}};
    out.steps.push_back(writer.write_step(t, scalars, vectors));
  }
  CHECK(writer.steps_written() == 2);
  CHECK(writer.xmf_file() == out.dir / "flow.xmf");
  return out;
}

}  // namespace

TEST_CASE("XdmfWriter writes coordinates, fields and topology readable by global id") {
  const World w;
  const Written out = write_case(w);
  REQUIRE(out.steps.size() == 2);
  CHECK(out.steps[1] == out.dir / "flow_000001.h5");

  const std::vector<double> xyz = io::read_nodal_field(out.dir / "flow_mesh.h5", "coordinates");
  REQUIRE(xyz.size() == 3 * kNodes);
  for (std::int64_t id = 0; id < kNodes; ++id)
    for (int d = 0; d < 3; ++d) CHECK(xyz[3 * id + d] == coord(id)[d]);

  const double times[] = {0.5, 1.25};
  for (int s = 0; s < 2; ++s) {
    const double t = times[s];
    const std::vector<double> p = io::read_nodal_field(out.steps[s], "p");
    const std::vector<double> u = io::read_nodal_field(out.steps[s], "velocity");
    REQUIRE(p.size() == kNodes);
    REQUIRE(u.size() == 3 * kNodes);
    int wrong = 0;
    for (std::int64_t id = 0; id < kNodes; ++id) {
      wrong += p[id] != pressure(id, t);
      for (int d = 0; d < 3; ++d) wrong += u[3 * id + d] != velocity(id, t)[d];
    }
    CHECK(wrong == 0);
    CHECK(io::h5::File(out.steps[s], io::h5::Mode::read).read_attribute("time") == t);

    // Parallel read of this rank's own rows, in its shuffled order.
    const std::vector<double> mine =
        io::read_nodal_field(MPI_COMM_WORLD, out.steps[s], "velocity", out.owned);
    REQUIRE(mine.size() == 3 * out.owned.size());
    for (std::size_t i = 0; i < out.owned.size(); ++i)
      for (int d = 0; d < 3; ++d) CHECK(mine[3 * i + d] == velocity(out.owned[i], t)[d]);
  }

  // Topology: rank blocks of (code, VTK-ordered nodes); compare as sorted lists of cells.
  const io::h5::File mesh(out.dir / "flow_mesh.h5", io::h5::Mode::read);
  const std::vector<std::int64_t> topo = mesh.read_all<std::int64_t>("topology");
  std::vector<std::vector<std::int64_t>> got, expected;
  const std::map<std::int64_t, int> count = {{6, 4}, {7, 5}, {8, 6}, {9, 8}};
  for (std::size_t pos = 0; pos < topo.size();) {
    REQUIRE(count.count(topo[pos]) == 1);
    const std::size_t n = 1 + count.at(topo[pos]);
    REQUIRE(pos + n <= topo.size());
    got.emplace_back(topo.begin() + pos, topo.begin() + pos + n);
    pos += n;
  }
  for (int r = 0; r < w.size; ++r) {
    const CellList c = cells_of_rank(r, w.size);
    expected.insert(expected.end(), c.xdmf.begin(), c.xdmf.end());
  }
  CHECK(got.size() == expected.size());
  CHECK(out.cells == static_cast<std::int64_t>(expected.size()));
  std::sort(got.begin(), got.end());
  std::sort(expected.begin(), expected.end());
  CHECK(got == expected);

  const std::vector<std::int32_t> part = mesh.read_all<std::int32_t>("partition");
  REQUIRE(static_cast<std::int64_t>(part.size()) == out.cells);
  std::size_t pos = 0;
  for (int r = 0; r < w.size; ++r)
    for (int c = 0; c < out.cells_per_rank[r]; ++c) CHECK(part[pos++] == r);
}

namespace {

// Every <DataItem Dimensions="..." ...>file:/name</DataItem> of the .xmf.
struct Item {
  std::string dims, file, dataset;
};
std::vector<Item> data_items(const std::string& xml) {
  const std::regex re(R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*>([^:<]+):/([^<]+)</DataItem>)re");
  std::vector<Item> items;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), re); it != std::sregex_iterator();
       ++it)
    items.push_back({(*it)[1], (*it)[2], (*it)[3]});
  return items;
}

}  // namespace

TEST_CASE("The .xmf time series references existing datasets with their dimensions") {
  const World w;
  const Written out = write_case(w);
  std::ifstream in(out.dir / "flow.xmf");
  REQUIRE(in.good());
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string xml = buffer.str();

  CHECK(xml.find(R"(CollectionType="Temporal")") != std::string::npos);
  CHECK(xml.find(R"(<Time Value="0.5"/>)") != std::string::npos);
  CHECK(xml.find(R"(<Time Value="1.25"/>)") != std::string::npos);
  CHECK(xml.find(R"(TopologyType="Mixed" NumberOfElements=")" + std::to_string(out.cells) + "\"") !=
        std::string::npos);

  const std::vector<Item> items = data_items(xml);
  // Per step: topology, coordinates, partition, p, velocity.
  CHECK(items.size() == 2 * 5);
  for (const Item& item : items) {
    CAPTURE(item.file);
    CAPTURE(item.dataset);
    REQUIRE(fs::exists(out.dir / item.file));
    const io::h5::File file(out.dir / item.file, io::h5::Mode::read);
    REQUIRE(file.has(item.dataset));
    std::string dims;
    for (std::int64_t d : file.dims(item.dataset))
      dims += (dims.empty() ? "" : " ") + std::to_string(d);
    CHECK(dims == item.dims);
  }

  // An independent parser: Python's xml.etree for well-formedness and h5py for the shapes.
  // Debian's interpreter, which has python3-h5py (a pyenv or venv python3 on PATH may not).
  if (w.rank == 0) {
    const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string cmd = python + " " VALSALVA_SOURCE_DIR "/tests/io/check_xdmf.py " +
                            (out.dir / "flow.xmf").string() + " 2";
    CHECK(std::system(cmd.c_str()) == 0);
  }
}

TEST_CASE("XdmfWriter and read_nodal_field reject bad input with clear errors") {
  const World w;
  const fs::path dir = fs::path("test_output") / ("xdmf_bad_np" + std::to_string(w.size));
  std::vector<std::int64_t> owned;
  std::vector<Eigen::Vector3d> xyz;
  for (std::int64_t id = 0; id < kNodes; ++id)
    if (node_owner(id, w.size) == w.rank) {
      owned.push_back(id);
      xyz.push_back(coord(id));
    }
  CellList cells = cells_of_rank(w.rank, w.size);
  io::XdmfWriter writer(MPI_COMM_WORLD, dir, "bad", kNodes, owned, xyz, cells.types, cells.offsets,
                        cells.nodes);
  const std::vector<double> short_p(owned.size() + 1, 0.0);
  const io::ScalarField wrong_size[] = {{"p", short_p}};
  CHECK_THROWS_WITH(
      writer.write_step(0.0, wrong_size),
      doctest::Contains(("field 'p' has " + std::to_string(short_p.size()) + " values").c_str()));
  const std::vector<double> p(owned.size(), 1.0);
  const io::ScalarField bad_name[] = {{"p/x", p}};
  CHECK_THROWS_WITH(writer.write_step(0.0, bad_name), doctest::Contains("field name 'p/x'"));
  const io::ScalarField twice[] = {{"p", p}, {"p", p}};
  CHECK_THROWS_WITH(writer.write_step(0.0, twice), doctest::Contains("field 'p' given twice"));
  CHECK(writer.steps_written() == 0);

  cells.types[0] = 7;
  CHECK_THROWS_WITH(io::XdmfWriter(MPI_COMM_WORLD, dir, "bad", kNodes, owned, xyz, cells.types,
                                   cells.offsets, cells.nodes),
                    doctest::Contains("cell 0 has type 7"));
  cells.types[0] = cells_of_rank(w.rank, w.size).types[0];
  CHECK_THROWS_WITH(
      io::XdmfWriter(MPI_COMM_WORLD, dir, "bad", kNodes + 1, owned, xyz, cells.types, cells.offsets,
                     cells.nodes),
      doctest::Contains(("expected global_nodes = " + std::to_string(kNodes + 1)).c_str()));

  CHECK_THROWS_WITH(io::read_nodal_field(writer.mesh_file(), "pressure"),
                    doctest::Contains("dataset 'pressure'"));
  CHECK_THROWS_WITH(io::read_nodal_field(writer.mesh_file(), "topology"),
                    doctest::Contains("not a nodal field"));
  CHECK_THROWS_WITH(io::read_nodal_field(dir / "missing.h5", "p"), doctest::Contains("missing.h5"));
}
