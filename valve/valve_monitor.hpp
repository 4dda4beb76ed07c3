// The indices of a valve during a flow run ([valve] of a scene, scene/scene_keys_valve.hpp), from
// the flow state and the immersed leaflets (one structure with node sets leaflet1..3):
//   valve.csv         every valve.every_steps and at each cycle end the run lands on: step,
//                     time, cycle, the flow through the inlet and outlet patches (m^3/s, into the
//                     domain at the inlet and out of it at the outlet: forward positive), the TPG
//                     (mmHg; mean pressure of the upstream region minus the downstream one), the
//                     geometric orifice area (m^2, structure/orifice_area.hpp) with its raster
//                     error and the opening ratio, the three leaflet tips (free-edge midpoints: x,
//                     y, z and distance from the axis), the largest von Mises stress over the
//                     Gauss points (Pa), its element and position, the smallest signed gap
//                     between contact surfaces (m) and the contact area (m^2)
//   valve_cycles.csv  one row per completed cycle (analysis/valve_cycles.hpp), with the valve's
//                     flow taken at the inlet
// The open cycle's samples are saved in checkpoints, so a restarted run completes it; a restart
// in place cuts valve_cycles.csv back to the cycles completed before that open cycle (valve.csv
// is cut by run::continue_in_place).
#pragma once

#include <filesystem>
#include <fstream>
#include <vector>

#include "analysis/pressure_drop.hpp"
#include "analysis/valve_cycles.hpp"
#include "analysis/valve_monitor_options.hpp"
#include "flow/projection_rk4.hpp"
#include "ibm/immersed_structure.hpp"
#include "io/checkpoint.hpp"
#include "mesh/local_mesh.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::valve {

class ValveMonitor {
 public:
  // Collective. `structure` must outlive the monitor. Throws std::runtime_error naming the
  // structure or set when the leaflets lack node sets leaflet1..3 / leaflet<i>_free_edge, or a
  // pressure region holds no node. `append`: continue the CSV files of an earlier run.
  ValveMonitor(const mesh::LocalMesh& local, const ibm::ImmersedStructure& structure, int body,
               analysis::ValveMonitorOptions options, const std::filesystem::path& run_dir,
               bool append);

  // Collective: the row due after step `step` (step 0 = the initial state).
  void sample(const flow::FlowState& state, std::int64_t step);
  std::vector<io::CheckpointArray> checkpoint_arrays() const;
  // Collective. Throws on every rank when valve_cycles.csv cannot be cut back.
  void restore(const io::CheckpointReader& reader);

 private:
  struct Leaflet {
    structure::SolidMesh mesh;  // its own nodes, for the orifice area
    std::vector<int> nodes;     // structure node of each of its nodes
    int tip = -1;               // structure node at the free-edge midpoint
  };
  void cut_cycles_csv();  // rank 0, restart in place

  const mesh::LocalMesh* local_;
  const ibm::ImmersedStructure* structure_;
  int body_ = 0;
  analysis::ValveMonitorOptions options_;
  std::vector<Leaflet> leaflets_;
  analysis::RegionMean upstream_, downstream_;
  int inlet_ = -1, outlet_ = -1;
  analysis::CycleTracker cycles_;
  std::ofstream csv_, cycles_csv_;
  std::filesystem::path cycles_path_;
  bool append_ = false;
};

}  // namespace valsalva::valve
