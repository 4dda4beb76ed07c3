#include "analysis/piv_export.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace valsalva::analysis {

namespace {

// 17 significant digits: a double printed and parsed back is the same double.
std::string exact(double x) {
  return std::isfinite(x) ? fmt::format("{:.17g}", x) : std::string();
}

}  // namespace

PivFrame piv_grid_frame(const PivGrid& g) {
  if (g.nx < 1 || g.ny < 1)
    throw std::invalid_argument(
        fmt::format("PIV grid: {} x {} vectors; both counts must be at least 1", g.nx, g.ny));
  if (!(g.spacing > 0) || !std::isfinite(g.spacing))
    throw std::invalid_argument(
        fmt::format("PIV grid: spacing {} m must be a positive finite number", g.spacing));
  if (!std::isfinite(g.x0) || !std::isfinite(g.y0))
    throw std::invalid_argument(
        fmt::format("PIV grid: first vector at ({}, {}) m must be finite", g.x0, g.y0));
  PivFrame f;
  f.ni = g.nx, f.nj = g.ny;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      f.x.push_back(g.x0 + i * g.spacing);
      f.y.push_back(g.y0 + j * g.spacing);
    }
  f.valid.assign(f.x.size(), 1);
  return f;
}

void sample_statistics(const PivSampler& sampler, const SimulationStatistics& sim,
                       PivFrame& frame) {
  const std::size_t n = frame.size();
  frame.u.assign(n, NAN), frame.v.assign(n, NAN);
  frame.u_rms.clear(), frame.v_rms.clear();
  if (sim.has_rms()) frame.u_rms.assign(n, NAN), frame.v_rms.assign(n, NAN);
  frame.valid.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector4d s = sampler.sample(i, sim);
    bool ok = std::isfinite(s[0]) && std::isfinite(s[1]);
    if (sim.has_rms()) ok = ok && std::isfinite(s[2]) && std::isfinite(s[3]);
    if (!ok) continue;
    frame.u[i] = s[0], frame.v[i] = s[1];
    if (sim.has_rms()) frame.u_rms[i] = s[2], frame.v_rms[i] = s[3];
    frame.valid[i] = 1;
  }
}

void write_piv_csv(const std::filesystem::path& path, const PivData& data,
                   const std::string& comment) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(fmt::format("PIV export: cannot write '{}'", path.string()));
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << '\n';
  const bool frames = !data.frame_key.empty();
  out << "x,y,u,v" << (data.has_rms ? ",u_rms,v_rms" : "") << ",valid"
      << (frames ? "," + data.frame_key : "") << '\n';
  for (const auto& f : data.frames)
    for (std::size_t i = 0; i < f.size(); ++i) {
      const bool ok = f.valid[i] != 0;
      out << exact(f.x[i]) << ',' << exact(f.y[i]) << ',' << (ok ? exact(f.u[i]) : "") << ','
          << (ok ? exact(f.v[i]) : "");
      if (data.has_rms)
        out << ',' << (ok ? exact(f.u_rms[i]) : "") << ',' << (ok ? exact(f.v_rms[i]) : "");
      out << ',' << (ok ? 1 : 0);
      if (frames) out << ',' << exact(f.phase);
      out << '\n';
    }
  if (!out) throw std::runtime_error(fmt::format("PIV export: cannot write '{}'", path.string()));
}

}  // namespace valsalva::analysis
