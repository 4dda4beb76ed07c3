// Stability estimate, kinetic energy, vorticity and the state guard; see run_diagnostics.hpp.
#include "flow/run_diagnostics.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>

namespace valsalva::flow {

namespace {
// `scale * nu_at(j)`: the kinematic viscosity of local node j (a constant nu as scale = nu and
// nu_at = 1 keeps the Newtonian bound's rounding as it was). With `nodal_viscosity` the Fourier
// number of node j uses the viscosity its row sees, the |a_jk|-weighted mean of its edge
// viscosities (nu_j + nu_k) / 2, rather than nu_j: it then stands to the row's Gershgorin bound
// rv_j as a constant nu does, so a node of small viscosity beside nodes of large one (the edge
// of a jet's subgrid viscosity) cannot meet the Fourier target and break the stability limit.
template <class Viscosity>
StabilityRates rates(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                     Viscosity nu_at, double scale, const VectorField& u,
                     std::vector<double>& scratch, bool nodal_viscosity) {
  const int n = mesh.num_local();
  // Per-node sums of |u_jk . S_jk| / 2, a_jk nu_jk, |a_jk| nu_jk and |a_jk| over the edges (each
  // edge feeds both ends).
  scratch.assign(4 * static_cast<std::size_t>(n), 0.0);
  double* conv = scratch.data();
  double* visc = scratch.data() + n;
  double* visc_abs = scratch.data() + 2 * n;
  double* weight_abs = scratch.data() + 3 * n;
  for (int e = 0; e < mesh.num_owned_edges; ++e) {
    const auto [j, k] = mesh.edges[e];
    const double flux = 0.25 * std::abs((u[j] + u[k]).dot(mesh.edge_normal[e]));
    conv[j] += flux;
    conv[k] += flux;
    const double nu_jk = 0.5 * (nu_at(j) + nu_at(k));
    const double a = weights[e] * nu_jk, w = std::abs(weights[e]);
    visc[j] += a;
    visc[k] += a;
    visc_abs[j] += w * nu_jk;
    visc_abs[k] += w * nu_jk;
    weight_abs[j] += w;
    weight_abs[k] += w;
  }
  StabilityRates r;
  for (int j = 0; j < mesh.num_owned; ++j) {
    const double rc = conv[j] / mesh.volume[j], rv = 2 * scale * visc[j] / mesh.volume[j];
    r.stability = std::max(r.stability, rc / rk4_imaginary_limit + rv / rk4_real_limit);
    r.convective = std::max(r.convective, u[j].norm() / mesh.h[j]);
    const double nu_row =
        nodal_viscosity && weight_abs[j] > 0 ? visc_abs[j] / weight_abs[j] : nu_at(j);
    r.viscous = std::max(r.viscous, scale * nu_row / (mesh.h[j] * mesh.h[j]));
  }
  r.stability = mesh.comm.max(r.stability);
  r.convective = mesh.comm.max(r.convective);
  r.viscous = mesh.comm.max(r.viscous);
  return r;
}
}  // namespace

StabilityRates stability_rates(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                               double nu, const VectorField& u, std::vector<double>& scratch) {
  return rates(
      mesh, weights, [](int) { return 1.0; }, nu, u, scratch, false);
}

StabilityRates stability_rates(const mesh::LocalMesh& mesh, const std::vector<double>& weights,
                               const ScalarField& nu, const VectorField& u,
                               std::vector<double>& scratch) {
  return rates(
      mesh, weights, [&nu](int j) { return nu[j]; }, 1.0, u, scratch, true);
}

double kinetic_energy(const mesh::LocalMesh& mesh, double rho, const VectorField& u) {
  double e = 0;
  for (int j = 0; j < mesh.num_owned; ++j) e += mesh.volume[j] * u[j].squaredNorm();
  return 0.5 * rho * mesh.comm.sum(e);
}

void vorticity(const TensorField& grad, VectorField& omega) {
  omega.resize(grad.size());
  for (std::size_t j = 0; j < grad.size(); ++j) {
    const auto& g = grad[j];
    omega[j] = {g(2, 1) - g(1, 2), g(0, 2) - g(2, 0), g(1, 0) - g(0, 1)};
  }
}

void q_criterion(const TensorField& grad, ScalarField& q) {
  q.resize(grad.size());
  for (std::size_t j = 0; j < grad.size(); ++j) {
    const Eigen::Matrix3d s = 0.5 * (grad[j] + grad[j].transpose());
    const Eigen::Matrix3d w = 0.5 * (grad[j] - grad[j].transpose());
    q[j] = 0.5 * (w.squaredNorm() - s.squaredNorm());
  }
}

std::string find_bad_state(const mesh::LocalMesh& mesh, const VectorField& u, const ScalarField& p,
                           double velocity_limit) {
  // The first bad owned node of this rank, then the one with the lowest dual-node number.
  int bad = -1;
  for (int j = 0; j < mesh.num_owned && bad < 0; ++j)
    if (!u[j].allFinite() || !std::isfinite(p[j]) || u[j].norm() > velocity_limit) bad = j;
  const auto none = std::numeric_limits<std::int64_t>::max();
  // dual_node numbers are the same for every partition, so is the reported node.
  const std::int64_t mine = bad < 0 ? none : static_cast<std::int64_t>(mesh.dual_node[bad]);
  const std::int64_t first = -mesh.comm.max(-mine);
  if (first == none) return {};
  // The owner fills [kind, value, x, y, z]; a sum over ranks hands it to everyone.
  std::array<double, 5> info{};
  if (mine == first) {
    const int j = bad;
    if (!u[j].allFinite())
      info = {0, u[j].norm(), 0, 0, 0};
    else if (!std::isfinite(p[j]))
      info = {1, p[j], 0, 0, 0};
    else
      info = {2, u[j].norm(), 0, 0, 0};
    for (int d = 0; d < 3; ++d) info[2 + d] = mesh.position[j][d];
  }
  for (auto& x : info) x = mesh.comm.sum(x);
  const int kind = static_cast<int>(std::lround(info[0]));
  const char* what = kind == 0   ? "velocity is not finite"
                     : kind == 1 ? "pressure is not finite"
                                 : "velocity magnitude exceeds flow.velocity_limit";
  std::string value = kind == 2
                          ? fmt::format("|u| = {:.6g} m/s > {:.6g} m/s", info[1], velocity_limit)
                          : fmt::format("value {}", info[1]);
  return fmt::format("{} ({}) at node {} (x, y, z) = ({:.6g}, {:.6g}, {:.6g}) m", what, value,
                     first, info[2], info[3], info[4]);
}

}  // namespace valsalva::flow
