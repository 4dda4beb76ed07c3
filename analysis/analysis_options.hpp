// What a run measures while it runs, as read from the scene (scene/scene_keys_analysis.cpp) and
// carried out by analysis::RunAnalysis (analysis/run_analysis.hpp). Every list may be empty.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "analysis/line_statistics.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/probes.hpp"
#include "analysis/section_flux.hpp"

namespace valsalva::analysis {

struct ProbeOptions {
  std::vector<ProbePoint> points;
  int every_steps = 1;
};

// Points origin + s u (+ t v), s, t in [0, 1], points[0] (x points[1]) of them.
struct SampleOptions {
  std::string name;
  bool plane = false;
  Eigen::Vector3d origin{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};  // m
  std::array<int, 2> points{50, 1};
  double interval = 0;  // s; 0 = every step
  double start_time = 0;
};

struct StatisticsOptions {
  enum class Region { all, plane, box, line, section };
  PhaseStatisticsOptions phase;
  int every_steps = 1;
  double write_interval = 0;  // s; > 0: also write the files every this much time (from start)
  Region region = Region::all;
  Eigen::Vector3d a{0, 0, 0}, b{0, 0, 0};    // plane, section: point, normal; box: lo, hi
  Eigen::Vector3d lo{0, 0, 0}, hi{0, 0, 0};  // section: the window the cut cells overlap
  double half_thickness = 0;
  LineSpec line;  // line: points along a segment (analysis/line_statistics.hpp)
};

struct WallShearOptions {
  std::vector<std::string> patches;  // empty = off
  double start_time = 0;
  int every_steps = 1;
};

struct PressureDropOptions {
  std::string name;
  Eigen::Vector3d upstream{0, 0, 0}, downstream{0, 0, 0};  // region centres, m
  double radius = 0;                                       // m
  int every_steps = 1;
};

struct SectionsOptions {
  std::vector<SectionOptions> sections;
  int every_steps = 1;
};

struct AnalysisOptions {
  ProbeOptions probes;
  std::vector<SampleOptions> samples;
  std::vector<StatisticsOptions> statistics;
  WallShearOptions wall_shear;
  std::vector<PressureDropOptions> pressure_drops;
  SectionsOptions sections;
  bool empty() const {
    return probes.points.empty() && samples.empty() && statistics.empty() &&
           wall_shear.patches.empty() && pressure_drops.empty() && sections.sections.empty();
  }
};

}  // namespace valsalva::analysis
