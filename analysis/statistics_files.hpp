// The phase statistics written by analysis::PhaseStatistics::write (<name>_mesh.h5, one
// <name>_<bin>.h5 per phase bin, <name>_phases.csv), read back for `valsalva compare-piv`.
// Files of one set can be mixed up with another run's: every size is checked across files
// before anything is read by index, and errors name both files and both sizes.
#pragma once

#include <filesystem>
#include <vector>

#include "analysis/piv_compare.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::analysis {

// The mesh of an XdmfWriter mesh file: coordinates and the Mixed topology (VTK order -> Gmsh);
// a topology naming a node the file lacks is refused.
mesh::Mesh read_statistics_mesh(const std::filesystem::path& file);

// bin -> phase time, the phase_time column of <name>_phases.csv (strict table reader).
std::vector<double> read_phase_times(const std::filesystem::path& file);

// One bin's statistics, each field checked against the mesh's node count before it is used (a
// bin file from another run carries its own, self-consistent node count).
SimulationStatistics read_statistics_bin(const std::filesystem::path& file, const mesh::Mesh& mesh,
                                         const std::filesystem::path& mesh_file);

}  // namespace valsalva::analysis
