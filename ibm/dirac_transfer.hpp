// Force spreading and velocity interpolation between Lagrangian markers and the distributed
// fluid mesh through the RKPM-corrected discrete Dirac kernel (ibm/kernels.hpp, ibm/rkpm.hpp):
//   spreading      f_j  = sum_i F_i phi(x_j, X_i)          (force density at fluid nodes)
//   interpolation  U_i  = sum_j u_j phi(x_j, X_i) V_j
// so that sum_j V_j f_j . u_j = sum_i F_i . U_i exactly: the two are adjoint.
//
// Marker ownership: markers are replicated on every rank (the same array everywhere). Each one
// is evaluated by exactly one rank, the owner of the fluid node nearest to it (ties to the lower
// rank, by MPI_MINLOC). That rank holds the marker's whole support among its owned and ghost
// nodes with the fewest ghost layers, and the rule needs no other knowledge than positions, so
// it does not depend on the partition shape. The evaluating rank builds phi over its owned and
// ghost nodes; spreading adds into them and a halo "add" returns ghost contributions to their
// owners; interpolation reads owned and ghost values after a halo "insert".
//
// The local mesh size at a marker is h of its nearest fluid node, or min_h when larger (it
// therefore jumps where the nearest node changes; on a graded mesh the kernel changes width
// there).
//
// Periodic meshes: a node stands at its periodic representative's position, so the support is
// searched around X - t for every period combination t (read off the local edges whose vector
// differs from the position difference) and each node is used at its image x_j + t. Markers must
// lie inside the periodic box (the structure wraps them); the nearest-node rule ignores images.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <vector>

#include "core/bucket_grid.hpp"
#include "ibm/kernels.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::ibm {

struct TransferOptions {
  KernelShape kernel;
  double min_rcond = 1e-6;     // smallest accepted reciprocal condition number of scaled M
  int max_growth = 2;          // an ill-conditioned M widens the support at most this often
  double growth_factor = 1.5;  // by this factor each time
  // A marker farther than this (in units of the local h) beyond the fluid boundary is refused:
  // the distance along the outward normal of the nearest boundary node in its support. Some
  // slack is needed because a curved wall's chord polygon lies inside the true wall (a marker
  // on the true wall, 2 h from a node of a wall of radius 8 h, is 0.25 h beyond the chord
  // plane there), and a clamped leaflet edge is often placed on the wall itself.
  double max_outside = 0.5;
  // Smallest h the kernel width is measured in [m]: h = max(h of the nearest node, min_h).
  // 0 = the local mesh size. A floor keeps the kernel (and so the coupling's stiffness bound,
  // which grows as the kernel shrinks) from following a few small cells that the geometry
  // forces, e.g. around a thin rigid frame the leaflets are attached to.
  double min_h = 0;
  // relocate(): a marker keeps the support and corrected weights built at its last location
  // until it is farther than this (in units of the h they were built with) from there; 0 =
  // every call rebuilds every marker. The kernel then lags the marker by less than this
  // distance, which changes interpolated values by O(this h |grad u|) and keeps spreading and
  // interpolation adjoint (they share the weights).
  double reuse_distance = 0;
};

// How much locating work the transfer did: locate and relocate calls, the markers they were
// given and those they (re)built, and the CPU seconds they took on this rank.
struct LocateCounts {
  std::int64_t calls = 0, markers = 0, rebuilt = 0;
  double cpu_seconds = 0;
};

class DiracTransfer {
 public:
  struct Weight {
    int node = 0;                           // local node (owned or ghost)
    double phi = 0.0;                       // corrected kernel phi(x_node, X) [1/m^3]
    Eigen::Vector3d offset{0.0, 0.0, 0.0};  // x_node - X, periodic image included
  };
  struct MarkerSupport {
    int marker = 0;          // index in the replicated marker array
    double h = 0.0;          // local mesh size used
    double width = 0.0;      // support width used, in units of h (grown if M was ill-conditioned)
    double rcond = 0.0;      // 1-norm reciprocal condition number of the scaled moment matrix
    int begin = 0, end = 0;  // range in weights()
  };

  // The mesh must outlive the transfer (its halo is used for every exchange).
  explicit DiracTransfer(mesh::LocalMesh& mesh, const TransferOptions& options = {});

  // Collective. Assigns every marker to its evaluating rank and builds the corrected kernel
  // there. Throws the same error on every rank, naming the marker index and position, when a
  // marker is outside the fluid mesh, when its support reaches the outermost ghost layer or is
  // wider than a period, when it lies more than max_outside h beyond the fluid boundary, or
  // when its moment matrix stays ill-conditioned after growing.
  void locate(std::span<const Eigen::Vector3d> markers);
  // Collective. As locate, but only when some marker moved farther than options.reuse_distance
  // h from where it was last located (or the marker count changed); else the supports and
  // weights stay as they are: those of locate at located_at(), bit for bit.
  void relocate(std::span<const Eigen::Vector3d> markers);
  // Where each marker's support was built (replicated; empty before the first locate).
  const std::vector<Eigen::Vector3d>& located_at() const { return located_at_; }
  const LocateCounts& counts() const { return counts_; }

  // Collective. `marker_force` (components per marker, replicated) -> `density` (components per
  // local node, overwritten): complete on owned nodes, ghosts refreshed by a halo insert.
  void spread(std::span<const double> marker_force, int components, std::span<double> density);
  void spread(std::span<const Eigen::Vector3d> marker_force, std::span<Eigen::Vector3d> density);
  // Collective. `reach` (one per local node, overwritten) = sum of |phi| over the supports that
  // hold the node: > 0 exactly on the nodes some marker's kernel reaches, complete on owned
  // nodes and halo-inserted into ghosts.
  void support_reach(std::span<double> reach);

  // Collective. Refreshes the ghosts of `field` (halo insert), then writes the interpolated
  // values at every marker into `marker_values` (replicated on every rank).
  void interpolate(std::span<double> field, int components, std::span<double> marker_values);
  void interpolate(std::span<Eigen::Vector3d> field, std::span<Eigen::Vector3d> marker_values);

  int num_markers() const { return num_markers_; }
  const std::vector<MarkerSupport>& supports() const { return supports_; }  // this rank's
  const std::vector<Weight>& weights() const { return weights_; }
  const mesh::LocalMesh& mesh() const { return *mesh_; }

 private:
  // |a - b| up to whole periods.
  double periodic_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Ownership and supports of every marker, located_at_ and located_h_.
  void locate_all(std::span<const Eigen::Vector3d> markers);
  // Builds the support of one marker on this rank; returns an error message or "".
  std::string build_support(int marker, const Eigen::Vector3d& x, int nearest);
  void check_sizes(const char* what, std::size_t marker_values, std::size_t node_values,
                   int components) const;

  mesh::LocalMesh* mesh_;
  TransferOptions options_;
  core::BucketGrid grid_;
  double h_max_ = 0.0;
  int outer_layer_ = 0;                   // deepest ghost layer of the distribution (0: none)
  std::vector<Eigen::Vector3d> periods_;  // independent periodic shifts seen on local edges
  std::vector<Eigen::Vector3d> images_;   // all sums of -1/0/+1 times each period (0 first)
  // Boundary nodes: outward unit normal (sum of the node's boundary areas) and the patch of its
  // largest boundary face; zero normal and -1 for interior nodes.
  std::vector<Eigen::Vector3d> boundary_normal_;
  std::vector<int> boundary_patch_;
  // The error for a marker beyond the fluid boundary (see max_outside), or "".
  std::string check_inside(int marker, const Eigen::Vector3d& x, double h) const;
  int num_markers_ = 0;
  std::vector<MarkerSupport> supports_;
  std::vector<Weight> weights_;
  std::vector<Eigen::Vector3d> located_at_;  // replicated, per marker
  std::vector<double> located_h_;            // replicated: the h its support was built with
  std::vector<double> built_h_;              // scratch of locate_all
  LocateCounts counts_;
  // Scratch reused between markers and calls (no allocation once warm).
  struct DistanceRank {  // layout of MPI_DOUBLE_INT for MPI_MINLOC
    double distance;
    int rank;
  };
  std::vector<DistanceRank> mine_, best_;
  std::vector<int> nearest_;
  std::vector<int> candidates_, found_;
  std::vector<Eigen::Vector3d> offset_;
  std::vector<double> psi_, volume_, phi_;
};

}  // namespace valsalva::ibm
