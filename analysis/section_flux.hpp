// Volume flux through a named interior section: the plane through `point` with normal `normal`,
// optionally bounded (a disc of radius r about `point`, or an axis-aligned box) to pick one cut
// of the mesh. The solver is node-centred: the projected face flux F_e (flow/face_flux.hpp) is
// the volume flux through the dual face of edge e, and it is what the projection makes
// discretely divergence-free (sum_k F_jk + B_j = 0 at every node, B_j the boundary flux). The
// section flux is the sum of +-F_e over the edges that cross the plane (one end on the plane or
// behind it, the other in front) whose crossing point lies in the bound:
//   Q = sum_{e = (j, k) cut} sign_e F_e,   sign_e = +1 when j is behind and k in front.
// Those dual faces separate the dual cells behind the plane from those in front; when the cut
// crosses the whole flow domain (e.g. a disc at least as wide as a pipe), summing the discrete
// continuity over the nodes behind it gives Q = - (boundary flux of those nodes), i.e. the inlet
// flow rate to the Poisson tolerance, with no interpolation error. A bound that clips the flow
// (a disc smaller than the pipe) gives the flux through the dual faces it picks, an
// approximation of the flux through the disc of O(h) in the clipped rim.
// On a periodic mesh an edge across a periodic pair is taken from j to k's image next to j, so
// that a plane across the periodic direction cuts the domain once (a periodic pipe's section).
// Each cut edge is counted once over all ranks (by the rank that owns its end of lower global
// id), so the value is the same at any rank count up to the order of the final sum.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flow/face_flux.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::analysis {

struct SectionOptions {
  enum class Bound { none, disc, box };
  std::string name;
  Eigen::Vector3d point{0, 0, 0}, normal{0, 0, 1};  // m, - (any length > 0)
  Bound bound = Bound::none;
  double radius = 0;                         // disc, m
  Eigen::Vector3d lo{0, 0, 0}, hi{0, 0, 0};  // box, m
};

class SectionFlux {
 public:
  // Collective. Throws std::invalid_argument for a zero normal or radius, std::runtime_error
  // naming section.<name> when the plane cuts no mesh edge within the bound.
  SectionFlux(const mesh::LocalMesh& local, SectionOptions options);

  const SectionOptions& options() const { return options_; }
  std::int64_t edges() const { return global_edges_; }  // cut edges over all ranks
  // sum_e sign_e S_e . n over the cut (m^2): the cut's dual faces projected on the plane.
  double projected_area() const { return area_; }
  // Collective: Q in m^3/s, positive along the normal. `face_flux`: every local edge.
  double flux(const flow::EdgeField& face_flux) const;

 private:
  const mesh::LocalMesh* local_;
  SectionOptions options_;
  std::vector<int> edges_;     // local edges this rank counts
  std::vector<double> signs_;  // +1: the local orientation j -> k goes along the normal
  std::int64_t global_edges_ = 0;
  double area_ = 0;
};

}  // namespace valsalva::analysis
