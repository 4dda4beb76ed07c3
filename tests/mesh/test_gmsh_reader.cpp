// Gmsh import: meshes made with the Gmsh API are written as .msh 4.1 ASCII, 4.1 binary and 2.2
// ASCII and read back; counts, patch names, volumes and areas are checked against the model.
#include <doctest/doctest.h>
#include <gmsh.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <string>

#include "mesh/gmsh_reader.hpp"
#include "mesh/mesh_check.hpp"

using namespace valsalva;
namespace fs = std::filesystem;

namespace {

struct Format {
  const char* name;
  double version;
  int binary;
};
constexpr Format formats[] = {{"v41_ascii", 4.1, 0}, {"v41_binary", 4.1, 1}, {"v22_ascii", 2.2, 0}};

fs::path scratch_dir(const std::string& name) {
  fs::path dir =
      fs::temp_directory_path() / ("valsalva_test_gmsh_" + std::to_string(getpid())) / name;
  fs::create_directories(dir);
  return dir;
}

void write_all_formats(const fs::path& dir) {
  for (const auto& f : formats) {
    gmsh::option::setNumber("Mesh.MshFileVersion", f.version);
    gmsh::option::setNumber("Mesh.Binary", f.binary);
    gmsh::write((dir / (std::string(f.name) + ".msh")).string());
  }
}

double total_volume(const mesh::Mesh& mesh) {
  double v = 0;
  for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c) v += mesh::cell_volume(mesh, c);
  return v;
}

std::map<std::string, double> patch_areas(const mesh::Mesh& mesh) {
  std::map<std::string, double> area;
  for (mesh::GlobalIndex f = 0; f < mesh.num_faces(); ++f)
    area[mesh.patch_names[mesh.face_patches[f]]] += mesh::face_area(mesh, mesh.face(f)).norm();
  return area;
}

std::map<mesh::CellType, int> type_counts(const mesh::Mesh& mesh) {
  std::map<mesh::CellType, int> n;
  for (auto t : mesh.cell_types) ++n[t];
  return n;
}

}  // namespace

TEST_CASE("tetrahedral box written by Gmsh reads back identically in all three formats") {
  const fs::path dir = scratch_dir("box");
  std::size_t model_nodes = 0, model_tets = 0;
  {
    mesh::GmshSession session;
    gmsh::model::add("box");
    gmsh::model::occ::addBox(0, 0, 0, 1.0, 2.0, 0.5);
    gmsh::model::occ::synchronize();
    std::vector<int> inlet, walls;
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    for (auto [dim, tag] : surfaces) {
      double x, y, z;
      gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
      (std::abs(x) < 1e-12 ? inlet : walls).push_back(tag);
    }
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, inlet), "inlet");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, walls), "walls");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "fluid");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
    gmsh::model::mesh::generate(3);
    std::vector<std::size_t> tags;
    std::vector<double> xyz, uvw;
    gmsh::model::mesh::getNodes(tags, xyz, uvw);
    model_nodes = tags.size();
    std::vector<std::size_t> tets, tet_nodes;
    gmsh::model::mesh::getElementsByType(4, tets, tet_nodes);
    model_tets = tets.size();
    write_all_formats(dir);
  }
  REQUIRE(model_tets > 100);
  for (const auto& f : formats) {
    const std::string format = f.name;
    CAPTURE(format);
    const mesh::Mesh mesh = mesh::read_gmsh(dir / (std::string(f.name) + ".msh"));
    CHECK(mesh.source == (dir / (std::string(f.name) + ".msh")).string());
    CHECK(mesh.num_nodes() == static_cast<mesh::GlobalIndex>(model_nodes));
    CHECK(mesh.num_cells() == static_cast<mesh::GlobalIndex>(model_tets));
    CHECK(type_counts(mesh)[mesh::CellType::tetra] == static_cast<int>(model_tets));
    CHECK(mesh.patch_names == std::vector<std::string>{"inlet", "walls"});
    CHECK(mesh.region_names == std::vector<std::string>{"fluid"});
    CHECK_NOTHROW(mesh::check_mesh(mesh));
    // Planar box: the tetrahedra fill it exactly, up to round-off.
    CHECK(total_volume(mesh) == doctest::Approx(1.0).epsilon(1e-12));
    auto area = patch_areas(mesh);
    CHECK(area["inlet"] == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(area["walls"] == doctest::Approx(6.0).epsilon(1e-12));  // x=1: 1, y: 2*0.5, z: 2*2
  }
  fs::remove_all(dir);
}

// A hand-built hybrid mesh of three unit cubes: [0,1]^3 as six pyramids around its centre,
// [1,2]x[0,1]x[0,1] as one hexahedron, [1,2]x[0,1]x[1,2] as two prisms; sparse node tags.
TEST_CASE("hybrid pyramid/hexahedron/prism mesh keeps Gmsh node order in all three formats") {
  const fs::path dir = scratch_dir("hybrid");
  {
    mesh::GmshSession session;
    gmsh::model::add("hybrid");
    gmsh::model::addDiscreteEntity(3, 1);
    gmsh::model::addDiscreteEntity(2, 1);
    gmsh::model::addDiscreteEntity(2, 2);
    // Node tag = 100 * (1 + i + 3 j + 9 k) + 7 for the lattice point (i, j, k), plus the centre.
    auto tag = [](int i, int j, int k) { return std::size_t(100 * (1 + i + 3 * j + 9 * k) + 7); };
    std::vector<std::size_t> node_tags;
    std::vector<double> xyz;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
          if (i == 0 && k == 2) continue;  // outside the three cubes
          node_tags.push_back(tag(i, j, k));
          xyz.insert(xyz.end(), {double(i), double(j), double(k)});
        }
    const std::size_t centre = 99999;
    node_tags.push_back(centre);
    xyz.insert(xyz.end(), {0.5, 0.5, 0.5});
    gmsh::model::mesh::addNodes(3, 1, node_tags, xyz);
    // Cube [0,1]^3 faces, each listed counter-clockwise seen from outside.
    const std::vector<std::array<std::size_t, 4>> cube_faces = {
        {tag(0, 0, 0), tag(0, 1, 0), tag(1, 1, 0), tag(1, 0, 0)},   // z = 0
        {tag(0, 0, 1), tag(1, 0, 1), tag(1, 1, 1), tag(0, 1, 1)},   // z = 1
        {tag(0, 0, 0), tag(1, 0, 0), tag(1, 0, 1), tag(0, 0, 1)},   // y = 0
        {tag(0, 1, 0), tag(0, 1, 1), tag(1, 1, 1), tag(1, 1, 0)},   // y = 1
        {tag(0, 0, 0), tag(0, 0, 1), tag(0, 1, 1), tag(0, 1, 0)},   // x = 0
        {tag(1, 0, 0), tag(1, 1, 0), tag(1, 1, 1), tag(1, 0, 1)}};  // x = 1
    // Pyramid base 0-1-2-3 is counter-clockwise seen from the apex: reverse the outward face.
    std::vector<std::size_t> pyramids;
    for (const auto& q : cube_faces)
      pyramids.insert(pyramids.end(), {q[3], q[2], q[1], q[0], centre});
    const std::vector<std::size_t> hexa = {tag(1, 0, 0), tag(2, 0, 0), tag(2, 1, 0), tag(1, 1, 0),
                                           tag(1, 0, 1), tag(2, 0, 1), tag(2, 1, 1), tag(1, 1, 1)};
    // Prisms: triangles in the xz-plane at y = 0 extruded to y = 1; the bottom triangle is
    // counter-clockwise seen from the top one, as Gmsh orders prisms.
    auto prism = [&](std::array<std::array<int, 2>, 3> t) {
      std::vector<std::size_t> p;
      for (auto [i, k] : t) p.push_back(tag(i, 0, k));
      for (auto [i, k] : t) p.push_back(tag(i, 1, k));
      return p;
    };
    std::vector<std::size_t> prisms = prism({{{1, 1}, {1, 2}, {2, 1}}});
    const auto second = prism({{{2, 1}, {1, 2}, {2, 2}}});
    prisms.insert(prisms.end(), second.begin(), second.end());
    gmsh::model::mesh::addElementsByType(1, 7, {}, pyramids);
    gmsh::model::mesh::addElementsByType(1, 5, {}, hexa);
    gmsh::model::mesh::addElementsByType(1, 6, {}, prisms);
    // Boundary: x = 0 as "inlet" (one quad), everything else as "wall".
    std::vector<std::size_t> wall_quads, wall_tris;
    for (std::size_t f = 0; f < cube_faces.size(); ++f)
      if (f != 4 && f != 5)
        wall_quads.insert(wall_quads.end(), cube_faces[f].begin(), cube_faces[f].end());
    auto quad = [&](std::array<std::array<int, 3>, 4> q) {
      for (auto [i, j, k] : q) wall_quads.push_back(tag(i, j, k));
    };
    quad({{{1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 0, 0}}});  // hex bottom
    quad({{{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}}});  // hex y = 0
    quad({{{1, 1, 0}, {1, 1, 1}, {2, 1, 1}, {2, 1, 0}}});  // hex y = 1
    quad({{{2, 0, 0}, {2, 1, 0}, {2, 1, 1}, {2, 0, 1}}});  // hex x = 2
    quad({{{1, 1, 1}, {1, 1, 2}, {1, 0, 2}, {1, 0, 1}}});  // prisms x = 1 (above the cube)
    quad({{{2, 0, 1}, {2, 1, 1}, {2, 1, 2}, {2, 0, 2}}});  // prisms x = 2
    quad({{{1, 0, 2}, {1, 1, 2}, {2, 1, 2}, {2, 0, 2}}});  // prisms z = 2
    for (auto y : {0, 1})
      for (auto t : {std::array<std::array<int, 2>, 3>{{{1, 1}, {1, 2}, {2, 1}}},
                     std::array<std::array<int, 2>, 3>{{{2, 1}, {1, 2}, {2, 2}}}})
        for (auto [i, k] : t) wall_tris.push_back(tag(i, y, k));
    gmsh::model::mesh::addElementsByType(1, 3, {}, wall_quads);
    gmsh::model::mesh::addElementsByType(1, 2, {}, wall_tris);
    gmsh::model::mesh::addElementsByType(2, 3, {},
                                         {tag(0, 0, 0), tag(0, 0, 1), tag(0, 1, 1), tag(0, 1, 0)});
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {1}), "wall");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {2}), "inlet");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "solid");
    write_all_formats(dir);
  }
  for (const auto& f : formats) {
    const std::string format = f.name;
    CAPTURE(format);
    const mesh::Mesh mesh = mesh::read_gmsh(dir / (std::string(f.name) + ".msh"));
    CHECK(mesh.num_nodes() == 17);  // 16 lattice points and the centre
    auto n = type_counts(mesh);
    CHECK(n[mesh::CellType::pyramid] == 6);
    CHECK(n[mesh::CellType::hexa] == 1);
    CHECK(n[mesh::CellType::prism] == 2);
    CHECK(n[mesh::CellType::tetra] == 0);
    CHECK(mesh.patch_names == std::vector<std::string>{"wall", "inlet"});
    CHECK(mesh.region_names == std::vector<std::string>{"solid"});
    // Every cell positive with its Gmsh node order, faces matched to the tagged boundary.
    CHECK_NOTHROW(mesh::check_mesh(mesh));
    for (mesh::GlobalIndex c = 0; c < mesh.num_cells(); ++c)
      CHECK(mesh::cell_volume(mesh, c) ==
            doctest::Approx(mesh.cell_types[c] == mesh::CellType::pyramid ? 1.0 / 6
                            : mesh.cell_types[c] == mesh::CellType::prism ? 0.5
                                                                          : 1.0)
                .epsilon(1e-14));
    CHECK(total_volume(mesh) == doctest::Approx(3.0).epsilon(1e-14));
    auto area = patch_areas(mesh);
    CHECK(area["inlet"] == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(area["wall"] == doctest::Approx(13.0).epsilon(1e-14));  // 14 unit squares minus inlet
  }
  fs::remove_all(dir);
}

TEST_CASE("missing and unreadable files give errors naming the file") {
  const fs::path missing = scratch_dir("missing") / "nowhere.msh";
  try {
    mesh::read_gmsh(missing);
    FAIL("no exception");
  } catch (const mesh::MeshFileError& e) {
    CHECK(std::string(e.what()).find(missing.string()) != std::string::npos);
    CHECK(std::string(e.what()).find("cannot open") != std::string::npos);
  }
  try {
    mesh::read_gmsh(missing.parent_path());
    FAIL("no exception");
  } catch (const mesh::MeshFileError& e) {
    CHECK(std::string(e.what()).find("not a regular file") != std::string::npos);
  }
  fs::remove_all(missing.parent_path());
}

TEST_CASE("a file cut anywhere gives MeshFileError or the complete mesh, never a crash") {
  const fs::path dir = scratch_dir("cut");
  {
    mesh::GmshSession session;
    gmsh::model::add("small");
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {1, 2, 3, 4, 5, 6}), "wall");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "fluid");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.7);
    gmsh::model::mesh::generate(3);
    write_all_formats(dir);
  }
  for (const auto& f : formats) {
    const std::string format = f.name;
    CAPTURE(format);
    const fs::path full = dir / (format + ".msh");
    const mesh::Mesh reference = mesh::read_gmsh(full);
    std::ifstream in(full, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const fs::path cut = dir / ("cut_" + format + ".msh");
    int errors = 0, complete = 0;
    for (std::size_t size = 0; size < bytes.size(); size += 1 + bytes.size() / 60) {
      std::ofstream(cut, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
      try {
        const mesh::Mesh mesh = mesh::read_gmsh(cut);
        CHECK(mesh.cell_nodes == reference.cell_nodes);  // only a complete mesh may come back
        CHECK(mesh.face_nodes == reference.face_nodes);
        ++complete;
      } catch (const mesh::MeshFileError& e) {
        CHECK(std::string(e.what()).find(cut.string()) != std::string::npos);
        ++errors;
      }
    }
    MESSAGE(format, ": ", errors, " cuts rejected, ", complete, " complete");
    CHECK(errors >= 55);
  }
  fs::remove_all(dir);
}

namespace {

// Writes a meshed unit box (format 4.1 ASCII) after `setup` has run on the Gmsh model, and
// returns the message of read_gmsh + check_mesh ("" when accepted).
template <class Setup>
std::string box_error(const std::string& name, Setup setup) {
  const fs::path file = scratch_dir("variants") / (name + ".msh");
  {
    mesh::GmshSession session;
    gmsh::model::add(name);
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.7);
    setup();
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write(file.string());
  }
  std::string message;
  try {
    mesh::check_mesh(mesh::read_gmsh(file));
  } catch (const mesh::MeshError& e) {
    message = e.what();
  }
  fs::remove(file);
  return message;
}

}  // namespace

TEST_CASE("Gmsh-written variants: second order, overlapping groups, no groups") {
  auto contains = [](const std::string& message, const char* word) {
    CAPTURE(message);
    CAPTURE(word);
    CHECK(message.find(word) != std::string::npos);
  };
  const std::string second_order = box_error("second_order", [] {
    gmsh::model::addPhysicalGroup(2, {1, 2, 3, 4, 5, 6});
    gmsh::model::addPhysicalGroup(3, {1});
    gmsh::option::setNumber("Mesh.ElementOrder", 2);
  });
  contains(second_order, "unsupported type 'Tetrahedron 10'");
  contains(second_order, "second_order.msh: element ");

  const std::string two_groups = box_error("two_groups", [] {
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {1, 2, 3, 4, 5, 6}), "wall");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "a");
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "b");
  });
  contains(two_groups, "volume entity 1 belongs to two physical groups, 'a' and 'b'");

  // Without physical groups Gmsh saves every element; no surface is a patch.
  const std::string no_groups = box_error("no_groups", [] {});
  contains(no_groups, "boundary faces belong to no boundary patch (missing physical group?)");
  contains(no_groups, "(0, 0, 0) - (1, 1, 1)");

  // Only part of the boundary tagged: the message locates the untagged faces (face x = 0 is
  // surface 1 of an OpenCASCADE box).
  const std::string part = box_error("part", [] {
    gmsh::model::addPhysicalGroup(2, {2, 3, 4, 5, 6});
    gmsh::model::addPhysicalGroup(3, {1});
  });
  contains(part, "missing physical group");
  contains(part, "(0, 0, 0) - (0, 1, 1)");
}
