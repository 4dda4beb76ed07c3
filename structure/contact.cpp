#include "structure/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>

#include "core/bucket_grid.hpp"
#include "structure/contact_face_box.hpp"
#include "structure/contact_kernel.hpp"
#include "structure/loads.hpp"

namespace valsalva::structure {

using namespace contact_detail;

std::vector<FaceRef> contact_surface(const SolidMesh& mesh, const std::vector<std::string>& sets) {
  std::vector<FaceRef> faces;
  for (const std::string& name : sets) {
    const auto& s = mesh.surface_set(name);
    faces.insert(faces.end(), s.begin(), s.end());
  }
  return faces;
}

std::vector<ContactPair> pairs_between(const SolidMesh& mesh,
                                       const std::vector<std::vector<std::string>>& bodies) {
  std::vector<ContactPair> pairs;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      if (bodies[i].empty() || bodies[j].empty())
        throw std::invalid_argument("pairs_between: a body has no surface sets");
      pairs.push_back({bodies[i][0] + "-" + bodies[j][0], contact_surface(mesh, bodies[i]),
                       contact_surface(mesh, bodies[j])});
    }
  return pairs;
}

double small_strain_modulus(const Material& material) {
  Mat3 P;
  Mat9 A;
  material.pk1_tangent(Mat3::Identity(), P, A);
  return 3 * A(vidx(0, 1), vidx(0, 1));
}

namespace {

std::set<int> face_nodes(const SolidMesh& mesh, const std::vector<FaceRef>& faces,
                         const std::string& what) {
  std::set<int> nodes;
  for (const FaceRef& fr : faces) {
    if (fr.element < 0 || fr.element >= mesh.num_elements() || fr.face < 0 || fr.face > 5)
      throw std::invalid_argument(
          fmt::format("contact {}: face (element {}, face {}) is not in "
                      "the mesh of {} elements",
                      what, fr.element, fr.face, mesh.num_elements()));
    for (int a : hex_face_nodes(mesh.order, fr.face))
      nodes.insert(mesh.element_nodes(fr.element)[a]);
  }
  return nodes;
}

double mean_face_size(const SolidMesh& mesh, const std::vector<FaceRef>& a,
                      const std::vector<FaceRef>& b) {
  const double area = surface_area(mesh, a, mesh.X) + surface_area(mesh, b, mesh.X);
  return std::sqrt(area / static_cast<double>(a.size() + b.size()));
}

template <int NF>
std::array<V3<double>, NF> gather(const SolidMesh& mesh,
                                  const Eigen::Ref<const Eigen::Matrix3Xd>& x, const FaceRef& fr,
                                  const FaceShape<NF>& shape, std::array<int, NF>& nodes) {
  std::array<V3<double>, NF> P;
  const int* en = mesh.element_nodes(fr.element);
  for (int a = 0; a < NF; ++a) {
    nodes[a] = en[shape.local[a]];
    for (int i = 0; i < 3; ++i) P[a][i] = x(i, nodes[a]);
  }
  return P;
}

// The face shapes of the six local faces and their slave quadrature points.
template <int NF>
struct FaceTables {
  std::array<FaceShape<NF>, 6> shape;
  std::array<std::vector<SlavePoint<NF>>, 6> points;
  FaceTables(HexOrder order, int nq) {
    for (int k = 0; k < 6; ++k) {
      shape[k] = FaceShape<NF>(order, k);
      const HexFace hf = hex_face(k);
      const QuadratureRule q = gauss_face(k, nq);
      for (int g = 0; g < q.size(); ++g) {
        const double s = q.points[g][(hf.axis + 1) % 3], t = q.points[g][(hf.axis + 2) % 3];
        SlavePoint<NF> sp;
        sp.weight = q.weights[g];
        const FaceShape<NF>& f = shape[k];
        for (int a = 0; a < NF; ++a) {
          const double ls = lagrange(f.order, f.cs[a], s), lt = lagrange(f.order, f.ct[a], t);
          sp.N[a] = ls * lt;
          sp.Ns[a] = lagrange_d(f.order, f.cs[a], s) * lt;
          sp.Nt[a] = ls * lagrange_d(f.order, f.ct[a], t);
        }
        points[k].push_back(sp);
      }
    }
  }
};

struct HalfTotals {
  double force = 0, area = 0;
};

}  // namespace

Contact::Contact(const SolidMesh& mesh, const Material& material, std::vector<ContactPair> pairs,
                 std::vector<RigidObstacle> obstacles, const ContactOptions& options)
    : mesh_(mesh), pairs_(std::move(pairs)), obstacles_(std::move(obstacles)), options_(options) {
  if (!(options_.penalty_factor > 0))
    throw std::invalid_argument(
        fmt::format("contact: penalty_factor {} must be > 0", options_.penalty_factor));
  if (!(options_.search_factor > 0))
    throw std::invalid_argument(
        fmt::format("contact: search_factor {} must be > 0", options_.search_factor));
  if (!(options_.clearance >= 0))
    throw std::invalid_argument(
        fmt::format("contact: clearance {} m must be >= 0", options_.clearance));
  if (!(options_.smoothing >= 0 && options_.smoothing < 1))
    throw std::invalid_argument(
        fmt::format("contact: smoothing {} must be in [0, 1) (a fraction of the face size)",
                    options_.smoothing));
  if (options_.quadrature < 0 || options_.quadrature > 4)
    throw std::invalid_argument(
        fmt::format("contact: quadrature {} must be 0 (automatic) or 1..4 points per direction",
                    options_.quadrature));
  modulus_ = options_.modulus > 0 ? options_.modulus : small_strain_modulus(material);
  if (!(modulus_ > 0))
    throw std::invalid_argument(fmt::format(
        "contact: the material's small-strain modulus is {} (set ContactOptions::modulus)",
        modulus_));
  for (const ContactPair& p : pairs_) {
    if (p.a.empty() || p.b.empty())
      throw std::invalid_argument(fmt::format("contact pair '{}': a surface has no faces", p.name));
    const auto na = face_nodes(mesh, p.a, "pair '" + p.name + "'");
    const auto nb = face_nodes(mesh, p.b, "pair '" + p.name + "'");
    for (int n : na)
      if (nb.count(n))
        throw std::invalid_argument(fmt::format(
            "contact pair '{}': node {} lies on both surfaces; the surfaces must belong to "
            "different bodies (self-contact is not supported)",
            p.name, n));
    h_.push_back(mean_face_size(mesh, p.a, p.b));
  }
  for (const RigidObstacle& o : obstacles_) {
    if (o.faces.empty())
      throw std::invalid_argument(fmt::format("contact obstacle '{}': no faces", o.name));
    face_nodes(mesh, o.faces, "obstacle '" + o.name + "'");
    if (!(o.direction.norm() > 0))
      throw std::invalid_argument(fmt::format("contact obstacle '{}': zero direction", o.name));
    if (o.shape == RigidObstacle::Shape::cylinder && !(o.radius > 0))
      throw std::invalid_argument(
          fmt::format("contact obstacle '{}': cylinder radius {} must be > 0", o.name, o.radius));
    h_.push_back(mean_face_size(mesh, o.faces, {}));
  }
}

template <int NF>
ContactSummary Contact::evaluate(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                                 Eigen::Ref<Eigen::Matrix3Xd>* f,
                                 std::vector<Eigen::Triplet<double>>* K,
                                 std::vector<ContactPoint>* pts, ContactShare share) const {
  constexpr int ND = 6 * NF;
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, ND, 1>>;
  const int nq = options_.quadrature > 0 ? options_.quadrature : static_cast<int>(mesh_.order) + 2;
  const FaceTables<NF> tables(mesh_.order, nq);
  ContactSummary summary;
  const bool exhaustive = options_.exhaustive_search;
  long slave_face = -1;  // running index of the slave faces, for the share
  auto mine = [&] { return ++slave_face % share.parts == share.part; };

  // Adds a point force (value, and the tangent from its derivatives) to the slave nodes.
  const bool two_pass = options_.formulation == ContactOptions::Formulation::two_pass;
  // Adds w times a point force (value, and the tangent from its derivatives) to the nodes.
  auto scatter_one = [&](const V3<AD>& fa, int row_node, double w, const std::array<int, NF>& slave,
                         const std::array<int, NF>* master) {
    for (int i = 0; i < 3; ++i) {
      (*f)(i, row_node) += w * fa[i].value();
      const auto& d = fa[i].derivatives();
      for (int b = 0; b < (master ? 2 * NF : NF); ++b) {
        const int node = b < NF ? slave[b] : (*master)[b - NF];
        for (int k = 0; k < 3; ++k)
          K->emplace_back(3 * row_node + i, 3 * node + k, -w * d[3 * b + k]);
      }
    }
  };
  auto scatter_ad = [&](const PointForce<AD, NF>& pf, const std::array<int, NF>& slave,
                        const std::array<int, NF>* master) {
    const double w = master && two_pass ? 0.5 : 1.0;
    for (int a = 0; a < NF; ++a) scatter_one(pf.f[a], slave[a], w, slave, master);
    if (master && two_pass)
      for (int b = 0; b < NF; ++b) scatter_one(pf.fm[b], (*master)[b], w, slave, master);
  };
  auto seed = [](const std::array<V3<double>, NF>& P, int offset) {
    std::array<V3<AD>, NF> Q;
    for (int a = 0; a < NF; ++a)
      for (int i = 0; i < 3; ++i) Q[a][i] = AD(P[a][i], ND, offset + 3 * a + i);
    return Q;
  };
  auto record = [&](ContactSurfaceSummary& s, HalfTotals& half, int surface, int h,
                    const FaceRef& fr, const std::array<int, NF>& nodes, const V3<double>& xs,
                    const FaceRef& master, double gap, double pressure, double area) {
    if (gap < s.min_gap) {
      s.min_gap = gap;
      s.min_gap_face = fr;
      s.min_gap_master = master;
      double best = INFINITY;
      for (int a = 0; a < NF; ++a) {
        const Vec3 d = x.col(nodes[a]) - Vec3(xs[0], xs[1], xs[2]);
        if (d.norm() < best) best = d.norm(), s.min_gap_node = nodes[a];
      }
    }
    if (pressure > 0) {
      half.force += pressure * area;
      half.area += area;
      s.max_pressure = std::max(s.max_pressure, pressure);
      ++s.active_points;
    }
    if (pts) pts->push_back({surface, h, fr, Vec3(xs[0], xs[1], xs[2]), gap, pressure, area});
  };

  // Half pass: the slave faces S against the master faces M.
  auto half_pass = [&](const std::vector<FaceRef>& S, const std::vector<FaceRef>& M, double eps,
                       double width, double search, double clearance, ContactSurfaceSummary& s,
                       HalfTotals& half, int surface, int h) {
    // Each master face's box (contact_face_box.hpp) bounds its distance to a point from below.
    std::vector<FaceBox> boxes(M.size());
    std::vector<Eigen::Vector3d> centres(M.size());
    std::vector<std::array<V3<double>, NF>> PM(M.size());
    std::vector<std::array<int, NF>> NM(M.size());
    double rmax = 0;
    for (std::size_t m = 0; m < M.size(); ++m) {
      const FaceShape<NF>& fm = tables.shape[M[m].face];
      PM[m] = gather<NF>(mesh_, x, M[m], fm, NM[m]);
      boxes[m] = face_box<NF>(fm, PM[m]);
      centres[m] = Eigen::Vector3d(boxes[m].centre[0], boxes[m].centre[1], boxes[m].centre[2]);
      rmax = std::max(rmax, boxes[m].radius);
    }
    // A converged projection's |gap| is the point's distance to the face up to the Newton
    // tolerance, and its foot may lie 1e-9 outside the face's parameter square: the margin
    // keeps the skip exact.
    const double margin = 1e-6 * rmax, accepted = clearance + search + margin;
    const core::BucketGrid grid(centres, std::max(2 * rmax, 1e-300));
    std::vector<int> candidates;
    std::vector<std::pair<double, int>> ranked;  // (box distance, position in candidates)
    for (const FaceRef& fr : S) {
      if (!mine()) continue;
      const FaceShape<NF>& fs = tables.shape[fr.face];
      std::array<int, NF> ns;
      const auto PS = gather<NF>(mesh_, x, fr, fs, ns);
      for (const SlavePoint<NF>& sp : tables.points[fr.face]) {
        V3<double> xs;
        double da;
        slave_geometry<double, NF>(fs, sp, PS, xs, da);
        if (exhaustive) {
          candidates.resize(M.size());
          std::iota(candidates.begin(), candidates.end(), 0);
        } else {
          grid.in_box(Eigen::Vector3d(xs[0], xs[1], xs[2]), rmax + accepted, candidates);
        }
        ++summary.slave_points;
        // Broad phase: no closest-point projection (a Newton solve) for a face farther from the
        // point than any gap the contact accepts, nor, once a face is found, for one farther
        // than its gap. The nearest boxes go first; ties keep the candidates' order, so the
        // face chosen is the one the plain loop over the candidates chooses.
        ranked.clear();
        for (std::size_t k = 0; k < candidates.size(); ++k) {
          const double d = exhaustive ? 0.0 : boxes[candidates[k]].distance(xs);
          if (d <= accepted) ranked.push_back({d, static_cast<int>(k)});
        }
        if (!exhaustive) std::sort(ranked.begin(), ranked.end());
        int best = -1, best_rank = 0;
        Projection pr;
        for (const auto& [d, k] : ranked) {
          if (best >= 0 && d > std::abs(pr.gap) + margin) break;
          const int c = candidates[k];
          const Projection p = project<NF>(tables.shape[M[c].face], PM[c], xs, !exhaustive);
          ++summary.projections;
          summary.newton_iterations += p.iterations;
          if (!p.inside || p.gap > clearance + search || p.gap < -search) continue;
          const double g = std::abs(p.gap), g_best = std::abs(pr.gap);
          if (best < 0 || g < g_best || (g == g_best && k < best_rank))
            best = c, best_rank = k, pr = p;
        }
        if (best < 0) continue;
        const FaceShape<NF>& fm = tables.shape[M[best].face];
        double pressure = 0;
        if (pr.gap < clearance && f) {
          if (K) {
            const auto pf = face_point_force<AD, NF>(
                fs, sp, seed(PS, 0), fm, seed(PM[best], 3 * NF), pr, eps, width, clearance);
            scatter_ad(pf, ns, &NM[best]);
            pressure = pf.pressure.value();
          } else {
            const auto pf =
                face_point_force<double, NF>(fs, sp, PS, fm, PM[best], pr, eps, width, clearance);
            const double w = two_pass ? 0.5 : 1.0;
            for (int a = 0; a < NF; ++a)
              for (int i = 0; i < 3; ++i) {
                (*f)(i, ns[a]) += w * pf.f[a][i];
                if (two_pass) (*f)(i, NM[best][a]) += w * pf.fm[a][i];
              }
            pressure = pf.pressure;
          }
        } else if (pr.gap < clearance) {
          pressure = penalty_pressure(pr.gap - clearance, eps, width);
        }
        record(s, half, surface, h, fr, ns, xs, M[best], pr.gap, pressure, da);
      }
    }
  };

  const double E = modulus_;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    ContactSurfaceSummary s;
    s.name = pairs_[p].name;
    s.h = h_[p];
    s.penalty = options_.penalty_factor * E / s.h;
    const double search = options_.search_factor * s.h;
    const double width = options_.smoothing * s.h;
    HalfTotals h0, h1;
    const double c = options_.clearance;
    half_pass(pairs_[p].a, pairs_[p].b, s.penalty, width, search, c, s, h0, static_cast<int>(p), 0);
    half_pass(pairs_[p].b, pairs_[p].a, s.penalty, width, search, c, s, h1, static_cast<int>(p), 1);
    s.force = 0.5 * (h0.force + h1.force);
    s.area = 0.5 * (h0.area + h1.area);
    summary.surfaces.push_back(s);
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const RigidObstacle& ob = obstacles_[o];
    const int index = static_cast<int>(pairs_.size() + o);
    ContactSurfaceSummary s;
    s.name = ob.name;
    s.h = h_[index];
    s.penalty = options_.penalty_factor * E / s.h;
    const double search = options_.search_factor * s.h;
    ObstacleShape shape;
    shape.cylinder = ob.shape == RigidObstacle::Shape::cylinder;
    shape.inside = ob.inside;
    shape.radius = ob.radius;
    const Vec3 d = ob.direction.normalized();
    for (int i = 0; i < 3; ++i) shape.p[i] = ob.point[i], shape.d[i] = d[i];
    HalfTotals half;
    for (const FaceRef& fr : ob.faces) {
      if (!mine()) continue;
      const FaceShape<NF>& fs = tables.shape[fr.face];
      std::array<int, NF> ns;
      const auto PS = gather<NF>(mesh_, x, fr, fs, ns);
      for (const SlavePoint<NF>& sp : tables.points[fr.face]) {
        V3<double> xs, n;
        double da;
        slave_geometry<double, NF>(fs, sp, PS, xs, da);
        const double gap = obstacle_gap(shape, xs, n);
        if (std::abs(gap) > search && gap > 0) continue;
        const double width = options_.smoothing * s.h;
        double pressure = penalty_pressure(gap, s.penalty, width);
        if (gap < 0 && f) {
          if (K) {
            const auto pf =
                obstacle_point_force<AD, NF>(fs, sp, seed(PS, 0), shape, s.penalty, width);
            scatter_ad(pf, ns, nullptr);
          } else {
            const auto pf = obstacle_point_force<double, NF>(fs, sp, PS, shape, s.penalty, width);
            for (int a = 0; a < NF; ++a)
              for (int i = 0; i < 3; ++i) (*f)(i, ns[a]) += pf.f[a][i];
          }
        }
        record(s, half, index, 0, fr, ns, xs, FaceRef{-1, -1}, gap, pressure, da);
      }
    }
    s.force = half.force;
    s.area = half.area;
    summary.surfaces.push_back(s);
  }
  for (const ContactSurfaceSummary& s : summary.surfaces) {
    summary.min_gap = std::min(summary.min_gap, s.min_gap);
    summary.force += s.force;
    summary.area += s.area;
    summary.max_pressure = std::max(summary.max_pressure, s.max_pressure);
  }
  return summary;
}

ContactSummary Contact::add_forces(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                                   Eigen::Ref<Eigen::Matrix3Xd> f,
                                   std::vector<Eigen::Triplet<double>>* K,
                                   ContactShare share) const {
  if (share.parts < 1 || share.part < 0 || share.part >= share.parts)
    throw std::invalid_argument(fmt::format(
        "structure::Contact: share {} of {} (needs 0 <= part < parts)", share.part, share.parts));
  return mesh_.order == HexOrder::q1 ? evaluate<4>(x, &f, K, nullptr, share)
                                     : evaluate<9>(x, &f, K, nullptr, share);
}

ContactSummary Contact::summary(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const {
  return mesh_.order == HexOrder::q1 ? evaluate<4>(x, nullptr, nullptr, nullptr)
                                     : evaluate<9>(x, nullptr, nullptr, nullptr);
}

std::vector<ContactPoint> Contact::points(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const {
  std::vector<ContactPoint> pts;
  if (mesh_.order == HexOrder::q1)
    evaluate<4>(x, nullptr, nullptr, &pts);
  else
    evaluate<9>(x, nullptr, nullptr, &pts);
  return pts;
}

Eigen::VectorXd Contact::obstacle_stiffness() const {
  Eigen::VectorXd k = Eigen::VectorXd::Zero(mesh_.num_nodes());
  const int nq = options_.quadrature > 0 ? options_.quadrature : static_cast<int>(mesh_.order) + 2;
  auto add = [&](const std::vector<FaceRef>& faces, double eps) {
    for (const FaceRef& fr : faces) {
      const QuadratureRule q = gauss_face(fr.face, nq);
      const int nen = mesh_.nodes_per_element();
      std::vector<double> N(nen), dN(3 * nen);
      const HexFace hf = hex_face(fr.face);
      const int* en = mesh_.element_nodes(fr.element);
      for (int g = 0; g < q.size(); ++g) {
        hex_shape(mesh_.order, q.points[g], N, dN);
        Vec3 xs = Vec3::Zero(), xt = Vec3::Zero();
        for (int a = 0; a < nen; ++a) {
          xs += mesh_.X.col(en[a]) * dN[3 * a + (hf.axis + 1) % 3];
          xt += mesh_.X.col(en[a]) * dN[3 * a + (hf.axis + 2) % 3];
        }
        const double dA = xs.cross(xt).norm() * q.weights[g];
        for (int a = 0; a < nen; ++a) k[en[a]] += eps * std::abs(N[a]) * dA;
      }
    }
  };
  for (std::size_t o = 0; o < obstacles_.size(); ++o)
    add(obstacles_[o].faces, options_.penalty_factor * modulus_ / h_[pairs_.size() + o]);
  return k;
}

}  // namespace valsalva::structure
