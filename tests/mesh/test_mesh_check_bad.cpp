// Bad meshes (tests/data/meshes/bad, written by make_bad_meshes.py) each give their own clear
// error naming the file and the problem; none crashes. Plus check_mesh on hand-made meshes.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "mesh/gmsh_reader.hpp"
#include "mesh/mesh_check.hpp"

using namespace valsalva;

namespace {

const std::filesystem::path data = std::filesystem::path(VALSALVA_SOURCE_DIR) / "tests/data/meshes";

// Reads and checks a mesh; returns the error message ("" when the mesh is accepted).
std::string error_of(const std::filesystem::path& file) {
  try {
    mesh::check_mesh(mesh::read_gmsh(file));
  } catch (const mesh::MeshError& e) {
    return e.what();
  }
  return "";
}

struct BadCase {
  const char* file;
  std::vector<const char*> words;  // all must appear in the message
};

}  // namespace

TEST_CASE("the good cube passes") {
  CHECK(error_of(data / "cube_tets.msh") == "");
}

TEST_CASE("every bad mesh file gives its specific message") {
  const std::vector<BadCase> cases = {
      {"truncated.msh", {"truncated"}},
      {"cut_after_nodes.msh", {"no volume elements", "truncated"}},
      {"unknown_element.msh", {"cannot read the file", "element type Gmsh does not know"}},
      {"second_order_tet.msh", {"element 1", "unsupported type", "Tetrahedron 10"}},
      // Gmsh drops the 6-node triangle of a 2.2 file; its mid-edge nodes are left unused.
      {"second_order_face.msh", {"unused node 8", "(0.5, 0, 0)", "3 unused nodes"}},
      {"inverted_tet.msh", {"inverted", "cell 2", "tetrahedron", "signed volume -"}},
      {"degenerate_hex.msh", {"degenerate", "cell 0", "hexahedron", "1e-12"}},
      {"missing_group.msh",
       {"missing physical group", "2 boundary faces", "(0, 0, 1) - (1, 1, 1)"}},
      {"unused_node.msh", {"unused node 8", "(2, 2, 2)"}},
      {"duplicate_node_tag.msh", {"node tag 8 is defined twice", "(1, 1, 1)", "(2, 2, 2)"}},
      {"non_manifold.msh", {"non-manifold", "more than two cells"}},
      {"stray_face.msh", {"not a face of any cell", "'wall'"}},
      {"interior_face.msh", {"lies inside", "'wall'"}},
      {"undefined_node.msh", {"Wrong node index 42"}},
      {"not_a_mesh.msh", {"truncated or not a Gmsh mesh"}},
      // Was a bare std::bad_alloc from inside Gmsh (issue 23, item 11).
      {"huge_node_count.msh",
       {":15: the $Nodes header declares 1e+15 nodes", "hold at most 65 ", "corrupt header"}},
      {"huge_element_count.msh",
       {":21: the $Elements header declares 1e+15 elements", "hold at most 131 "}},
  };
  for (const auto& c : cases) {
    const auto file = data / "bad" / c.file;
    const std::string message = error_of(file);
    CAPTURE(message);
    CHECK(message.find(file.string()) != std::string::npos);
    for (const char* word : c.words) {
      const std::string expected = word;
      CAPTURE(expected);
      CHECK(message.find(word) != std::string::npos);
    }
  }
}
