#include "run/immersed_run.hpp"

#include <fmt/format.h>

#include <limits>
#include <numeric>
#include <stdexcept>

#include "run/immersed_coupling.hpp"
#include "structure/stress_recovery.hpp"

namespace valsalva::run {

namespace fs = std::filesystem;

ImmersedRun::ImmersedRun(scene::ImmersedSetup setup, mesh::LocalMesh& local,
                         const fs::path& run_dir, bool in_place, std::int64_t start_step)
    : setup_(std::move(setup)), local_(local), root_(local.comm.rank() == 0) {
  auto coupling = build_immersed_coupling(setup_, local_);
  ib_ = std::move(coupling.structure);
  dt_bound_ = coupling.dt_bound;
  if (root_) {
    for (const auto& s : setup_.structures) {
      const std::string base =
          in_place ? fmt::format("{}_restart_{:09d}", s.name, start_step) : s.name;
      series_.emplace_back(run_dir / "structures", base, s.mesh);
    }
    const auto file = run_dir / "structures.csv";
    const bool append = in_place && fs::exists(file);
    csv_.open(file, append ? std::ios::app : std::ios::trunc);
    if (!csv_) throw std::runtime_error("cannot write " + file.string());
    if (!append)
      csv_ << "step,time,structure,load_x,load_y,load_z,force_x,force_y,force_z,tether_x,tether_y,"
              "tether_z,max_speed,max_displacement,min_det_F,dt_bound,contact_min_gap,contact_min_"
              "gap_node,"
              "contact_force,contact_area,contact_max_pressure\n";
  }
}

double ImmersedRun::max_dt(std::int64_t step) {
  // The schedule depends on the step number only, so a restart repeats it.
  if (step % setup_.stability_check_every == 0 && step != evaluated_at_) {
    dt_bound_ = setup_.dt_safety * ib_->stable_time_step();
    evaluated_at_ = step;
  }
  return dt_bound_;
}

scene::StepCoupling ImmersedRun::coupling() {
  scene::StepCoupling c;
  c.body_force = ib_->body_force();
  c.finish_step = [this](const flow::FlowState& s) { ib_->finish_step(s); };
  c.max_dt = [this](std::int64_t step) { return max_dt(step); };
  if (setup_.damping_in_support < 1 || setup_.damping_in_support_at_boundary < 1) {
    c.undamped_nodes = [this](std::vector<char>& nodes) { ib_->support_nodes(nodes); };
    c.kept_damping = setup_.damping_in_support;
    c.kept_damping_at_boundary = setup_.damping_in_support_at_boundary;
  }
  c.max_dt_source = fmt::format(
      "the explicit immersed-boundary coupling ({} x the bound 2 sqrt(2)/omega or 2/omega, "
      "omega^2 = lambda_max(Interp Spread K)/rho: stiffer solids or finer fluid meshes lower it; "
      "see immersed.dt_safety)",
      setup_.dt_safety);
  return c;
}

void ImmersedRun::write(double time, io::FieldSet& fields) {
  ib_->current_force_density(force_density_);  // collective
  fields.vectors.emplace_back("force_density", &force_density_);
  if (!root_) return;
  for (int b = 0; b < ib_->num_bodies(); ++b) {
    const auto& s = setup_.structures[b];
    const int first = ib_->first_marker(b), n = ib_->body(b).num_nodes();
    const Eigen::Matrix3Xd x = ib_->positions().middleCols(first, n);
    const Eigen::Matrix3Xd v = ib_->velocities().middleCols(first, n);
    const Eigen::Matrix3Xd f = ib_->forces().middleCols(first, n);
    std::optional<structure::NodalStress> stress;
    if (s.stresses) stress = structure::nodal_stress(ib_->body(b).solid_forces(), x);
    series_[b].write(time, x, stress ? &*stress : nullptr,
                     {{"marker_velocity", &v}, {"marker_force", &f}});
  }
}

void ImmersedRun::after_step(double time, std::int64_t step) {
  if (!root_ || step % setup_.log_every != 0) return;
  for (int b = 0; b < ib_->num_bodies(); ++b) {
    const int first = ib_->first_marker(b), n = ib_->body(b).num_nodes();
    const auto& mesh = ib_->body(b).mesh();
    const Eigen::Vector3d f = ib_->total_force(b), t = ib_->tether_force(b);
    // The fluid's load on the structure: with the solid massless, the internal forces at the
    // free nodes balance the fluid there, so the load is what the clamped nodes' internal forces
    // pass to the support, whether the tether or a no-slip wall under them holds it.
    Eigen::Vector3d load = -t;
    for (int a : ib_->body(b).clamped_nodes()) load += ib_->forces().col(first + a);
    const double speed = ib_->velocities().middleCols(first, n).colwise().norm().maxCoeff();
    const double disp =
        (ib_->positions().middleCols(first, n) - mesh.X).colwise().norm().maxCoeff();
    // Contact: smallest signed gap (inf: no surfaces within the search radius; nan: the body has
    // no contact) with the slave node nearest to it, normal force, closed area, peak pressure.
    std::string contact = "nan,-1,nan,nan,nan";
    if (ib_->body(b).has_contact()) {
      const auto c = ib_->body(b).contact_summary(ib_->positions().middleCols(first, n));
      int node = -1;
      for (const auto& s : c.surfaces)
        if (s.min_gap == c.min_gap) node = s.min_gap_node;
      contact = fmt::format("{:.6e},{},{:.6e},{:.6e},{:.6e}", c.min_gap, node, c.force, c.area,
                            c.max_pressure);
    }
    csv_ << fmt::format(
        "{},{:.12g},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6e},{:.6e}"
        ","
        "{:.9g},{:.6e},{}\n",
        step, time, ib_->body(b).spec().name, load.x(), load.y(), load.z(), f.x(), f.y(), f.z(),
        t.x(), t.y(), t.z(), speed, disp, ib_->last_min_det(), dt_bound_, contact);
  }
  csv_.flush();
}

std::vector<io::CheckpointArray> ImmersedRun::checkpoint_arrays() const {
  // Replicated markers: rank 0 contributes every row.
  io::CheckpointArray a{"marker_positions", ib_->num_markers(), 3, {}, {}};
  io::CheckpointArray bound{"immersed_dt_bound", 1, 2, {}, {}};  // bound, step it was evaluated at
  if (root_) {
    const auto& x = ib_->positions();
    for (int m = 0; m < x.cols(); ++m) {
      a.rows.push_back(m);
      for (int d = 0; d < 3; ++d) a.data.push_back(x(d, m));
    }
    bound.rows.push_back(0);
    bound.data = {dt_bound_, static_cast<double>(evaluated_at_)};
  }
  std::vector<io::CheckpointArray> arrays{a, bound};
  // Where the kernel supports were built (they are kept while markers stay near).
  const auto& at = ib_->located_at();
  if (static_cast<int>(at.size()) == ib_->num_coupled_markers()) {
    io::CheckpointArray l{"marker_located_at", ib_->num_coupled_markers(), 3, {}, {}};
    if (root_)
      for (std::size_t m = 0; m < at.size(); ++m) {
        l.rows.push_back(static_cast<std::int64_t>(m));
        for (int k = 0; k < 3; ++k) l.data.push_back(at[m][k]);
      }
    arrays.push_back(std::move(l));
  }
  if (ib_->options().mode != ibm::CouplingMode::implicit) return arrays;
  // The implicit coupling's state: the last marker displacement (its extrapolated force).
  io::CheckpointArray d{"marker_last_displacement", ib_->num_markers(), 3, {}, {}};
  if (root_) {
    const auto& dx = ib_->last_displacement();
    for (int m = 0; m < dx.cols(); ++m) {
      d.rows.push_back(m);
      for (int k = 0; k < 3; ++k) d.data.push_back(dx(k, m));
    }
  }
  arrays.push_back(std::move(d));
  return arrays;
}

void ImmersedRun::restore(const io::CheckpointReader& in) {
  if (!in.has("marker_positions"))
    throw std::runtime_error(
        "restart: the checkpoint has no marker positions (it was written by a run without "
        "immersed structures)");
  std::vector<std::int64_t> rows(ib_->num_markers());
  for (int m = 0; m < ib_->num_markers(); ++m) rows[m] = m;
  const auto data = in.read_array("marker_positions", rows);
  Eigen::Matrix3Xd x(3, ib_->num_markers());
  for (int m = 0; m < x.cols(); ++m)
    for (int d = 0; d < 3; ++d) x(d, m) = data[3 * m + d];
  ib_->set_positions(x);
  if (ib_->options().mode == ibm::CouplingMode::implicit) {
    if (!in.has("marker_last_displacement"))
      throw std::runtime_error(
          "restart: the checkpoint has no marker_last_displacement, the state of immersed.coupling "
          "= \"implicit\" (it was written with another coupling); restart with the coupling it "
          "was written with");
    const auto d = in.read_array("marker_last_displacement", rows);
    Eigen::Matrix3Xd dx(3, ib_->num_markers());
    for (int m = 0; m < dx.cols(); ++m)
      for (int k = 0; k < 3; ++k) dx(k, m) = d[3 * m + k];
    ib_->set_last_displacement(dx);
  }
  // A checkpoint without supports (written before the markers were ever located) locates them
  // afresh at the next stage, as the uninterrupted run would have.
  if (in.has("marker_located_at")) {
    std::vector<std::int64_t> coupled(static_cast<std::size_t>(ib_->num_coupled_markers()));
    std::iota(coupled.begin(), coupled.end(), 0);
    const auto l = in.read_array("marker_located_at", coupled);
    std::vector<Eigen::Vector3d> at(coupled.size());
    for (std::size_t m = 0; m < at.size(); ++m) at[m] = {l[3 * m], l[3 * m + 1], l[3 * m + 2]};
    ib_->restore_location(at);
  }
  const std::int64_t row = 0;
  const auto bound = in.read_array("immersed_dt_bound", std::span(&row, 1));
  dt_bound_ = bound[0];
  evaluated_at_ = static_cast<std::int64_t>(bound[1]);
}

}  // namespace valsalva::run
