#include "mesh/local_mesh.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/enum_names.hpp"

namespace valsalva::mesh {

namespace {

struct Graph {
  std::vector<idx_t> xadj, adjncy;
};

Graph node_graph(const DualMetrics& m) {
  const auto n = static_cast<std::size_t>(m.num_nodes());
  std::vector<idx_t> degree(n, 0);
  for (const auto& e : m.edges) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  Graph g;
  g.xadj.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) g.xadj[i + 1] = g.xadj[i] + degree[i];
  g.adjncy.resize(g.xadj[n]);
  std::vector<idx_t> fill(g.xadj.begin(), g.xadj.end() - 1);
  for (const auto& e : m.edges) {
    g.adjncy[fill[e[0]]++] = static_cast<idx_t>(e[1]);
    g.adjncy[fill[e[1]]++] = static_cast<idx_t>(e[0]);
  }
  return g;
}

std::vector<int> metis_partition(const DualMetrics& m, int parts) {
  Graph g = node_graph(m);
  idx_t n = static_cast<idx_t>(m.num_nodes()), ncon = 1, nparts = parts, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // reproducible partitions
  std::vector<idx_t> part(static_cast<std::size_t>(n), 0);
  const int status =
      METIS_PartGraphKway(&n, &ncon, g.xadj.data(), g.adjncy.data(), nullptr, nullptr, nullptr,
                          &nparts, nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error(
        fmt::format("METIS_PartGraphKway failed with status {} for {} parts", status, parts));
  return {part.begin(), part.end()};
}

}  // namespace

constexpr core::EnumNames<PartitionMethod, 2> kMethods{{"metis", "block"}, "partition method"};

VALSALVA_ENUM_NAMES(PartitionMethod, kMethods, partition_method_names, to_string,
                    parse_partition_method)

std::vector<int> partition_nodes(const DualMetrics& metrics, const core::Comm& comm,
                                 PartitionMethod method) {
  const GlobalIndex n = metrics.num_nodes();
  std::vector<int> part(static_cast<std::size_t>(n), 0);
  if (comm.size() == 1) return part;
  if (n < comm.size())
    throw std::runtime_error(
        fmt::format("cannot split {} mesh nodes over {} ranks", n, comm.size()));
  if (method == PartitionMethod::block) {
    for (GlobalIndex i = 0; i < n; ++i) part[i] = static_cast<int>(i * comm.size() / n);
    return part;
  }
  if (comm.root()) part = metis_partition(metrics, comm.size());
  comm.broadcast(std::span<int>(part.data(), n));
  return part;
}

LocalMesh distribute(const Mesh& mesh, const DualMetrics& m, MPI_Comm mpi_comm,
                     const PartitionOptions& options, const GhostRegion& extra) {
  if (options.ghost_layers < 1)
    throw std::invalid_argument("partition: ghost_layers must be at least 1");
  LocalMesh local;
  local.comm = core::Comm(mpi_comm);
  const core::Comm& comm = local.comm;
  const GlobalIndex n = m.num_nodes();
  const std::vector<int> part = partition_nodes(m, comm, options.method);

  // Global (hypre) numbering: ranks in order, dual-node order within a rank.
  std::vector<GlobalIndex> first(comm.size() + 1, 0);
  for (int p : part) ++first[p + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<GlobalIndex> new_id(static_cast<std::size_t>(n));
  {
    std::vector<GlobalIndex> next(first.begin(), first.end() - 1);
    for (GlobalIndex i = 0; i < n; ++i) new_id[i] = next[part[i]]++;
  }
  local.first_owned = first[comm.rank()];
  local.global_nodes = n;

  // Local nodes: owned in order, then ghost layers by breadth-first search on the edge graph.
  const Graph g = node_graph(m);
  std::vector<int> local_of(static_cast<std::size_t>(n), -1);
  auto add_local = [&](GlobalIndex d, int layer) {
    local_of[d] = local.num_local();
    local.dual_node.push_back(d);
    local.global_id.push_back(new_id[d]);
    local.ghost_layer.push_back(layer);
  };
  for (GlobalIndex d = 0; d < n; ++d)
    if (part[d] == comm.rank()) add_local(d, 0);
  local.num_owned = local.num_local();
  // Layers 1..ghost_layers take every neighbour. Past them only nodes inside the box nearer
  // than `reach` to the owned node they were reached from (`origin`) are expanded, until a layer
  // has none on any rank: its nodes are the fringe beyond the distance.
  const double reach = extra.distance;
  std::vector<GlobalIndex> origin(local.dual_node.begin(), local.dual_node.end());
  std::vector<char> expand(local.dual_node.size(), 1);
  std::size_t layer_begin = 0, layer_end = local.dual_node.size();
  for (int layer = 1;; ++layer) {
    const bool beyond = layer > options.ghost_layers;
    std::vector<std::pair<GlobalIndex, GlobalIndex>> found;  // node, its origin
    auto distance = [&](GlobalIndex a, GlobalIndex b) {
      return (m.position[a] - m.position[b]).norm();
    };
    for (std::size_t i = layer_begin; i < layer_end; ++i) {
      if (!expand[i]) continue;
      const GlobalIndex d = local.dual_node[i];
      for (idx_t a = g.xadj[d]; a < g.xadj[d + 1]; ++a) {
        const GlobalIndex e = g.adjncy[a];
        if (local_of[e] <= -2) {  // claimed in this layer: keep the nearer origin
          auto& o = found[static_cast<std::size_t>(-local_of[e] - 2)].second;
          if (distance(e, origin[i]) < distance(e, o)) o = origin[i];
          continue;
        }
        if (local_of[e] != -1) continue;
        if (beyond && !extra.box.contains(m.position[e])) continue;
        local_of[e] = -2 - static_cast<int>(found.size());
        found.emplace_back(e, origin[i]);
      }
    }
    std::sort(found.begin(), found.end(),
              [&](const auto& a, const auto& b) { return new_id[a.first] < new_id[b.first]; });
    bool near = false;
    for (const auto& [d, from] : found) {
      add_local(d, layer);
      origin.push_back(from);
      const bool is_near = extra.box.contains(m.position[d]) && distance(d, from) < reach;
      expand.push_back(layer < options.ghost_layers || is_near);
      near = near || is_near;
    }
    layer_begin = layer_end;
    layer_end = local.dual_node.size();
    if (layer >= options.ghost_layers && (!(reach > 0) || !comm.any(near))) break;
  }
  local.frontier.assign(local.dual_node.size(), 0);
  for (std::size_t i = local.num_owned; i < local.dual_node.size(); ++i) {
    const GlobalIndex d = local.dual_node[i];
    for (idx_t a = g.xadj[d]; a < g.xadj[d + 1]; ++a)
      if (local_of[g.adjncy[a]] < 0) local.frontier[i] = 1;
  }

  const int nl = local.num_local();
  local.position.resize(nl);
  local.volume.resize(nl);
  local.h.resize(nl);
  local.first_moment.resize(nl);
  local.second_moment.resize(nl);
  local.gradient_correction.resize(nl);
  for (int i = 0; i < nl; ++i) {
    const GlobalIndex d = local.dual_node[i];
    local.position[i] = m.position[d];
    local.volume[i] = m.volume[d];
    local.h[i] = m.h[d];
    local.first_moment[i] = m.first_moment[d];
    local.second_moment[i] = m.second_moment[d];
    local.gradient_correction[i] = m.gradient_correction[d];
  }

  // Edges: those touching an owned node first, then ghost-ghost edges.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
      const int a = local_of[m.edges[e][0]], b = local_of[m.edges[e][1]];
      if (a < 0 || b < 0) continue;
      const bool owned = a < local.num_owned || b < local.num_owned;
      if (owned != (pass == 0)) continue;
      // Orient local edges from the lower to the higher local index.
      const bool flip = a > b;
      local.edges.push_back({flip ? b : a, flip ? a : b});
      local.edge_normal.push_back(flip ? Eigen::Vector3d(-m.edge_normal[e]) : m.edge_normal[e]);
      local.edge_vector.push_back(flip ? Eigen::Vector3d(-m.edge_vector[e]) : m.edge_vector[e]);
      local.global_edge.push_back(static_cast<GlobalIndex>(e));
      local.edge_flipped.push_back(flip ? 1 : 0);
    }
    if (pass == 0) local.num_owned_edges = static_cast<int>(local.edges.size());
  }
  for (const auto& b : m.boundary)
    if (local_of[b.node] >= 0) local.boundary.push_back({local_of[b.node], b.patch, b.area});
  local.patch_names = mesh.patch_names;

  // Halo: ghosts ask their owners, through one all-to-all of request counts and ids.
  const int size = comm.size();
  std::vector<std::vector<GlobalIndex>> wanted(size);
  std::vector<std::vector<int>> recv_local(size);
  for (int i = local.num_owned; i < nl; ++i) {
    const int owner = part[local.dual_node[i]];
    wanted[owner].push_back(local.dual_node[i]);
    recv_local[owner].push_back(i);
  }
  std::vector<int> send_counts(size), recv_counts(size);
  for (int r = 0; r < size; ++r) send_counts[r] = static_cast<int>(wanted[r].size());
  VALSALVA_MPI(
      MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, comm.get()));
  std::vector<int> sdispl(size + 1, 0), rdispl(size + 1, 0);
  for (int r = 0; r < size; ++r) {
    sdispl[r + 1] = sdispl[r] + send_counts[r];
    rdispl[r + 1] = rdispl[r] + recv_counts[r];
  }
  std::vector<GlobalIndex> sendbuf(sdispl[size]), recvbuf(rdispl[size]);
  for (int r = 0; r < size; ++r)
    std::copy(wanted[r].begin(), wanted[r].end(), sendbuf.begin() + sdispl[r]);
  VALSALVA_MPI(MPI_Alltoallv(sendbuf.data(), send_counts.data(), sdispl.data(), MPI_INT64_T,
                             recvbuf.data(), recv_counts.data(), rdispl.data(), MPI_INT64_T,
                             comm.get()));
  std::vector<Halo::Neighbour> neighbours;
  for (int r = 0; r < size; ++r) {
    if (send_counts[r] == 0 && recv_counts[r] == 0) continue;
    Halo::Neighbour nb;
    nb.rank = r;
    nb.recv = recv_local[r];
    for (int k = rdispl[r]; k < rdispl[r + 1]; ++k) {
      const int li = local_of[recvbuf[k]];
      if (li < 0 || li >= local.num_owned)
        throw std::logic_error("halo: rank asked for a node this rank does not own");
      nb.send.push_back(li);
    }
    neighbours.push_back(std::move(nb));
  }
  local.halo = Halo(comm.get(), std::move(neighbours));
  return local;
}

}  // namespace valsalva::mesh
