#include "analysis/piv_compare.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace valsalva::analysis {

namespace {

std::ofstream open_out(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out)
    throw std::runtime_error(fmt::format("PIV comparison: cannot write '{}'", path.string()));
  return out;
}

std::string num(double x) {
  return fmt::format("{:.10g}", x);
}

}  // namespace

PivPlane::PivPlane(const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y)
    : origin(o), ex(x), ey(y) {
  if (std::abs(ex.norm() - 1) > 1e-9 || std::abs(ey.norm() - 1) > 1e-9 ||
      std::abs(ex.dot(ey)) > 1e-9)
    throw std::invalid_argument(fmt::format(
        "PIV plane: axes ex = ({}, {}, {}) and ey = ({}, {}, {}) must be orthogonal unit vectors",
        ex.x(), ex.y(), ex.z(), ey.x(), ey.y(), ey.z()));
}

PivSampler::PivSampler(const mesh::PointLocator& locator, const PivPlane& plane,
                       const PivFrame& frame)
    : locator_(&locator), plane_(plane) {
  for (std::size_t i = 0; i < frame.size(); ++i) {
    auto loc = locator.locate(plane.point(frame.x[i], frame.y[i]));
    if (!loc) ++outside_;
    locations_.push_back(loc ? *loc : mesh::PointLocation{});
  }
}

namespace {

Eigen::Vector4d sample_location(const mesh::PointLocation& loc, const PivPlane& plane,
                                const SimulationStatistics& s) {
  if (loc.cell < 0) return Eigen::Vector4d::Constant(NAN);
  auto field = [&](const std::vector<double>& a, int comps, int c) {
    return loc.interpolate([&](mesh::GlobalIndex n) { return a[std::size_t(n) * comps + c]; });
  };
  const Eigen::Vector3d u(field(s.mean_velocity, 3, 0), field(s.mean_velocity, 3, 1),
                          field(s.mean_velocity, 3, 2));
  Eigen::Vector4d out(u.dot(plane.ex), u.dot(plane.ey), NAN, NAN);
  if (!s.has_rms()) return out;
  // Reynolds stresses are interpolated (they are linear in the samples; RMS values are not).
  Eigen::Matrix3d r;
  auto sq = [&](int c) {
    return loc.interpolate([&](mesh::GlobalIndex n) {
      const double v = s.rms_velocity[std::size_t(n) * 3 + c];
      return v * v;
    });
  };
  r(0, 0) = sq(0), r(1, 1) = sq(1), r(2, 2) = sq(2);
  r(0, 1) = r(1, 0) = field(s.reynolds_uv, 1, 0);
  r(0, 2) = r(2, 0) = field(s.reynolds_uw, 1, 0);
  r(1, 2) = r(2, 1) = field(s.reynolds_vw, 1, 0);
  out[2] = std::sqrt(std::max(0.0, plane.ex.dot(r * plane.ex)));
  out[3] = std::sqrt(std::max(0.0, plane.ey.dot(r * plane.ey)));
  return out;
}

}  // namespace

Eigen::Vector4d PivSampler::sample(std::size_t i, const SimulationStatistics& s) const {
  return sample_location(locations_[i], plane_, s);
}

Eigen::Vector4d PivSampler::sample_at(double x, double y, const SimulationStatistics& s) const {
  auto loc = locator_->locate(plane_.point(x, y));
  return sample_location(loc ? *loc : mesh::PointLocation{}, plane_, s);
}

FieldMetrics field_metrics(const std::vector<double>& sim, const std::vector<double>& piv,
                           const std::vector<std::uint8_t>& use) {
  FieldMetrics m;
  double se = 0, pp = 0, ms = 0, mp = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (!use[i] || !std::isfinite(sim[i]) || !std::isfinite(piv[i])) continue;
    ++m.points;
    se += (sim[i] - piv[i]) * (sim[i] - piv[i]);
    pp += piv[i] * piv[i];
    ms += sim[i], mp += piv[i];
  }
  if (m.points == 0) return m;
  const double n = double(m.points);
  ms /= n, mp /= n;
  double cov = 0, vs = 0, vp = 0;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (!use[i] || !std::isfinite(sim[i]) || !std::isfinite(piv[i])) continue;
    cov += (sim[i] - ms) * (piv[i] - mp), vs += (sim[i] - ms) * (sim[i] - ms);
    vp += (piv[i] - mp) * (piv[i] - mp);
  }
  m.rmse = std::sqrt(se / n);
  m.normalised_error = m.rmse / std::sqrt(pp / n);
  m.correlation = cov / std::sqrt(vs * vp);
  return m;
}

FrameComparison compare_frame(const PivFrame& frame, const PivSampler& sampler,
                              const SimulationStatistics& sim) {
  FrameComparison c;
  c.label = frame.label;
  c.phase = frame.phase;
  c.outside = sampler.outside();
  const std::size_t n = frame.size();
  c.sim_u.resize(n), c.sim_v.resize(n), c.sim_urms.resize(n), c.sim_vrms.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = sampler.sample(i, sim);
    c.sim_u[i] = s[0], c.sim_v[i] = s[1], c.sim_urms[i] = s[2], c.sim_vrms[i] = s[3];
    c.masked += frame.valid[i] == 0;
  }
  c.u = field_metrics(c.sim_u, frame.u, frame.valid);
  c.v = field_metrics(c.sim_v, frame.v, frame.valid);
  if (sim.has_rms() && !frame.u_rms.empty()) {
    c.u_rms = field_metrics(c.sim_urms, frame.u_rms, frame.valid);
    c.v_rms = field_metrics(c.sim_vrms, frame.v_rms, frame.valid);
  }
  return c;
}

Profile sample_profile(const ProfileLine& line, const PivSampler& sampler, const PivFrame& frame,
                       const SimulationStatistics& sim, double max_distance) {
  if (line.points < 2)
    throw std::invalid_argument(
        fmt::format("profile '{}': points = {} < 2", line.name, line.points));
  Profile p;
  const double length = (line.b - line.a).norm();
  for (int k = 0; k < line.points; ++k) {
    const double t = double(k) / (line.points - 1);
    const Eigen::Vector2d q = line.a + t * (line.b - line.a);
    const auto s = sampler.sample_at(q.x(), q.y(), sim);
    double best = max_distance;
    std::size_t nearest = frame.size();
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (!frame.valid[i]) continue;
      const double d = std::hypot(frame.x[i] - q.x(), frame.y[i] - q.y());
      if (d <= best) best = d, nearest = i;
    }
    p.s.push_back(t * length), p.x.push_back(q.x()), p.y.push_back(q.y());
    p.sim_u.push_back(s[0]), p.sim_v.push_back(s[1]);
    p.piv_u.push_back(nearest < frame.size() ? frame.u[nearest] : NAN);
    p.piv_v.push_back(nearest < frame.size() ? frame.v[nearest] : NAN);
  }
  return p;
}

void write_comparison_csv(const std::filesystem::path& path, const PivFrame& f,
                          const FrameComparison& c) {
  auto out = open_out(path);
  const bool rms = !f.u_rms.empty();
  out << "x,y,valid,piv_u,piv_v,sim_u,sim_v" << (rms ? ",piv_urms,piv_vrms,sim_urms,sim_vrms" : "")
      << '\n';
  for (std::size_t i = 0; i < f.size(); ++i) {
    out << num(f.x[i]) << ',' << num(f.y[i]) << ',' << int(f.valid[i]) << ',' << num(f.u[i]) << ','
        << num(f.v[i]) << ',' << num(c.sim_u[i]) << ',' << num(c.sim_v[i]);
    if (rms)
      out << ',' << num(f.u_rms[i]) << ',' << num(f.v_rms[i]) << ',' << num(c.sim_urms[i]) << ','
          << num(c.sim_vrms[i]);
    out << '\n';
  }
}

void write_profile_csv(const std::filesystem::path& path, const Profile& p) {
  auto out = open_out(path);
  out << "s,x,y,sim_u,sim_v,piv_u,piv_v\n";
  for (std::size_t k = 0; k < p.s.size(); ++k)
    out << num(p.s[k]) << ',' << num(p.x[k]) << ',' << num(p.y[k]) << ',' << num(p.sim_u[k]) << ','
        << num(p.sim_v[k]) << ',' << num(p.piv_u[k]) << ',' << num(p.piv_v[k]) << '\n';
}

void write_metrics_csv(const std::filesystem::path& path, const std::vector<FrameComparison>& c) {
  auto out = open_out(path);
  out << "frame,phase,quantity,rmse,normalised_error,correlation,points,masked,outside\n";
  for (const auto& f : c) {
    const std::pair<const char*, const FieldMetrics*> q[] = {
        {"u", &f.u}, {"v", &f.v}, {"u_rms", &f.u_rms}, {"v_rms", &f.v_rms}};
    for (const auto& [name, m] : q)
      out << '"' << f.label << "\"," << num(f.phase) << ',' << name << ',' << num(m->rmse) << ','
          << num(m->normalised_error) << ',' << num(m->correlation) << ',' << m->points << ','
          << f.masked << ',' << f.outside << '\n';
  }
}

}  // namespace valsalva::analysis
