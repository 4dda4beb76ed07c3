// PIV comparison: synthetic PIV built from an analytic (linear) mean field and constant Reynolds
// stresses on a plane tilted about two axes, with Gaussian noise of sigma = 0.01 m/s and 10%
// masked points. Linear fields are interpolated exactly, so without noise the errors are
// round-off, and with noise the RMSE is sigma within its sampling scatter (n ~ 400 points:
// relative standard deviation 1/sqrt(2n) = 3.5%, tolerance 15%). Points beyond the mesh are
// counted and skipped; profiles follow the analytic field.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "analysis/piv_compare.hpp"
#include "mesh/box_generator.hpp"

using namespace valsalva;

namespace {

Eigen::Vector3d mean_u(const Eigen::Vector3d& x) {
  return {0.2 + 0.5 * x.x() - 0.3 * x.z(), 0.4 + 0.1 * x.y(), -0.2 + 0.3 * x.x()};
}
// Reynolds stress tensor (constant): RMS 0.05, 0.04, 0.03 and correlations.
Eigen::Matrix3d stress() {
  Eigen::Matrix3d r;
  r << 0.0025, 0.0006, -0.0002, 0.0006, 0.0016, 0.0003, -0.0002, 0.0003, 0.0009;
  return r;
}

struct Setup {
  mesh::Mesh mesh;
  analysis::SimulationStatistics sim;
};

Setup setup(const std::string& type) {
  mesh::BoxSpec spec;
  spec.cell_type = mesh::parse_box_cell_type(type);
  spec.cells = {6, 6, 6};
  spec.perturbation = 0.1;
  Setup s{mesh::generate_box(spec), {}};
  const auto r = stress();
  for (const auto& x : s.mesh.nodes) {
    const auto u = mean_u(x);
    s.sim.mean_velocity.insert(s.sim.mean_velocity.end(), {u.x(), u.y(), u.z()});
    s.sim.rms_velocity.insert(s.sim.rms_velocity.end(),
                              {std::sqrt(r(0, 0)), std::sqrt(r(1, 1)), std::sqrt(r(2, 2))});
    s.sim.reynolds_uv.push_back(r(0, 1));
    s.sim.reynolds_uw.push_back(r(0, 2));
    s.sim.reynolds_vw.push_back(r(1, 2));
  }
  return s;
}

// Plane through the cube centre, tilted by a = 30 deg about y and b = 20 deg about x.
analysis::PivPlane tilted_plane() {
  const double a = M_PI / 6, b = M_PI / 9;
  return analysis::PivPlane({0.5, 0.5, 0.5}, {std::cos(a), 0, std::sin(a)},
                            {-std::sin(a) * std::sin(b), std::cos(b), std::cos(a) * std::sin(b)});
}

analysis::PivFrame synthetic(const analysis::PivPlane& plane, double sigma, std::uint64_t seed,
                             double extent) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  analysis::PivFrame f;
  f.label = "phase 0.3";
  f.ni = 21, f.nj = 21;
  const auto r = stress();
  for (int j = 0; j < f.nj; ++j)
    for (int i = 0; i < f.ni; ++i) {
      const double x = -extent + 2 * extent * i / (f.ni - 1),
                   y = -extent + 2 * extent * j / (f.nj - 1);
      const auto u = mean_u(plane.point(x, y));
      f.x.push_back(x), f.y.push_back(y);
      f.u.push_back(u.dot(plane.ex) + noise(rng));
      f.v.push_back(u.dot(plane.ey) + noise(rng));
      f.u_rms.push_back(std::sqrt(plane.ex.dot(r * plane.ex)) + noise(rng));
      f.v_rms.push_back(std::sqrt(plane.ey.dot(r * plane.ey)) + noise(rng));
      const bool masked = unit(rng) < 0.1;
      if (masked && (i + j) % 2) f.u.back() = NAN;  // some NaN, some flagged
      f.valid.push_back(masked ? 0 : 1);
    }
  return f;
}

}  // namespace

TEST_CASE("PIV comparison on a tilted plane: round-off without noise, sigma with noise") {
  for (std::string type : {"tetra", "hexa"}) {
    CAPTURE(type);
    const auto s = setup(type);
    const mesh::PointLocator locator(s.mesh);
    const auto plane = tilted_plane();
    const auto exact = synthetic(plane, 0.0, 1, 0.3);
    const analysis::PivSampler exact_sampler(locator, plane, exact);
    const auto c0 = analysis::compare_frame(exact, exact_sampler, s.sim);
    CHECK(c0.outside == 0);
    CHECK(c0.u.points == exact.valid_count());
    CHECK(c0.u.rmse < 1e-13);
    CHECK(c0.v.rmse < 1e-13);
    CHECK(c0.u_rms.rmse < 1e-13);
    CHECK(c0.v_rms.rmse < 1e-13);
    CHECK(c0.u.correlation == doctest::Approx(1.0).epsilon(1e-12));

    const double sigma = 0.01;
    const auto noisy = synthetic(plane, sigma, 2, 0.3);
    const auto c =
        analysis::compare_frame(noisy, analysis::PivSampler(locator, plane, noisy), s.sim);
    MESSAGE(type, ": RMSE u ", c.u.rmse, " v ", c.v.rmse, " u_rms ", c.u_rms.rmse, " v_rms ",
            c.v_rms.rmse, "; normalised u ", c.u.normalised_error, "; correlation u ",
            c.u.correlation, " v ", c.v.correlation, "; masked ", c.masked);
    for (const auto* m : {&c.u, &c.v, &c.u_rms, &c.v_rms})
      CHECK(m->rmse == doctest::Approx(sigma).epsilon(0.15));
    CHECK(c.masked > 20);
    CHECK(c.u.points == noisy.size() - c.masked);
    CHECK(c.u.correlation > 0.95);
    CHECK(c.u.normalised_error < 0.1);

    // A PIV window larger than the domain: outside points counted and skipped.
    const auto wide = synthetic(plane, 0.0, 3, 0.8);
    const analysis::PivSampler wide_sampler(locator, plane, wide);
    const auto cw = analysis::compare_frame(wide, wide_sampler, s.sim);
    CHECK(cw.outside > 50);
    CHECK(cw.u.points + cw.outside <= wide.size());
    CHECK(cw.u.rmse < 1e-13);

    // Profile along the plane's x axis: the simulation follows the analytic field exactly, the
    // PIV side takes the nearest grid point (spacing 0.03) and so matches to sigma.
    const auto profile = analysis::sample_profile({"x_axis", {-0.3, 0.0}, {0.3, 0.0}, 21},
                                                  exact_sampler, noisy, s.sim, 0.02);
    double worst = 0;
    for (std::size_t k = 0; k < profile.s.size(); ++k)
      worst =
          std::max(worst, std::abs(profile.sim_u[k] -
                                   mean_u(plane.point(profile.x[k], profile.y[k])).dot(plane.ex)));
    CHECK(worst < 1e-13);
    CHECK(profile.s.back() == doctest::Approx(0.6));

    const std::filesystem::path out = "test_output/piv_compare";
    std::filesystem::create_directories(out);
    analysis::write_comparison_csv(out / ("frame_" + type + ".csv"), noisy, c);
    analysis::write_profile_csv(out / ("profile_" + type + ".csv"), profile);
    analysis::write_metrics_csv(out / ("metrics_" + type + ".csv"), {c0, c});
    std::ifstream metrics(out / ("metrics_" + type + ".csv"));
    std::string header;
    std::getline(metrics, header);
    CHECK(header == "frame,phase,quantity,rmse,normalised_error,correlation,points,masked,outside");
  }
  CHECK_THROWS_WITH(analysis::PivPlane({0, 0, 0}, {1, 0, 0}, {0.1, 1, 0}),
                    doctest::Contains("must be orthogonal unit vectors"));
}

namespace {

// The metrics that must not depend on the file's units.
std::vector<double> metrics(const analysis::FrameComparison& c) {
  std::vector<double> m;
  for (const auto* q : {&c.u, &c.v})
    m.insert(m.end(), {q->rmse, q->normalised_error, q->correlation, double(q->points)});
  m.insert(m.end(), {double(c.masked), double(c.outside)});
  return m;
}

void check_same_metrics(const analysis::FrameComparison& a, const analysis::FrameComparison& b) {
  const auto ma = metrics(a), mb = metrics(b);
  for (std::size_t i = 0; i < ma.size(); ++i) {
    CAPTURE(i);
    // x 1000 and x 0.001 round to within 2 ulp; metrics are sums of a few hundred terms.
    CHECK(mb[i] == doctest::Approx(ma[i]).epsilon(1e-12));
  }
}

}  // namespace

TEST_CASE("PIV files in mm and mm/s read with scale factors give the metrics of the file in m") {
  const auto s = setup("hexa");
  const mesh::PointLocator locator(s.mesh);
  const auto plane = tilted_plane();
  // 1. The stored Tecplot test file and its copy in mm (tests/data/piv/good_mm.dat).
  const std::filesystem::path data = std::filesystem::path(VALSALVA_SOURCE_DIR) / "tests/data/piv";
  const auto m = analysis::read_piv(data / "good.dat");
  const auto mm = analysis::read_piv(data / "good_mm.dat", {1e-3, 1e-3});
  REQUIRE(mm.frames.size() == m.frames.size());
  for (std::size_t f = 0; f < m.frames.size(); ++f) {
    const auto& a = m.frames[f];
    const auto& b = mm.frames[f];
    CHECK(b.phase == a.phase);  // times are not scaled
    check_same_metrics(analysis::compare_frame(a, analysis::PivSampler(locator, plane, a), s.sim),
                       analysis::compare_frame(b, analysis::PivSampler(locator, plane, b), s.sim));
  }
  // 2. A noisy synthetic frame written as CSV in m and in mm (with RMS columns).
  const auto frame = synthetic(plane, 0.01, 5, 0.3);
  const std::filesystem::path out = "test_output/piv_units";
  std::filesystem::create_directories(out);
  for (const auto& [name, k] : {std::pair{"m.csv", 1.0}, std::pair{"mm.csv", 1000.0}}) {
    std::ofstream f(out / name);
    f.precision(17);
    f << "x,y,u,v,u_rms,v_rms,valid\n";
    for (std::size_t i = 0; i < frame.size(); ++i)
      f << k * frame.x[i] << ',' << k * frame.y[i] << ',' << k * frame.u[i] << ',' << k * frame.v[i]
        << ',' << k * frame.u_rms[i] << ',' << k * frame.v_rms[i] << ',' << int(frame.valid[i])
        << '\n';
  }
  const auto a = analysis::read_piv(out / "m.csv").frames.at(0);
  const auto b = analysis::read_piv(out / "mm.csv", {1e-3, 1e-3}).frames.at(0);
  const auto ca = analysis::compare_frame(a, analysis::PivSampler(locator, plane, a), s.sim);
  const auto cb = analysis::compare_frame(b, analysis::PivSampler(locator, plane, b), s.sim);
  CHECK(ca.u.points > 300);
  check_same_metrics(ca, cb);
  CHECK(cb.u_rms.rmse == doctest::Approx(ca.u_rms.rmse).epsilon(1e-12));
  // Without the scale factors the mm file is far off (the check can fail).
  const auto raw = analysis::read_piv(out / "mm.csv").frames.at(0);
  CHECK(analysis::compare_frame(raw, analysis::PivSampler(locator, plane, raw), s.sim).outside >
        300);

  CHECK_THROWS_WITH_AS(analysis::read_piv(data / "good.dat", {0.0, 1.0}),
                       doctest::Contains("length scale 0 and velocity scale 1 must be positive"),
                       std::invalid_argument);
}
