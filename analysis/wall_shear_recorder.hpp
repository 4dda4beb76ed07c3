// Wall shear stress of a run on its wall patches (flow/wall_shear.hpp): tau_w from the
// residual (reaction) force of each wall node's dual volume, the area-weighted mean |tau_w| per
// patch as a time series, TAWSS and OSI accumulated from `start_time`, saved in checkpoints and
// written per wall node at the end (gathered on rank 0: the same files at any rank count).
//   wall_shear_history.csv  time, <patch>_mean_wss (Pa) per patch
//   wall_shear.csv          per wall node: TAWSS, OSI, RRT, last tau_w (wall_shear_rows.hpp)
//   wall_shear_summary.csv  per patch: area-weighted means and maxima (wall_shear_summary.hpp),
//                           also printed, one line per patch
//   wall_shear_surface.xmf  the patches' faces with those nodal values (wall_shear_surface.hpp)
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "analysis/analysis_options.hpp"
#include "flow/operators.hpp"
#include "flow/projection_rk4.hpp"
#include "flow/wall_shear.hpp"
#include "io/checkpoint.hpp"
#include "mesh/dual_metrics.hpp"
#include "mesh/local_mesh.hpp"
#include "mesh/mesh.hpp"

namespace valsalva::analysis {

class WallShearRecorder {
 public:
  // `dynamic_viscosity` in Pa s. Collective. Throws naming an unknown patch.
  WallShearRecorder(const mesh::LocalMesh& local, WallShearOptions options, double density,
                    double dynamic_viscosity, const std::filesystem::path& run_dir, bool append);

  // Collective: evaluates tau_w and, from start_time on, adds it with the time elapsed since the
  // previous sample.
  void sample(const flow::FlowState& state);
  // A body-force density acting in the fluid (a prescribed [forcing]): the wall nodes' share of
  // it belongs to the fluid's momentum balance, not to the wall (without it a uniform force F
  // adds F h/2 per unit area to tau_w, h/H of a channel's wall shear). Must outlive the recorder.
  void set_body_force(const flow::VectorField* force_density) { body_force_ = force_density; }
  // The local nodes inside an immersed structure's kernel support at the sampled state, marked
  // by `source` (collective): each wall node's time there is accumulated over the window (the
  // support_fraction of wall_shear.csv and the "clear" means of the summary).
  using NodeMask = std::function<void(std::vector<char>&)>;
  void set_support_nodes(NodeMask source) { support_nodes_ = std::move(source); }
  // A non-Newtonian fluid (flow.viscosity_model): tau_w with the nodal viscosity
  // mu(gamma_dot) of the sampled velocity, in place of the constructor's dynamic_viscosity.
  void set_viscosity_model(const flow::ViscosityModel& model) { model_ = model; }
  std::vector<io::CheckpointArray> checkpoint_arrays() const;
  void restore(const io::CheckpointReader& reader);  // collective
  // Collective; `mesh` and `metrics` give the patches' faces (the surface file).
  void write(const mesh::Mesh& mesh, const mesh::DualMetrics& metrics,
             const std::filesystem::path& run_dir) const;

  const std::vector<flow::WallShearStatistics>& statistics() const { return stats_; }
  // tau_w of the last sample per patch, in the order of each patch's wall loads.
  const std::vector<std::vector<Eigen::Vector3d>>& last_tau() const { return tau_; }
  const std::vector<std::vector<int>>& nodes() const { return nodes_; }
  // |A_j| of each wall node's dual face, in the same order (area-weighted means).
  const std::vector<std::vector<double>>& areas() const { return area_; }

 private:
  const mesh::LocalMesh* local_;
  WallShearOptions options_;
  double density_, mu_;
  const flow::VectorField* body_force_ = nullptr;
  std::vector<double> weights_;  // the viscous edge weights of the momentum operator
  flow::TensorField grad_;
  flow::ViscosityModel model_;           // newtonian: mu_
  flow::ScalarField mu_field_;           // non-Newtonian: mu(gamma_dot) per local node
  std::vector<std::vector<int>> nodes_;  // local wall node per load, per patch
  std::vector<std::vector<double>> area_;
  std::vector<std::vector<Eigen::Vector3d>> tau_;
  std::vector<flow::WallShearStatistics> stats_;
  NodeMask support_nodes_;
  std::vector<char> in_support_;                   // support_nodes_ at the sample
  std::vector<std::vector<double>> support_time_;  // per patch and wall node, s in the window
  double last_time_ = 0;
  bool sampled_ = false;
  std::ofstream history_;
};

}  // namespace valsalva::analysis
