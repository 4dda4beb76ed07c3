// Boundary conditions by patch; see boundary_conditions.hpp for the conditions, the priority at
// shared nodes, the mass correction and how they enter the projection step.
#include "flow/boundary_conditions.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "core/comm.hpp"
#include "flow/patch_fluxes.hpp"

namespace valsalva::flow {

namespace {

void allreduce(std::vector<double>& values, const core::Comm& comm, MPI_Op op = MPI_SUM) {
  if (values.empty()) return;
  VALSALVA_MPI(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()),
                             MPI_DOUBLE, op, comm.get()));
}

Eigen::Vector3d off_axis(const Eigen::Vector3d& x, const Eigen::Vector3d& centre,
                         const Eigen::Vector3d& axis) {
  const Eigen::Vector3d d = x - centre;
  return d - d.dot(axis) * axis;
}

// The lumped ventricle's parameters (code that builds specs directly bypasses the scene checks).
void check_elastance(const BoundarySpec& spec, const std::vector<BoundarySpec>& specs) {
  const auto& e = spec.elastance;
  auto bad = [&](const std::string& what) {
    return std::invalid_argument(fmt::format("elastance inlet '{}': {}", spec.patch, what));
  };
  if (!e.tabulated &&
      !(e.minimum >= 0 && e.maximum >= e.minimum && e.period > 0 && e.systole > 0 &&
        e.systole <= e.period && std::isfinite(e.maximum) && std::isfinite(e.period)))
    throw bad(
        fmt::format("needs 0 <= elastance_min <= elastance_max and 0 < systole <= period "
                    "(got {}, {}, {}, {})",
                    e.minimum, e.maximum, e.systole, e.period));
  if (e.tabulated && *std::min_element(e.table.q.begin(), e.table.q.end()) < 0)
    throw bad("the elastance table has a negative elastance");
  if (!(spec.rest_volume >= 0) || !(spec.volume >= 0))
    throw bad(fmt::format("volume = {} and rest_volume = {} must be >= 0", spec.volume,
                          spec.rest_volume));
  if (spec.venous_return.empty()) return;
  const auto it = std::find_if(specs.begin(), specs.end(), [&](const BoundarySpec& s) {
    return s.patch == spec.venous_return;
  });
  if (it == specs.end() || it->type != BoundaryType::rcr_outlet)
    throw bad(fmt::format("venous_return = '{}' is not an rcr_outlet patch", spec.venous_return));
}

}  // namespace

BoundaryConditions::BoundaryConditions(const mesh::LocalMesh& mesh, std::vector<BoundarySpec> specs,
                                       double nu)
    : mesh_(mesh), specs_(std::move(specs)), patches_(mesh.patch_names.size()) {
  const auto& names = mesh.patch_names;
  const std::string patch_list = fmt::format("{}", fmt::join(names, ", "));
  for (std::size_t s = 0; s < specs_.size(); ++s) {
    const auto it = std::find(names.begin(), names.end(), specs_[s].patch);
    if (it == names.end())
      throw std::invalid_argument(fmt::format(
          "boundary condition for patch '{}', which is not in the mesh (its patches: {})",
          specs_[s].patch, patch_list));
    const int p = static_cast<int>(it - names.begin());
    if (patches_[p].spec >= 0)
      throw std::invalid_argument(
          fmt::format("patch '{}' has two boundary conditions", specs_[s].patch));
    patches_[p].spec = static_cast<int>(s);
    spec_patch_.push_back(p);
  }

  // Geometry of every patch from the owned boundary entries: sums, then the radius.
  const int np = static_cast<int>(names.size());
  sums_.assign(8 * np, 0.0);
  for (const auto& b : mesh.boundary) {
    if (b.node >= mesh.num_owned) continue;
    double* s = &sums_[8 * b.patch];
    const double a = b.area.norm();
    for (int d = 0; d < 3; ++d) s[d] += b.area[d], s[4 + d] += a * mesh.position[b.node][d];
    s[3] += a;
    s[7] += 1;
  }
  allreduce(sums_, mesh.comm);
  std::vector<std::string> missing;
  for (int p = 0; p < np; ++p) {
    auto& P = patches_[p];
    const double* s = &sums_[8 * p];
    const bool has_faces = s[7] > 0;
    if (!has_faces && P.spec >= 0)
      throw std::invalid_argument(fmt::format(
          "boundary condition for patch '{}', which is periodic (it has no boundary faces): "
          "remove the condition",
          names[p]));
    if (has_faces && P.spec < 0) missing.push_back("'" + names[p] + "'");
    if (!has_faces) continue;
    P.area_vector = Eigen::Vector3d(s[0], s[1], s[2]);
    P.area = s[3];
    P.centroid = Eigen::Vector3d(s[4], s[5], s[6]) / s[3];
    P.inward = -P.area_vector.normalized();
  }
  if (!missing.empty())
    throw std::invalid_argument(fmt::format(
        "boundary patch{} {} of the mesh {} no boundary condition (give each non-periodic patch "
        "one of: {})",
        missing.size() > 1 ? "es" : "", fmt::join(missing, ", "),
        missing.size() > 1 ? "have" : "has", boundary_type_names));
  std::vector<double> radius(np, 0.0);
  for (const auto& b : mesh.boundary)
    if (b.node < mesh.num_owned)
      radius[b.patch] = std::max(
          radius[b.patch],
          off_axis(mesh.position[b.node], patches_[b.patch].centroid, patches_[b.patch].inward)
              .norm());
  allreduce(radius, mesh.comm, MPI_MAX);

  for (int p = 0; p < np; ++p) {
    auto& P = patches_[p];
    P.radius = radius[p];
    if (P.spec < 0) continue;
    const auto& spec = specs_[P.spec];
    has_pressure_ |= pressure_type(spec.type);
    has_convective_ |= spec.type == BoundaryType::convective_outlet;
    if (spec.type == BoundaryType::elastance_inlet) check_elastance(spec, specs_);
    if (spec.type == BoundaryType::resistance_outlet || spec.type == BoundaryType::rcr_outlet) {
      const bool rcr = spec.type == BoundaryType::rcr_outlet;
      for (const auto& [name, value] :
           {std::pair{"resistance", spec.resistance},
            std::pair{"distal_resistance", rcr ? spec.distal_resistance : 1.0},
            std::pair{"capacitance", rcr ? spec.capacitance : 1.0}})
        if (!(value > 0) || !std::isfinite(value))
          throw std::invalid_argument(fmt::format(
              "outlet '{}': {} = {} must be a positive finite number", spec.patch, name, value));
    }
    if (spec.type != BoundaryType::inlet) continue;
    if (spec.profile == InletProfile::womersley) {
      if (spec.flow_rate.kind != Waveform::Kind::sine)
        throw std::invalid_argument(fmt::format(
            "inlet '{}': the Womersley profile is the exact solution for a sine flow rate; use "
            "waveform sine (or a flat or Poiseuille profile)",
            spec.patch));
      if (spec.flow_rate.ramp != 0)
        throw std::invalid_argument(fmt::format(
            "inlet '{}': the Womersley profile is the periodic state of a sine flow rate, not "
            "its start from rest; use ramp = 0 (or a flat or Poiseuille profile)",
            spec.patch));
      if (!(nu > 0))
        throw std::invalid_argument(fmt::format(
            "inlet '{}': the Womersley profile needs a positive viscosity", spec.patch));
      const auto& w = spec.flow_rate;
      P.womersley = Womersley::from_sine(P.radius, nu, w.mean, w.amplitude, w.period, w.phase);
    }
    if (spec.profile == InletProfile::plane_poiseuille) {
      if (!(spec.across.norm() > 0))
        throw std::invalid_argument(fmt::format(
            "inlet '{}': the plane_poiseuille profile needs `across`, the direction from one "
            "channel wall to the other",
            spec.patch));
      specs_[P.spec].across = spec.across.normalized();
      double lo = 1e300, hi = -1e300;
      for (const auto& b : mesh.boundary)
        if (b.patch == p && b.node < mesh.num_owned) {
          const double s = mesh.position[b.node].dot(specs_[P.spec].across);
          lo = std::min(lo, s), hi = std::max(hi, s);
        }
      P.across_min = mesh.comm.min(lo);
      P.across_max = mesh.comm.max(hi);
      if (!(P.across_max > P.across_min))
        throw std::invalid_argument(
            fmt::format("inlet '{}': the patch has no extent along `across` = ({}, {}, {})",
                        spec.patch, spec.across.x(), spec.across.y(), spec.across.z()));
    }
    if (spec.swap_with.empty()) continue;
    const auto it = std::find(names.begin(), names.end(), spec.swap_with);
    const int q = it == names.end() ? -1 : static_cast<int>(it - names.begin());
    if (q < 0 || patches_[q].spec < 0 ||
        specs_[patches_[q].spec].type != BoundaryType::convective_outlet)
      throw std::invalid_argument(fmt::format(
          "inlet '{}': swap_with = '{}' must name a convective_outlet patch of the mesh "
          "(patches: {})",
          spec.patch, spec.swap_with, patch_list));
    if (patches_[q].partner >= 0)
      throw std::invalid_argument(
          fmt::format("outlet '{}' is the swap partner of two inlets", spec.swap_with));
    P.partner = q;
    patches_[q].partner = p;
    has_convective_ = true;
  }

  // Boundary nodes in CSR form.
  std::vector<int> order(mesh.boundary.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return mesh.boundary[a].node < mesh.boundary[b].node; });
  entry_offsets_.push_back(0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int node = mesh.boundary[order[i]].node;
    if (nodes_.empty() || nodes_.back() != node) {
      if (!nodes_.empty()) entry_offsets_.push_back(static_cast<int>(i));
      nodes_.push_back(node);
    }
    entries_.push_back(order[i]);
  }
  entry_offsets_.push_back(static_cast<int>(order.size()));
  if (nodes_.empty()) entry_offsets_.assign(1, 0);
  role_.assign(nodes_.size(), Role::none);
  role_patch_.assign(nodes_.size(), -1);
  slip_.assign(nodes_.size(), 0);
  outlet_area_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  held_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  response_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  outlet_pressure_.assign(patches_.size(), 0.0);
  // The pressure outlet each Dirichlet node takes its value from: fixed before lumped, then the
  // lowest patch index (the same on every rank: ghosts carry their boundary entries).
  pressure_owner_.assign(mesh.num_local(), -1);
  auto precedence = [&](int patch) {
    return specs_[patches_[patch].spec].type == BoundaryType::pressure_outlet ? 2 : 1;
  };
  for (const auto& b : mesh.boundary) {
    const auto& P = patches_[b.patch];
    if (P.spec < 0 || !pressure_type(specs_[P.spec].type)) continue;
    int& owner = pressure_owner_[b.node];
    if (owner < 0 || precedence(b.patch) > precedence(owner) ||
        (precedence(b.patch) == precedence(owner) && b.patch < owner))
      owner = b.patch;
  }
  update_roles(0.0);
}

double BoundaryConditions::imposed_inflow(int patch, double t) const {
  const auto& P = patches_[patch];
  if (P.spec < 0) return 0;
  const auto& spec = specs_[P.spec];
  if (spec.type == BoundaryType::inlet) {
    const double q = spec.flow_rate(t);
    return (P.partner >= 0 && q < 0) ? 0.0 : q;
  }
  if (spec.type == BoundaryType::convective_outlet && P.partner >= 0) {
    const double q = specs_[patches_[P.partner].spec].flow_rate(t);
    return q < 0 ? -q : 0.0;
  }
  return 0;
}

void BoundaryConditions::update_roles(double t) {
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    auto& P = patches_[p];
    if (P.spec < 0) continue;
    switch (specs_[P.spec].type) {
      case BoundaryType::wall:
        P.role = Role::fixed;
        break;
      case BoundaryType::slip:
        P.role = Role::slip;
        break;
      case BoundaryType::pressure_outlet:
      case BoundaryType::resistance_outlet:
      case BoundaryType::rcr_outlet:
      case BoundaryType::pressure_inlet:
      case BoundaryType::elastance_inlet:
        P.role = Role::pressure;
        break;
      case BoundaryType::inlet:
        P.role =
            (P.partner >= 0 && specs_[P.spec].flow_rate(t) < 0) ? Role::convective : Role::inflow;
        break;
      case BoundaryType::convective_outlet:
        P.role = imposed_inflow(static_cast<int>(p), t) > 0 ? Role::inflow : Role::convective;
        break;
    }
  }
  // Strongest condition per node: stationary wall > moving wall > inflow > slip > outflow.
  auto rank = [&](int patch) {
    const auto& P = patches_[patch];
    switch (P.role) {
      case Role::fixed:
        return specs_[P.spec].wall_velocity.isZero(0) ? 6 : 5;
      case Role::inflow:
        return 4;
      case Role::slip:
        return 3;
      case Role::convective:
        return 2;
      case Role::pressure:
        return 1;
      case Role::none:
        return 0;
    }
    return 0;
  };
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    int best = -1, best_rank = 0;
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1]; ++i) {
      const auto& b = mesh_.boundary[entries_[i]];
      const int r = rank(b.patch);
      if (r > best_rank) best = b.patch, best_rank = r;
      if (r == 2 || r == 1) out += b.area;
    }
    role_patch_[k] = best;
    role_[k] = best < 0 ? Role::none : patches_[best].role;
    // Slip constrains the normal velocity only: a slip node that is also on an outlet takes its
    // value from the outlet condition (advected on a convective outlet), then the slip
    // projection; it is not mass-corrected.
    slip_[k] = role_[k] == Role::slip;
    if (role_[k] == Role::slip || role_[k] == Role::pressure)
      for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1]; ++i) {
        const int p = mesh_.boundary[entries_[i]].patch;
        if (patches_[p].role == Role::convective) role_[k] = Role::convective, role_patch_[k] = p;
      }
    outlet_area_[k] = out;
  }
}

double BoundaryConditions::profile(const Patch& P, int patch, const Eigen::Vector3d& x, double q,
                                   double t, double& shape) const {
  const auto& spec = specs_[P.spec];
  // A swapped partner imposes a flat profile.
  const InletProfile kind = spec.type == BoundaryType::inlet ? spec.profile : InletProfile::flat;
  (void)patch;
  if (kind == InletProfile::flat) {
    shape = 1;
    return q / P.area;
  }
  if (kind == InletProfile::plane_poiseuille) {
    const double s =
        std::clamp((x.dot(spec.across) - P.across_min) / (P.across_max - P.across_min), 0.0, 1.0);
    shape = 4 * s * (1 - s);
    return 1.5 * q / P.area * shape;  // mean of 4 s (1 - s) is 2/3
  }
  const double r = std::min(off_axis(x, P.centroid, P.inward).norm(), P.radius);
  const double s = r / P.radius;
  shape = 1 - s * s;
  if (kind == InletProfile::poiseuille)
    return 2 * q / (std::numbers::pi * P.radius * P.radius) * shape;
  return P.womersley.velocity(r, t);
}

std::vector<char> BoundaryConditions::pressure_dirichlet() const {
  std::vector<char> fixed(mesh_.num_local(), 0);
  for (int j = 0; j < mesh_.num_local(); ++j) fixed[j] = pressure_owner_[j] >= 0;
  return fixed;
}

void BoundaryConditions::velocity_dirichlet(std::vector<char>& held) const {
  held.assign(mesh_.num_local(), 0);
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    held[nodes_[k]] = role_[k] == Role::fixed || role_[k] == Role::inflow;
}

void BoundaryConditions::impose_pressure(ScalarField& p) const {
  for (const auto& b : mesh_.boundary) {
    const auto& P = patches_[b.patch];
    if (P.spec >= 0 && specs_[P.spec].type == BoundaryType::pressure_outlet)
      p[b.node] = specs_[P.spec].pressure;
  }
  for (int j = 0; j < mesh_.num_local(); ++j) {
    const int owner = pressure_owner_[j];
    if (owner >= 0 && lumped_type(specs_[patches_[owner].spec].type))
      p[j] = outlet_pressure_[owner];
  }
}

void BoundaryConditions::advect_outlets(const VectorField& w, const VectorField& un, double t,
                                        double dt_stage) {
  if (!has_convective_) return;
  update_roles(t);
  // Only the outlet nodes' gradients are read: their edges, not the whole mesh's (roles swap
  // with the flow direction, so the subset is every boundary node's).
  if (!outlet_gradient_) outlet_gradient_ = gradient_edges(mesh_, nodes_);
  gradient_at(mesh_, *outlet_gradient_, w, grad_);
  // Automatic convection speed: total imposed inflow over the total outflow area.
  double inflow = 0, outflow_area = 0;
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    if (patches_[p].role == Role::inflow) inflow += imposed_inflow(static_cast<int>(p), t);
    if (patches_[p].role == Role::convective || patches_[p].role == Role::pressure)
      outflow_area += patches_[p].area;
  }
  const double automatic = outflow_area > 0 ? std::max(inflow, 0.0) / outflow_area : 0.0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    if (role_[k] != Role::convective) continue;
    const int j = nodes_[k];
    const double given = specs_[patches_[role_patch_[k]].spec].convection_speed;
    const double speed = given > 0 ? given : automatic;
    const Eigen::Vector3d n = outlet_area_[k].normalized();
    held_[k] = un[j] - dt_stage * speed * (grad_[j] * n);
  }
}

void BoundaryConditions::hold_outlets(const VectorField& u) {
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    if (role_[k] == Role::convective) held_[k] = u[nodes_[k]];
}

void BoundaryConditions::impose(VectorField& u, double t) {
  update_roles(t);
  const int np = static_cast<int>(patches_.size());
  // Inflow: u = (w + delta s) n_in with delta such that the discrete flux is exactly Q.
  sums_.assign(2 * np + 2, 0.0);
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    if (role_[k] != Role::inflow || nodes_[k] >= mesh_.num_owned) continue;
    const int p = role_patch_[k];
    const auto& P = patches_[p];
    for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1]; ++i) {
      const auto& b = mesh_.boundary[entries_[i]];
      if (b.patch != p) continue;
      double shape = 0;
      const double w = profile(P, p, mesh_.position[b.node], imposed_inflow(p, t), t, shape);
      sums_[2 * p] += w * P.inward.dot(b.area);
      sums_[2 * p + 1] += shape * P.inward.dot(b.area);
    }
  }
  allreduce(sums_, mesh_.comm);
  for (int p = 0; p < np; ++p)
    if (patches_[p].role == Role::inflow && !(sums_[2 * p + 1] < 0))
      throw std::runtime_error(fmt::format(
          "boundary patch '{}': no inflow node is free of wall conditions, the flow rate "
          "cannot be imposed",
          mesh_.patch_names[p]));
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const int j = nodes_[k];
    const int p = role_patch_[k];
    switch (role_[k]) {
      case Role::fixed:
        u[j] = specs_[patches_[p].spec].wall_velocity;
        break;
      case Role::inflow: {
        const auto& P = patches_[p];
        double shape = 0;
        const double q = imposed_inflow(p, t);
        const double w = profile(P, p, mesh_.position[j], q, t, shape);
        const double delta =
            specs_[P.spec].unscaled_profile ? 0.0 : (-q - sums_[2 * p]) / sums_[2 * p + 1];
        u[j] = (w + delta * shape) * P.inward;
        break;
      }
      case Role::convective:
        u[j] = held_[k];
        break;
      case Role::slip:
      case Role::pressure:
      case Role::none:
        break;
    }
    if (slip_[k]) remove_slip_normals(k, u[j]);
  }
  // Mass correction on the free outflow nodes.
  double flux = 0, weight = 0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const int j = nodes_[k];
    if (j >= mesh_.num_owned) continue;
    for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1]; ++i)
      flux += u[j].dot(mesh_.boundary[entries_[i]].area);
    if (free_outflow(k)) weight += outlet_area_[k].squaredNorm();
  }
  sums_.assign({flux, weight});
  allreduce(sums_, mesh_.comm);
  if (!(sums_[1] > 0)) return;  // no outflow: closed or inflow-only domain
  const double c = -sums_[0] / sums_[1];
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    if (free_outflow(k)) u[nodes_[k]] += c * outlet_area_[k];
}

void BoundaryConditions::remove_slip_normals(std::size_t k, Eigen::Vector3d& u) const {
  // Remove the normal of every slip patch at the node (Gram-Schmidt).
  Eigen::Vector3d basis[3];
  int m = 0;
  for (int i = entry_offsets_[k]; i < entry_offsets_[k + 1] && m < 3; ++i) {
    const auto& b = mesh_.boundary[entries_[i]];
    if (patches_[b.patch].role != Role::slip) continue;
    Eigen::Vector3d n = b.area;
    for (int q = 0; q < m; ++q) n -= n.dot(basis[q]) * basis[q];
    if (n.norm() <= 1e-12 * b.area.norm()) continue;
    basis[m++] = n.normalized();
  }
  for (int q = 0; q < m; ++q) u -= u.dot(basis[q]) * basis[q];
}

void BoundaryConditions::stabilize_backflow(const VectorField& u, VectorField& rhs) const {
  if (!has_pressure_) return;
  for (const auto& b : mesh_.boundary) {
    const auto& P = patches_[b.patch];
    if (P.spec < 0 || !pressure_type(specs_[P.spec].type)) continue;
    const double flux = u[b.node].dot(b.area);
    if (flux < 0) rhs[b.node] += flux / mesh_.volume[b.node] * u[b.node];
  }
}

void BoundaryConditions::drop_outlet_viscous_flux(const TensorField& grad, double nu,
                                                  const ScalarField& nu_sgs,
                                                  VectorField& rhs) const {
  if (!has_pressure_) return;
  for (const auto& b : mesh_.boundary) {
    const auto& P = patches_[b.patch];
    if (P.spec < 0 || !pressure_type(specs_[P.spec].type)) continue;
    const auto& g = grad[b.node];
    const Eigen::Vector3d flux =
        nu_sgs.empty() ? Eigen::Vector3d(nu * (g * b.area))
                       : Eigen::Vector3d((nu + nu_sgs[b.node]) * ((g + g.transpose()) * b.area));
    rhs[b.node] -= flux / mesh_.volume[b.node];
  }
}

std::vector<double> BoundaryConditions::patch_fluxes(const VectorField& u) const {
  return flow::patch_fluxes(mesh_, u);
}

}  // namespace valsalva::flow
