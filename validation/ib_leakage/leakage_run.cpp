// One leakage run through the scene; see leakage_run.hpp.
#include "validation/ib_leakage/leakage_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "analysis/pressure_drop.hpp"
#include "core/comm.hpp"
#include "ibm/dirac_transfer.hpp"
#include "ibm/immersed_structure.hpp"
#include "structure/solid_forces.hpp"
#include "validation/ib_leakage/leakage_membrane.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

constexpr double region_distance = 5e-3, region_radius = 1.5e-3;  // m, see the header

// Pressure on the node row nearest y = H/2 (z = 0), indexed by round(x / h), all ranks.
void centre_line_pressure(const LeakageSetup& s, const mesh::LocalMesh& local,
                          const flow::ScalarField& p, LeakageResult& r) {
  const int n = static_cast<int>(std::lround(s.length() / s.h)) + 1;
  std::vector<double> sum(static_cast<std::size_t>(n), 0.0);
  for (int j = 0; j < local.num_owned; ++j) {
    const auto& x = local.position[j];
    if (std::abs(x.y() - s.height / 2) > 0.51 * s.h || std::abs(x.z()) > s.h / 4) continue;
    sum[static_cast<std::size_t>(std::lround(x.x() / s.h))] = p[j];
  }
  local.comm.sum_in_place(sum);
  for (int i = 0; i < n; ++i) {
    r.profile_x.push_back(i * s.h);
    r.profile_p.push_back(sum[static_cast<std::size_t>(i)]);
  }
}

// The membrane's force on the fluid, split between interior nodes and wall nodes (whose
// velocity is imposed, so the force spread there never reaches the fluid): spreads the last
// marker forces again through a transfer of the same kernel, on a partition of the run's fluid
// mesh of its own (the run's is read-only to its observers). Returns {interior, wall} x sums.
class ForceSplit {
 public:
  ForceSplit(const LeakageSetup& s, const run::Simulation& sim, const ibm::TransferOptions& o)
      : s_(s),
        local_(
            mesh::distribute(sim.mesh(), sim.metrics(), sim.local().comm.get(),
                             {leakage_ghost_layers(s.kernel_width), mesh::PartitionMethod::metis})),
        transfer_(local_, o) {
    double v[2] = {0, 0};
    for (int j = 0; j < local_.num_owned; ++j) {
      const double y = local_.position[j].y();
      wall_.push_back(y < 1e-9 * s.height || y > (1 - 1e-9) * s.height);
      v[wall_.back() ? 1 : 0] += local_.volume[j];
    }
    const double interior = local_.comm.sum(v[0]);
    span_ = s.height * interior / (interior + local_.comm.sum(v[1]));
  }
  // Height of the interior nodes' dual volumes (H - h on the uniform mesh): the pressure
  // gradient over the wall nodes' half cells meets their imposed velocity, not the membrane.
  double interior_span() const { return span_; }
  std::array<double, 2> operator()(const ibm::ImmersedStructure& ib) {
    const double depth = s_.depth();
    wrapped_ = ib.positions();
    for (int a = 0; a < wrapped_.cols(); ++a)
      wrapped_(2, a) -= depth * std::floor(wrapped_(2, a) / depth);
    transfer_.locate({reinterpret_cast<const Eigen::Vector3d*>(wrapped_.data()),
                      static_cast<std::size_t>(wrapped_.cols())});
    force_ = ib.forces();
    density_.resize(static_cast<std::size_t>(local_.num_local()));
    transfer_.spread({reinterpret_cast<const Eigen::Vector3d*>(force_.data()),
                      static_cast<std::size_t>(force_.cols())},
                     density_);
    std::array<double, 2> sum{0, 0};
    for (int j = 0; j < local_.num_owned; ++j)
      sum[wall_[j] ? 1 : 0] += local_.volume[j] * density_[j].x();
    return {local_.comm.sum(sum[0]), local_.comm.sum(sum[1])};
  }

 private:
  const LeakageSetup& s_;
  mesh::LocalMesh local_;
  ibm::DiracTransfer transfer_;
  std::vector<char> wall_;
  double span_ = 0;
  Eigen::Matrix3Xd wrapped_, force_;
  flow::VectorField density_;
};

// Area between the polyline through `line` at x and the plane x = x_m (trapezoids in y).
double displaced_area(const std::vector<int>& line, const Eigen::Matrix3Xd& x, double x_m) {
  double a = 0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const auto p = x.col(line[i]), q = x.col(line[i + 1]);
    a += (p.x() + q.x() - 2 * x_m) / 2 * (q.y() - p.y());
  }
  return a;
}

// Window means of the samples with time in [t1, t2]; the leak by mass balance (header).
void window_means(const std::vector<LeakageSample>& h, double t1, double t2, LeakageResult& r,
                  double& leak) {
  double q = 0, jump = 0, tether = 0, interior = 0, wall = 0, deflection = 0, span = 0;
  const LeakageSample* first = nullptr;
  const LeakageSample* last = nullptr;
  for (std::size_t i = 1; i < h.size(); ++i) {
    if (h[i - 1].time < t1 - 1e-12 || h[i].time > t2 + 1e-12) continue;
    if (!first) first = &h[i - 1];
    last = &h[i];
    const double dt = h[i].time - h[i - 1].time, w = dt / 2;
    auto trap = [&](double LeakageSample::*m) { return w * (h[i - 1].*m + h[i].*m); };
    q += trap(&LeakageSample::flow_in);
    jump += trap(&LeakageSample::jump);
    tether += trap(&LeakageSample::tether);
    interior += trap(&LeakageSample::interior);
    wall += trap(&LeakageSample::wall);
    deflection += trap(&LeakageSample::deflection);
    span += dt;
  }
  if (!first || span <= 0) throw std::logic_error("ib_leakage: no samples in the window");
  leak = (q - (last->area - first->area)) / span;
  r.jump = jump / span, r.tether = tether / span, r.interior = interior / span;
  r.wall = wall / span, r.deflection = deflection / span;
}

// What the run's hooks measure: set up at the start (the simulation's mesh and membrane), a
// sample every t_end / 400 of simulated time and at the end.
class Sampler {
 public:
  Sampler(const LeakageSetup& s, LeakageResult& r) : s_(s), r_(r) {}

  void start(const run::Simulation& sim) {
    const auto& ib = *sim.immersed();
    const auto& membrane = ib.body(0).mesh();
    r_.nodes = sim.local().global_nodes;
    r_.markers = ib.num_markers();
    line_ = membrane_centre_line(membrane, s_.membrane_x(), s_.thickness);
    const double expected = membrane_deflection(
        membrane,
        membrane_static_shape(membrane, ib.body(0).solid_forces().material(), s_.pressure));
    const Eigen::Vector3d mid(0, s_.height / 2, s_.depth() / 2);
    const double x_up = s_.membrane_x() - s_.thickness / 2 - region_distance;
    const double x_down = s_.membrane_x() + s_.thickness / 2 + expected + region_distance;
    if (x_up - region_radius < 0 || x_down + region_radius > s_.length())
      throw std::invalid_argument(fmt::format(
          "ib_leakage: pressure regions at x = {:.4g} and {:.4g} m (radius {:.3g} m) do not fit "
          "in the channel [0, {:.4g}] m; lengthen `upstream` or `downstream`",
          x_up, x_down, region_radius, s_.length()));
    up_ = std::make_unique<analysis::RegionMean>(sim.local(), mid + Eigen::Vector3d(x_up, 0, 0),
                                                 region_radius, "upstream");
    down_ = std::make_unique<analysis::RegionMean>(sim.local(), mid + Eigen::Vector3d(x_down, 0, 0),
                                                   region_radius, "downstream");
    split_ = std::make_unique<ForceSplit>(s_, sim, ib.options().transfer);
    r_.interior_span = split_->interior_span();
    const auto& mesh = sim.mesh();
    inlet_ = static_cast<std::size_t>(mesh.patch_index("xmin"));
    outlet_ = static_cast<std::size_t>(mesh.patch_index("xmax"));
    last_time_ = sim.state().time;
    sample(sim);
  }

  void observe(const run::Simulation& sim) {
    const double t = sim.state().time, dt = t - last_time_;
    last_time_ = t;
    r_.dt_min = r_.steps == 0 ? dt : std::min(r_.dt_min, dt);
    r_.dt_max = std::max(r_.dt_max, dt);
    ++r_.steps;
    if (t >= next_ * (1 - 1e-12) || t >= s_.t_end * (1 - 1e-12)) sample(sim);
  }

  const std::vector<int>& line() const { return line_; }

 private:
  void sample(const run::Simulation& sim) {
    const auto& state = sim.state();
    const auto& ib = *sim.immersed();
    const auto& membrane = ib.body(0).mesh();
    const double depth = s_.depth();
    const auto flux = sim.loop().boundary()->patch_fluxes(state.velocity);
    const auto& x = ib.positions();
    const auto force = (*split_)(ib);
    r_.history.push_back({state.time, leakage_inlet_pressure(s_, state.time), -flux[inlet_] / depth,
                          flux[outlet_] / depth, displaced_area(line_, x, s_.membrane_x()),
                          membrane_deflection(membrane, x),
                          (*up_)(state.pressure) - (*down_)(state.pressure),
                          -ib.tether_force(0).x() / depth, -force[0] / depth, -force[1] / depth,
                          ib.velocities().colwise().norm().maxCoeff()});
    next_ = state.time + s_.t_end / 400;
  }

  const LeakageSetup& s_;
  LeakageResult& r_;
  std::vector<int> line_;
  std::unique_ptr<analysis::RegionMean> up_, down_;
  std::unique_ptr<ForceSplit> split_;
  std::size_t inlet_ = 0, outlet_ = 0;
  double next_ = 0, last_time_ = 0;
};

}  // namespace

LeakageResult run_leakage(const LeakageSetup& setup, const std::filesystem::path& run_dir,
                          MPI_Comm comm) {
  const double t0 = MPI_Wtime();
  const auto& s = setup;
  LeakageResult r;
  r.setup = s;
  r.leak_reference = s.height * std::sqrt(2 * s.pressure / s.density);
  Sampler sampler(s, r);
  SceneRun measure;
  measure.at_start = [&](const run::Simulation& sim) { sampler.start(sim); };
  measure.observer = [&](const run::Simulation& sim, std::int64_t) { sampler.observe(sim); };
  measure.at_end = [&](const run::Simulation& sim) {
    const auto& ib = *sim.immersed();
    const auto& membrane = ib.body(0).mesh();
    const double t2 = r.history.back().time, t1 = t2 - (s.t_end - s.ramp) / 2;
    const double tm = (t1 + t2) / 2;
    double first = 0, second = 0;
    LeakageResult halves;
    window_means(r.history, t1, tm, halves, first);
    window_means(r.history, tm, t2, halves, second);
    window_means(r.history, t1, t2, r, r.leak);
    // Volume that crossed the moving membrane while the load was ramped: int Q_in - [A].
    double inflow = 0;
    const LeakageSample* ramp_end = &r.history.front();
    for (std::size_t i = 1; i < r.history.size() && r.history[i].time <= s.ramp + 1e-12; ++i) {
      inflow += (r.history[i].time - r.history[i - 1].time) *
                (r.history[i].flow_in + r.history[i - 1].flow_in) / 2;
      ramp_end = &r.history[i];
    }
    r.ramp_leak = (inflow - ramp_end->area) / ramp_end->area;
    r.leak_change = std::abs(first - second) / r.leak_reference;
    centre_line_pressure(s, sim.local(), sim.state().pressure, r);
    const Eigen::Matrix3Xd statics =
        membrane_static_shape(membrane, ib.body(0).solid_forces().material(), r.jump);
    r.static_deflection = membrane_deflection(membrane, statics);
    const auto& line = sampler.line();
    for (const auto& [from, to] :
         {std::pair{&ib.positions(), &r.final_line}, std::pair{&statics, &r.static_line}}) {
      to->resize(3, static_cast<Eigen::Index>(line.size()));
      for (std::size_t i = 0; i < line.size(); ++i)
        to->col(static_cast<Eigen::Index>(i)) = from->col(line[i]);
    }
  };
  const auto result = run_scene_file(leakage_scene(), leakage_overrides(s), run_dir, comm, measure);
  r.dt = result.summary.time / static_cast<double>(result.summary.steps);
  double wall = MPI_Wtime() - t0;
  wall = core::Comm(comm).max(wall);
  r.wall_seconds = wall;
  return r;
}

}  // namespace valsalva::validation
