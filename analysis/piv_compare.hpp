// PIV against simulation statistics: the PIV plane is placed in the simulation frame by an
// origin and two orthonormal in-plane axes; each PIV point is located in the mesh
// (mesh::PointLocator) and the nodal statistics are interpolated there. The simulated in-plane
// velocity is (U.ex, U.ey); the simulated in-plane RMS along an axis e is sqrt(e^T R e), R the
// Reynolds stress tensor. Per frame (phase) and quantity: RMSE = sqrt(mean((sim - piv)^2)),
// normalised error = RMSE / sqrt(mean(piv^2)), Pearson correlation; masked PIV points and
// points outside the mesh are skipped (and counted).
//
// How a run or `valsalva compare-piv` uses it:
//   auto piv = analysis::read_piv(file);  analysis::PivPlane plane(origin, ex, ey);
//   analysis::PivSampler sampler(locator, plane, piv.frames[f]);         // once per PIV grid
//   auto fields = analysis::SimulationStatistics{...nodal arrays of the matching phase...};
//   auto cmp = analysis::compare_frame(piv.frames[f], sampler, fields);  // metrics + sampled
//   values analysis::write_comparison_csv(out / "phase_03.csv", piv.frames[f], cmp);   // for
//   plot_piv.py
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/piv_data.hpp"
#include "mesh/point_locator.hpp"

namespace valsalva::analysis {

struct PivPlane {
  // Throws std::invalid_argument when the axes are not orthogonal unit vectors (1e-9).
  PivPlane(const Eigen::Vector3d& origin, const Eigen::Vector3d& ex, const Eigen::Vector3d& ey);
  Eigen::Vector3d point(double x, double y) const { return origin + x * ex + y * ey; }
  Eigen::Vector3d origin, ex, ey;
};

// Nodal statistics of one phase, replicated, indexed by mesh node (as written by
// PhaseStatistics::write and read back with io::read_nodal_field). Empty RMS arrays: no RMS.
struct SimulationStatistics {
  std::vector<double> mean_velocity;  // 3 per node
  std::vector<double> rms_velocity;   // 3 per node (sqrt of <u'u'>, <v'v'>, <w'w'>)
  std::vector<double> reynolds_uv, reynolds_uw, reynolds_vw;  // 1 per node
  bool has_rms() const { return !rms_velocity.empty(); }
};

// Locations of a frame's points (built once per PIV grid).
class PivSampler {
 public:
  PivSampler(const mesh::PointLocator& locator, const PivPlane& plane, const PivFrame& frame);
  std::size_t outside() const { return outside_; }  // points not in the mesh
  const PivPlane& plane() const { return plane_; }
  // In-plane mean (u, v) and RMS (u_rms, v_rms; NaN without RMS) at point i; NaN if outside.
  Eigen::Vector4d sample(std::size_t i, const SimulationStatistics& s) const;
  // The same at an arbitrary point of the plane (NaN outside the mesh).
  Eigen::Vector4d sample_at(double x, double y, const SimulationStatistics& s) const;

 private:
  const mesh::PointLocator* locator_;
  PivPlane plane_;
  std::vector<mesh::PointLocation> locations_;  // cell -1 when outside
  std::size_t outside_ = 0;
};

struct FieldMetrics {
  double rmse = NAN, normalised_error = NAN, correlation = NAN;
  std::size_t points = 0;
};
FieldMetrics field_metrics(const std::vector<double>& sim, const std::vector<double>& piv,
                           const std::vector<std::uint8_t>& use);

struct FrameComparison {
  std::string label;
  double phase = NAN;
  FieldMetrics u, v, u_rms, v_rms;  // RMS metrics NaN when either side has no RMS
  std::size_t masked = 0, outside = 0;
  std::vector<double> sim_u, sim_v, sim_urms, sim_vrms;  // per PIV point
};
FrameComparison compare_frame(const PivFrame& frame, const PivSampler& sampler,
                              const SimulationStatistics& sim);

// A velocity profile along a straight line of the PIV plane: simulation sampled at `points`
// evenly spaced points; PIV from the nearest valid point within `max_distance` (else NaN).
struct ProfileLine {
  std::string name;
  Eigen::Vector2d a{0, 0}, b{0, 0};
  int points = 50;
};
struct Profile {
  std::vector<double> s, x, y, sim_u, sim_v, piv_u, piv_v;
};
Profile sample_profile(const ProfileLine& line, const PivSampler& sampler, const PivFrame& frame,
                       const SimulationStatistics& sim, double max_distance);

// CSV for plot_piv.py: x,y,valid,piv_u,piv_v,sim_u,sim_v[,piv_urms,piv_vrms,sim_urms,sim_vrms].
void write_comparison_csv(const std::filesystem::path& path, const PivFrame& frame,
                          const FrameComparison& c);
void write_profile_csv(const std::filesystem::path& path, const Profile& p);
// One row per frame and quantity: frame,phase,quantity,rmse,normalised_error,correlation,points.
void write_metrics_csv(const std::filesystem::path& path, const std::vector<FrameComparison>& c);

}  // namespace valsalva::analysis
