// Gmsh smoke test through its C++ API: a 1 x 2 x 3 box meshed with tetrahedra; elements exist,
// both physical groups (volume "fluid", surface "walls") are present with their entities, and
// the tetrahedra fill the box: their volumes sum to 6 up to round-off (1e-12 relative).
#include <doctest/doctest.h>
#include <gmsh.h>

#include <cmath>
#include <map>
#include <vector>

TEST_CASE("Gmsh: box mesh with physical groups") {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("smoke_box");
  const int volume = gmsh::model::occ::addBox(0, 0, 0, 1, 2, 3);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary({{3, volume}}, boundary, false, false, false);
  std::vector<int> surfaces;
  for (const auto& [dim, tag] : boundary) surfaces.push_back(tag);
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "fluid");
  const int walls = gmsh::model::addPhysicalGroup(2, surfaces);
  gmsh::model::setPhysicalName(2, walls, "walls");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
  gmsh::model::mesh::generate(3);

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 3);
  REQUIRE(types.size() == 1);
  CHECK(types[0] == 4);  // 4-node tetrahedron
  const std::size_t tets = element_tags[0].size();
  CHECK(tets > 0);

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::map<std::string, int> dims;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    dims[name] = dim;
  }
  CHECK(dims == std::map<std::string, int>{{"fluid", 3}, {"walls", 2}});
  std::vector<int> wall_entities;
  gmsh::model::getEntitiesForPhysicalGroup(2, walls, wall_entities);
  CHECK(wall_entities.size() == 6);

  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(node_tags, xyz, param);
  std::map<std::size_t, std::size_t> index;
  for (std::size_t i = 0; i < node_tags.size(); ++i) index[node_tags[i]] = i;
  double total = 0.0;
  for (std::size_t t = 0; t < tets; ++t) {
    const std::size_t* n = &element_nodes[0][4 * t];
    double e[3][3];
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) e[k][d] = xyz[3 * index[n[k + 1]] + d] - xyz[3 * index[n[0]] + d];
    total += std::abs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
             6.0;
  }
  MESSAGE("Gmsh: ", tets, " tetrahedra, volume ", total);
  CHECK(total == doctest::Approx(6.0).epsilon(1e-12));
  gmsh::finalize();
}
