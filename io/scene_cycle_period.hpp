// The cycle of a scene against the periodic waveform tables that drive it: the valve monitor's
// cycles (valve.period) and phase-averaged statistics (statistics.<name>.period) must span a
// whole number of the table's periods, else the cycles drift against the imposed flow.
#pragma once

#include "io/scene.hpp"

namespace valsalva::io {

// Throws SceneError at the period key, naming the table file, its period and the accepted values.
// Tables that are not one period (they cover the run instead) set no cycle and are not checked.
void check_cycle_periods(const Scene& scene);

}  // namespace valsalva::io
