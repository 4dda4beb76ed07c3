// One Turek–Hron FSI run through run::Simulation; see fsi_run.hpp.
#include "validation/turek_hron_fsi/fsi_run.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <optional>
#include <stdexcept>

#include "ibm/dirac_transfer.hpp"
#include "ibm/immersed_structure.hpp"
#include "validation/dfg_cylinder/cylinder_channel_flow.hpp"
#include "validation/scene_run.hpp"

namespace valsalva::validation {

namespace {

using Vec = Eigen::Vector3d;

// Benchmark geometry (turek_hron_parameters.csv header; turek_hron_fsi.toml).
constexpr double kHeight = 0.41, kCx = 0.2, kCy = 0.2, kRadius = 0.05;
constexpr double kBarEnd = 0.6, kBarHalf = 0.01;

std::string real(const std::string& key, double v) {
  return fmt::format("{}={:.17g}", key, v);
}

// Point A: the node of u1 at y = cy on the face z = 0.
int tip_node(const structure::SolidMesh& m) {
  for (int n : m.node_set("u1"))
    if (std::abs(m.X(1, n) - kCy) < 1e-12 && m.X(2, n) == 0) return n;
  throw std::logic_error("turek_hron_fsi: the bar mesh has no node at point A");
}

// The force density the bar spreads into the fluid at its last forces and current positions,
// indexed like the run's local mesh (a copy of it carries a transfer of the run's options: the
// run's own is read-only to observers). For the cylinder's wall-node balance.
class BarDensity {
 public:
  BarDensity(const run::Simulation& sim, double depth)
      : run_local_(sim.local()),
        local_(sim.local()),
        transfer_(local_, sim.immersed()->options().transfer),
        depth_(depth) {}

  const flow::VectorField& operator()(const ibm::ImmersedStructure& ib) {
    x_ = ib.positions();
    for (int a = 0; a < x_.cols(); ++a) x_(2, a) -= depth_ * std::floor(x_(2, a) / depth_);
    markers_.assign(x_.cols(), Vec::Zero());
    forces_.assign(x_.cols(), Vec::Zero());
    for (int a = 0; a < x_.cols(); ++a) {
      markers_[a] = x_.col(a);
      forces_[a] = ib.forces().col(a);
    }
    transfer_.locate(markers_);
    density_.assign(local_.num_local(), Vec::Zero());
    transfer_.spread(forces_, density_);
    density_.resize(run_local_.num_local());  // owned nodes first, in the run's order
    return density_;
  }

  // |sum_j V_j f_j - sum_a F_a| / |sum_a F_a| of the last density.
  double balance_error(const ibm::ImmersedStructure& ib) const {
    Vec spread = Vec::Zero();
    for (int i = 0; i < local_.num_owned; ++i) spread += local_.volume[i] * density_[i];
    for (int d = 0; d < 3; ++d) spread[d] = local_.comm.sum(spread[d]);
    return (spread - ib.total_force(0)).norm() / ib.total_force(0).norm();
  }

  ibm::DiracTransfer& transfer() { return transfer_; }
  const std::vector<Vec>& markers() const { return markers_; }

 private:
  const mesh::LocalMesh& run_local_;
  mesh::LocalMesh local_;
  ibm::DiracTransfer transfer_;
  double depth_;
  Eigen::Matrix3Xd x_;
  std::vector<Vec> markers_, forces_;
  flow::VectorField density_;
};

// Per call, seconds, max over ranks (FsiSpec::profile): locate, spread, interpolate, forces.
void profile(const run::Simulation& sim, BarDensity& d, FsiResult& r) {
  const auto& ib = *sim.immersed();
  const auto& local = sim.local();
  const std::vector<Vec> markers = d.markers();
  std::vector<Vec> values(markers.size()), forces(markers.size(), Vec::Zero());
  Eigen::Matrix3Xd f(3, ib.num_markers());
  flow::VectorField field = sim.state().velocity, out(field.size());
  field.resize(d.transfer().mesh().num_local(), Vec::Zero());
  out.resize(field.size());
  const int reps = 5;
  auto time = [&](auto&& work) {
    const double s0 = MPI_Wtime();
    for (int i = 0; i < reps; ++i) work();
    return local.comm.max((MPI_Wtime() - s0) / reps);
  };
  r.t_locate = time([&] { d.transfer().locate(markers); });
  r.t_spread = time([&] { d.transfer().spread(forces, out); });
  r.t_interp = time([&] { d.transfer().interpolate(field, values); });
  r.t_forces = time([&] { ib.body(0).forces(ib.positions(), f); });
}

}  // namespace

std::vector<std::string> fsi_overrides(const FsiSpec& spec) {
  const auto& p = spec.p;
  const auto& l = spec.level;
  const double depth = l.layers * l.size_near;
  // Q2 elements of about size_near along the bar (markers h/2 apart in the plane); in z, element
  // nodes about size_near apart are enough for a z-invariant state.
  const double x_clamp = kCx + std::sqrt(kRadius * kRadius - kBarHalf * kBarHalf);
  const int nx = std::max(1, static_cast<int>(std::lround((kBarEnd - x_clamp) / l.size_near)));
  const int ny = std::max(1, static_cast<int>(std::lround(2 * kBarHalf / l.size_near)));
  const int nz = std::max(2, l.layers / 2);
  std::vector<std::string> o = {
      real("mesh.cylinder_channel.size_near", l.size_near),
      real("mesh.cylinder_channel.size_far", l.size_far),
      fmt::format("mesh.cylinder_channel.layers={}", l.layers),
      real("mesh.cylinder_channel.thickness", depth),
      real("mesh.cylinder_channel.box_size", l.size_near),
      fmt::format("mesh.periodic.z.translation=[0.0, 0.0, {:.17g}]", depth),
      real("flow.density", p.rho_f), real("flow.viscosity", p.rho_f * p.nu_f),
      real("boundary.inlet.flow_rate", p.U_bar * kHeight * depth),
      real("boundary.inlet.ramp", std::max(0.0, spec.ramp)),
      // No ramp: from the developed channel profile everywhere (a shortcut to the steady state);
      // with the ramp from rest (the profile of mean velocity 0).
      real("initial.plane_poiseuille.mean_velocity", spec.ramp > 0 ? 0.0 : p.U_bar),
      real("initial.plane_poiseuille.width", kHeight),
      fmt::format("immersed.coupling={}", spec.per_step ? "per_step" : "per_stage"),
      fmt::format("immersed.kernel={}", spec.kernel),
      real("immersed.kernel_width", spec.kernel_width),
      real("immersed.dt_safety", spec.dt_fraction),
      fmt::format("structure.bar.size=[0.4, {:.17g}, {:.17g}]", 2 * kBarHalf, depth),
      fmt::format("structure.bar.elements=[{}, {}, {}]", nx, ny, nz),
      fmt::format("structure.bar.parameters={{ E = {:.17g}, nu = {:.17g} }}", p.E_s, p.nu_s),
      // Tether: a node spring of E times half the marker spacing, about the bar's own nodal
      // stiffness: the clamp is as stiff as the bar without lowering the coupling bound much.
      real("structure.bar.tether_stiffness", p.E_s * l.size_near / 2),
      real("structure.bar.initial_bend", spec.initial_bend), real("time.end", spec.t_end),
      fmt::format("time.max_steps={}", spec.max_steps)};
  return o;
}

FsiResult run_fsi(const Context& ctx, const FsiSpec& spec, const std::string& label) {
  const double t0 = MPI_Wtime();
  const auto& p = spec.p;
  const double rho = p.rho_f, nu = p.nu_f;
  if (!(p.E_s > 0) || !(p.U_bar > 0))
    throw std::invalid_argument("turek_hron_fsi: the case needs an elastic bar and an inflow");
  const double depth = spec.level.layers * spec.level.size_near;

  FsiResult r;
  r.slab = depth;
  int A = -1;
  std::optional<BarDensity> density;
  flow::TensorField grad;
  double next_sample = 0, next_steady = spec.steady_window, loop_start = 0, t_previous = 0;
  std::clock_t cpu_start = 0;
  FsiSample at_window{};
  auto sample = [&](const run::Simulation& sim) {
    const auto& ib = *sim.immersed();
    const auto& f = (*density)(ib);
    const Vec cyl =
        cylinder_force(sim.local(), sim.loop().solver(), sim.state(), rho, nu, grad, &f);
    const Vec on_bar = -ib.total_force(0);
    const Vec total = (cyl + on_bar) / depth;
    const Vec uA = ib.positions().col(A) - ib.body(0).mesh().X.col(A);
    r.samples.push_back({sim.state().time, uA.x(), uA.y(), total.x(), total.y(), on_bar.x() / depth,
                         on_bar.y() / depth});
  };

  SceneRun measure;
  measure.at_start = [&](const run::Simulation& sim) {
    if (!sim.immersed()) throw std::logic_error("turek_hron_fsi: the scene has no bar");
    A = tip_node(sim.immersed()->body(0).mesh());
    density.emplace(sim, depth);
    r.nodes = sim.local().global_nodes;
    r.markers = sim.immersed()->num_markers();
    r.ranks = sim.local().comm.size();
    loop_start = MPI_Wtime();
    cpu_start = std::clock();
  };
  measure.observer = [&](const run::Simulation& sim, std::int64_t) {
    const double t = sim.state().time;
    r.dt = std::max(r.dt, t - t_previous);
    t_previous = t;
    ++r.steps;
    if (t >= next_sample - 1e-12) {
      sample(sim);
      next_sample += spec.sample_interval;
      const auto& v = sim.immersed()->velocities();
      for (int a = 0; a < v.cols(); ++a) r.max_w = std::max(r.max_w, std::abs(v(2, a)));
    }
    if (spec.steady_window > 0 && t >= next_steady - 1e-12) {
      sample(sim);
      const auto& s = r.samples.back();
      r.steady_change =
          std::max(std::abs(s.drag / at_window.drag - 1), std::abs(s.uy / at_window.uy - 1));
      at_window = s;
      next_steady += spec.steady_window;
      if (sim.local().comm.rank() == 0)
        fmt::print("  t {:.3f}: drag {:.5f} lift {:.5f} uy_A {:.5e} (change {:.2e})\n", s.t, s.drag,
                   s.lift, s.uy, r.steady_change);
      if (r.steady_change < spec.steady_tolerance) sim.request_stop();
    }
  };
  measure.at_end = [&](const run::Simulation& sim) {
    r.loop_wall = MPI_Wtime() - loop_start;
    r.loop_cpu =
        sim.local().comm.max(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    sample(sim);
    r.balance_error = density->balance_error(*sim.immersed());
    if (spec.profile) profile(sim, *density, r);
  };
  run_scene_file(case_scene("turek_hron_fsi", "turek_hron_fsi.toml"), fsi_overrides(spec),
                 ctx.out_dir / "runs" / label, ctx.comm, measure);
  r.wall = MPI_Wtime() - t0;
  return r;
}

}  // namespace valsalva::validation
