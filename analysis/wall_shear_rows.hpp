// The per-wall-node results of [wall_shear] at the end of a run, gathered on rank 0 in one
// order (patch, then dual node) so that every file made from them is the same at any rank count,
// and wall_shear.csv written from them:
//   patch, node (dual id), x, y, z, area (|A_j| of the node's dual face on the patch, m2),
//   tawss (Pa), osi, rrt (1/Pa, nan where undefined), tau_x, tau_y, tau_z (last sample, Pa),
//   support_fraction (the share of the averaging window the node spent inside an immersed
//   structure's kernel support, where the spread force and the smeared pressure jump make tau_w
//   a property of the immersed boundary method rather than of the flow; 0 without structures)
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/comm.hpp"

namespace valsalva::analysis {

struct WallNodeRow {
  int patch = 0;  // index into the [wall_shear] patches
  std::int64_t node = 0;
  Eigen::Vector3d x{0, 0, 0};
  double area = 0, tawss = 0, osi = 0, rrt = 0;
  Eigen::Vector3d tau{0, 0, 0};
  double support = 0;  // support_fraction
};

// Collective: every rank's rows, on rank 0 only (empty elsewhere), sorted by patch and node.
std::vector<WallNodeRow> gather_wall_rows(const core::Comm& comm,
                                          const std::vector<WallNodeRow>& mine);

void write_wall_shear_csv(const std::filesystem::path& path,
                          const std::vector<std::string>& patches,
                          const std::vector<WallNodeRow>& rows);

}  // namespace valsalva::analysis
