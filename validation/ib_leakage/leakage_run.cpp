// One leakage run; see leakage_run.hpp.
#include "validation/ib_leakage/leakage_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flow/run_diagnostics.hpp"
#include "io/pressure_drop.hpp"

namespace valsalva::validation {

namespace {

constexpr double region_distance = 5e-3, region_radius = 1.5e-3;  // m, see the header

// Pressure on the node row nearest y = H/2 (z = 0), indexed by round(x / h), all ranks.
void centre_line_pressure(const LeakageChannel& c, const flow::ScalarField& p, LeakageResult& r) {
  const auto& s = c.setup;
  const int n = static_cast<int>(std::lround(s.length() / s.h)) + 1;
  std::vector<double> sum(static_cast<std::size_t>(n), 0.0);
  for (int j = 0; j < c.local.num_owned; ++j) {
    const auto& x = c.local.position[j];
    if (std::abs(x.y() - s.height / 2) > 0.51 * s.h || std::abs(x.z()) > s.h / 4) continue;
    sum[static_cast<std::size_t>(std::lround(x.x() / s.h))] = p[j];
  }
  MPI_Allreduce(MPI_IN_PLACE, sum.data(), n, MPI_DOUBLE, MPI_SUM, c.local.comm.get());
  for (int i = 0; i < n; ++i) {
    r.profile_x.push_back(i * s.h);
    r.profile_p.push_back(sum[static_cast<std::size_t>(i)]);
  }
}

// The membrane's force on the fluid, split between interior nodes and wall nodes (whose
// velocity is imposed, so the force spread there never reaches the fluid): spreads the last
// marker forces again through a transfer of the same kernel. Returns {interior, wall} x sums.
struct ForceSplit {
  explicit ForceSplit(LeakageChannel& c) : c_(c), transfer_(c.local, c.ib->options().transfer) {
    double v[2] = {0, 0};
    for (int j = 0; j < c.local.num_owned; ++j) {
      const double y = c.local.position[j].y();
      wall_.push_back(y < 1e-9 * c.setup.height || y > (1 - 1e-9) * c.setup.height);
      v[wall_.back() ? 1 : 0] += c.local.volume[j];
    }
    const double interior = c.local.comm.sum(v[0]);
    span_ = c.setup.height * interior / (interior + c.local.comm.sum(v[1]));
  }
  // Height of the interior nodes' dual volumes (H - h on the uniform mesh): the pressure
  // gradient over the wall nodes' half cells meets their imposed velocity, not the membrane.
  double interior_span() const { return span_; }
  std::array<double, 2> operator()() {
    const double depth = c_.setup.depth();
    wrapped_ = c_.ib->positions();
    for (int a = 0; a < wrapped_.cols(); ++a)
      wrapped_(2, a) -= depth * std::floor(wrapped_(2, a) / depth);
    transfer_.locate({reinterpret_cast<const Eigen::Vector3d*>(wrapped_.data()),
                      static_cast<std::size_t>(wrapped_.cols())});
    force_ = c_.ib->forces();
    density_.resize(static_cast<std::size_t>(c_.local.num_local()));
    transfer_.spread({reinterpret_cast<const Eigen::Vector3d*>(force_.data()),
                      static_cast<std::size_t>(force_.cols())},
                     density_);
    std::array<double, 2> sum{0, 0};
    for (int j = 0; j < c_.local.num_owned; ++j)
      sum[wall_[j] ? 1 : 0] += c_.local.volume[j] * density_[j].x();
    return {c_.local.comm.sum(sum[0]), c_.local.comm.sum(sum[1])};
  }

 private:
  LeakageChannel& c_;
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

}  // namespace

std::vector<int> membrane_centre_line(const LeakageSetup& s, const structure::SolidMesh& m) {
  std::vector<int> line;
  for (int a = 0; a < m.num_nodes(); ++a)
    if (std::abs(m.X(0, a) - s.membrane_x()) < 1e-6 * s.thickness && std::abs(m.X(2, a)) < 1e-9)
      line.push_back(a);
  std::sort(line.begin(), line.end(), [&](int a, int b) { return m.X(1, a) < m.X(1, b); });
  return line;
}

LeakageResult run_leakage(const LeakageSetup& setup, MPI_Comm comm) {
  const double t0 = MPI_Wtime();
  LeakageChannel c(setup, comm);
  const auto& s = c.setup;
  LeakageResult r;
  r.setup = s;
  r.nodes = c.local.global_nodes;
  r.markers = c.ib->num_markers();
  r.leak_reference = s.height * std::sqrt(2 * s.pressure / s.density);
  if (!(s.ramp > 0) || !(s.t_end > s.ramp))
    throw std::invalid_argument(fmt::format(
        "ib_leakage: ramp {} s and t_end {} s: need 0 < ramp < t_end", s.ramp, s.t_end));

  // Time step: a fraction of the coupling bound at the flat start, within RK4's viscous limit
  // (7-point Laplacian eigenvalue 12/h^2); the whole RK4 stability limit is checked on every
  // sample.
  const double nu = s.viscosity / s.density;
  r.dt_bound = c.ib->stable_time_step();
  r.dt = std::min(s.dt_fraction * r.dt_bound, 0.5 * flow::rk4_real_limit * s.h * s.h / (12 * nu));
  c.ib->check_time_step(r.dt);
  const int steps = static_cast<int>(std::ceil(s.t_end / r.dt - 1e-9));
  const int every = std::max(1, steps / 400);

  const double depth = s.depth();
  const auto line = membrane_centre_line(s, c.membrane);
  const double expected =
      membrane_deflection(c.membrane, membrane_static_shape(c.membrane, *c.material, s.pressure));
  const Eigen::Vector3d mid(0, s.height / 2, depth / 2);
  const double x_up = s.membrane_x() - s.thickness / 2 - region_distance;
  const double x_down = s.membrane_x() + s.thickness / 2 + expected + region_distance;
  if (x_up - region_radius < 0 || x_down + region_radius > s.length())
    throw std::invalid_argument(fmt::format(
        "ib_leakage: pressure regions at x = {:.4g} and {:.4g} m (radius {:.3g} m) do not fit "
        "in the channel [0, {:.4g}] m; lengthen `upstream` or `downstream`",
        x_up, x_down, region_radius, s.length()));
  const io::RegionMean up(c.local, mid + Eigen::Vector3d(x_up, 0, 0), region_radius, "upstream");
  const io::RegionMean down(c.local, mid + Eigen::Vector3d(x_down, 0, 0), region_radius,
                            "downstream");
  ForceSplit split(c);
  r.interior_span = split.interior_span();

  flow::FlowState state{flow::VectorField(c.local.num_local(), Eigen::Vector3d::Zero()),
                        flow::ScalarField(c.local.num_local(), 0.0), 0.0};
  const auto weights = flow::laplacian_weights(c.local);
  std::vector<double> scratch;
  auto sample = [&]() {
    const auto flux = c.bc->patch_fluxes(state.velocity);
    const auto& x = c.ib->positions();
    const auto force = split();
    r.history.push_back(
        {state.time, c.inlet_pressure(state.time),
         -flux[static_cast<std::size_t>(c.inlet_patch)] / depth,
         flux[static_cast<std::size_t>(c.outlet_patch)] / depth,
         displaced_area(line, x, s.membrane_x()), membrane_deflection(c.membrane, x),
         up(state.pressure) - down(state.pressure), -c.ib->tether_force(0).x() / depth,
         -force[0] / depth, -force[1] / depth, c.ib->velocities().colwise().norm().maxCoeff()});
    const auto rates = flow::stability_rates(c.local, weights, nu, state.velocity, scratch);
    if (r.dt * rates.stability > 1)
      throw std::runtime_error(fmt::format(
          "ib_leakage: dt {:.4g} s beyond the RK4 stability limit {:.4g} s at t = {:.4g} s", r.dt,
          1 / rates.stability, state.time));
  };
  sample();
  for (int n = 1; n <= steps; ++n) {
    const double p_in = c.inlet_pressure(state.time + r.dt);
    for (int j : c.inlet_nodes) state.pressure[j] = p_in;
    const auto report = c.flow->step(state, r.dt);
    c.ib->finish_step(state);
    // |div u| stays near round-off / h in a sane run; 1e6 1/s is a blow-up.
    if (!std::isfinite(report.max_divergence) || report.max_divergence > 1e6)
      throw std::runtime_error(fmt::format(
          "ib_leakage: the run blew up at step {} (t = {:.4g} s, max |div u| {:.3g} 1/s)", n,
          state.time, report.max_divergence));
    if (n % every == 0 || n == steps) sample();
  }
  r.steps = steps;

  const double t2 = r.history.back().time, t1 = t2 - (s.t_end - s.ramp) / 2, tm = (t1 + t2) / 2;
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
  centre_line_pressure(c, state.pressure, r);
  const auto statics = membrane_static_shape(c.membrane, *c.material, r.jump);
  r.static_deflection = membrane_deflection(c.membrane, statics);
  for (const auto& [from, to] :
       {std::pair{&c.ib->positions(), &r.final_line}, std::pair{&statics, &r.static_line}}) {
    to->resize(3, static_cast<Eigen::Index>(line.size()));
    for (std::size_t i = 0; i < line.size(); ++i)
      to->col(static_cast<Eigen::Index>(i)) = from->col(line[i]);
  }
  r.wall_seconds = c.local.comm.max(MPI_Wtime() - t0);
  return r;
}

}  // namespace valsalva::validation
