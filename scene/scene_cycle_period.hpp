// The cycle of phase-averaged statistics (statistics.<name>.period) against the periodic waveform
// tables that drive the scene (boundary and forcing tables): it must span a whole number of the
// tables' periods, else the phases drift against the imposed flow. (valve.period is checked
// against the valve's inlet waveform by scene/scene_keys_valve.cpp.)
#pragma once

#include "scene/scene.hpp"

namespace valsalva::scene {

// Throws SceneError at the period key, naming the table file, its period and the accepted values.
// Tables that are not one period (they cover the run instead) set no cycle and are not checked.
void check_cycle_periods(const Scene& scene);

}  // namespace valsalva::scene
