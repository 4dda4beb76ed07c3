// The node and element counts a Gmsh .msh file declares in its $Nodes and $Elements headers,
// checked against the file's size before Gmsh reads it: Gmsh allocates what the header claims,
// so a corrupt or hostile header (1e15 nodes in a 1 kB file) ends in a bare std::bad_alloc.
// Formats: MSH 2.2 (count on the line after the marker) and 4.1 ASCII or binary
// ("numEntityBlocks numNodes minTag maxTag", binary: four size_t).
#pragma once

#include <filesystem>

namespace valsalva::mesh {

// Throws MeshFileError naming the file, the header line, the count and the most the file's size
// can hold (every node takes at least 8 bytes in ASCII, 28 in binary; every element 4 and 8).
void check_msh_counts(const std::filesystem::path& path);

}  // namespace valsalva::mesh
