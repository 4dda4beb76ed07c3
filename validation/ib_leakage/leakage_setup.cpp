// The leakage channel's scene overrides; see leakage_setup.hpp.
#include "validation/ib_leakage/leakage_setup.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

int cells(double length, double h) {
  return static_cast<int>(std::lround(length / h));
}

constexpr double table_pressure = 13332.2;  // Pa: the load the ramp tables hold (100 mmHg)

}  // namespace

std::filesystem::path leakage_scene() {
  return case_scene("ib_leakage", "ib_leakage.toml");
}

std::vector<std::string> leakage_overrides(const LeakageSetup& s) {
  if (!(s.h > 0) || s.kernel_width * s.h >= s.depth() || !(s.thickness > 0))
    throw std::invalid_argument(fmt::format(
        "ib_leakage: h = {} m, kernel width {} h, thickness {} m: need h > 0, thickness > 0 and "
        "the kernel narrower than the slab depth {} cells",
        s.h, s.kernel_width, s.thickness, s.depth_cells));
  if (!(s.ramp > 0) || !(s.t_end > s.ramp))
    throw std::invalid_argument(fmt::format(
        "ib_leakage: ramp {} s and t_end {} s: need 0 < ramp < t_end", s.ramp, s.t_end));
  const auto table = fmt::format("ramp_{:g}ms.csv", s.ramp * 1e3);
  if (!std::filesystem::exists(case_scene("ib_leakage", table)) || s.pressure != table_pressure)
    throw std::invalid_argument(fmt::format(
        "ib_leakage: no table {} of a {} Pa ramp over {} s next to the scene (there are tables "
        "of 13332.2 Pa over 10 and 20 ms)",
        table, s.pressure, s.ramp));
  const int nx = cells(s.length(), s.h), ny = cells(s.height, s.h);
  return {
      fmt::format("mesh.box.length=[{:.17g}, {:.17g}, {:.17g}]", s.length(), s.height, s.depth()),
      fmt::format("mesh.box.cells=[{}, {}, {}]", nx, ny, s.depth_cells),
      fmt::format("flow.density={:.17g}", s.density),
      fmt::format("flow.viscosity={:.17g}", s.viscosity),
      fmt::format("immersed.kernel_width={:.17g}", s.kernel_width),
      fmt::format("structure.membrane.origin=[{:.17g}, 0.0, 0.0]",
                  s.membrane_x() - s.thickness / 2),
      fmt::format("structure.membrane.size=[{:.17g}, {:.17g}, {:.17g}]", s.thickness, s.height,
                  s.depth()),
      fmt::format("structure.membrane.elements=[1, {}, {}]", ny, s.depth_cells),
      fmt::format("structure.membrane.parameters={{ G = {:.17g}, K = {:.17g} }}", s.G, s.K),
      fmt::format("structure.membrane.tether_stiffness={:.17g}", s.G * s.h * s.tether_factor),
      fmt::format("boundary.xmin.pressure_file={}", table),
      fmt::format("time.end={:.17g}", s.t_end)};
}

int leakage_ghost_layers(double width) {
  return 3 * static_cast<int>(std::floor(width / 2 + 0.5)) + 1;
}

double leakage_inlet_pressure(const LeakageSetup& setup, double t) {
  if (t >= setup.ramp) return setup.pressure;
  const double s = t / setup.ramp;
  return setup.pressure * s * s * s * (10 - 15 * s + 6 * s * s);
}

}  // namespace valsalva::validation
