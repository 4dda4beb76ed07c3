// Distributed values collected for a case's tables and comparisons: the owned values of every
// rank concatenated on rank 0 (profiles, samples), a velocity field by dual node on every rank
// (a run against its twin on the same mesh) and a scalar field likewise.
#pragma once

#include <mpi.h>

#include <vector>

#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::validation {

// Collective over `comm`: rank 0 gets every rank's `mine` in rank order, the others nothing.
std::vector<double> gather_to_root(const std::vector<double>& mine, MPI_Comm comm);

// Collective: u (3 values per node) by dual node (global order), the same on every rank.
std::vector<double> velocity_by_dual_node(const mesh::LocalMesh& local, const flow::VectorField& u,
                                          std::int64_t dual_nodes);

// Collective: a scalar field (one value per node, e.g. the pressure) by dual node, every rank.
std::vector<double> scalar_by_dual_node(const mesh::LocalMesh& local,
                                        const std::vector<double>& field, std::int64_t dual_nodes);

}  // namespace valsalva::validation
