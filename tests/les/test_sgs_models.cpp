// Subgrid models (les/sgs_kernels.hpp, les/sgs_model.hpp): the flows where Sigma must vanish,
// near-wall scaling, hand-computed values, the factory and the array loop.
#include <doctest/doctest.h>

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "les/sgs_kernels.hpp"
#include "les/sgs_model.hpp"
#include "random_gradients.hpp"

using namespace valsalva::les;
using namespace valsalva::les::test;

TEST_CASE("D_sigma vanishes to round-off for the flows of Nicoud et al. 2011 (Sec. II)") {
  // Each canonical gradient is put in 200 random orientations (R g R^T) with magnitudes 1..1e4.
  // Round-off bound: D_sigma/|g| < 1e-13, against ~0.05-0.3 for a generic 3D gradient.
  std::mt19937_64 rng(1999);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto worst_for = [&](auto make) {
    double worst = 0.0;
    for (int t = 0; t < 200; ++t) {
      const Eigen::Matrix3d R = random_rotation(rng);
      const Eigen::Matrix3d g = R * make() * R.transpose() * std::pow(10.0, 2.0 + 2.0 * u(rng));
      worst = std::max(worst, std::abs(sigma_operator(g)) / g.norm());
    }
    return worst;
  };
  const double solid_rotation = worst_for([&] {
    Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
    w(0, 1) = -1.0;
    w(1, 0) = 1.0;
    return w;
  });
  const double pure_shear = worst_for([&] {
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    s(0, 1) = 1.0;
    return s;
  });
  const double flow_2d = worst_for([&] {  // any in-plane gradient, no out-of-plane dependence
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    s.topLeftCorner<2, 2>() << u(rng), u(rng), u(rng), u(rng);
    return s;
  });
  const double axisymmetric =
      worst_for([&] { return Eigen::Matrix3d(Eigen::Vector3d(1.0, 1.0, -2.0).asDiagonal()); });
  const double axisym_rotating = worst_for([&] {  // expansion + swirl about the axis
    Eigen::Matrix3d s = Eigen::Vector3d(1.0, 1.0, -2.0).asDiagonal();
    s(0, 1) = -0.7;
    s(1, 0) = 0.7;
    return s;
  });
  const double isotropic = worst_for([&] { return Eigen::Matrix3d(Eigen::Matrix3d::Identity()); });
  double generic_min = 1.0;
  for (int t = 0; t < 200; ++t) {
    const Eigen::Matrix3d g = gaussian_matrix(rng);
    generic_min = std::min(generic_min, sigma_operator(g) / g.norm());
  }
  MESSAGE("max D_sigma/|g|: solid rotation "
          << solid_rotation << ", pure shear " << pure_shear << ", 2D " << flow_2d
          << ", axisymmetric " << axisymmetric << ", axisymmetric+swirl " << axisym_rotating
          << ", isotropic " << isotropic);
  CHECK(solid_rotation < 1e-13);
  CHECK(pure_shear < 1e-13);
  CHECK(flow_2d < 1e-13);
  CHECK(axisymmetric < 1e-13);
  CHECK(axisym_rotating < 1e-13);
  CHECK(isotropic < 1e-13);
  CHECK(generic_min >= 0.0);
}

namespace {
// Velocity gradient of a divergence-free, no-slip field near the wall y = 0, at (x, z):
//   u = y f + y^2 h,  w = y k + y^2 m,  v = -y^2/2 (f_x + k_z) - y^3/3 (h_x + m_z),
// with smooth f, k, h, m of (x, z). Rows: components u, v, w; columns: d/dx, d/dy, d/dz.
Eigen::Matrix3d near_wall_gradient(double y) {
  const double x = 0.3, z = 0.7;
  const double f = 1.0 + 0.3 * std::sin(x) + 0.2 * std::sin(z), f_x = 0.3 * std::cos(x),
               f_z = 0.2 * std::cos(z), f_xx = -0.3 * std::sin(x), f_xz = 0.0;
  const double k = 0.5 + 0.4 * std::cos(x) * std::cos(z), k_x = -0.4 * std::sin(x) * std::cos(z),
               k_z = -0.4 * std::cos(x) * std::sin(z), k_zx = 0.4 * std::sin(x) * std::sin(z),
               k_zz = -0.4 * std::cos(x) * std::cos(z);
  const double h = 0.7 + 0.2 * std::cos(x), h_x = -0.2 * std::sin(x), h_z = 0.0,
               h_xx = -0.2 * std::cos(x), h_xz = 0.0;
  const double m = -0.3 + 0.1 * std::sin(z), m_x = 0.0, m_z = 0.1 * std::cos(z), m_zx = 0.0,
               m_zz = -0.1 * std::sin(z);
  const double y2 = y * y, y3 = y2 * y;
  Eigen::Matrix3d g;
  g << y * f_x + y2 * h_x, f + 2 * y * h, y * f_z + y2 * h_z,
      -y2 / 2 * (f_xx + k_zx) - y3 / 3 * (h_xx + m_zx), -y * (f_x + k_z) - y2 * (h_x + m_z),
      -y2 / 2 * (f_xz + k_zz) - y3 / 3 * (h_xz + m_zz),  //
      y * k_x + y2 * m_x, k + 2 * y * m, y * k_z + y2 * m_z;
  return g;
}

// Least-squares slope of log(value) against log(y) for y in [1e-4, 1e-2].
template <class F>
double fitted_exponent(F value) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int n = 21;
  for (int i = 0; i < n; ++i) {
    const double ly = std::log(1e-4) + i * (std::log(1e-2) - std::log(1e-4)) / (n - 1);
    const double lv = std::log(value(near_wall_gradient(std::exp(ly))));
    sx += ly, sy += lv, sxx += ly * ly, sxy += ly * lv;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}
}  // namespace

TEST_CASE("near-wall scaling: D_sigma ~ y^3 (and WALE ~ y^3, Smagorinsky ~ y^0)") {
  CHECK(std::abs(near_wall_gradient(1e-3).trace()) < 1e-15);  // divergence-free
  const double p_sigma =
      fitted_exponent([](const Eigen::Matrix3d& g) { return sigma_operator(g); });
  const double p_wale = fitted_exponent([](const Eigen::Matrix3d& g) { return wale_operator(g); });
  const double p_smag =
      fitted_exponent([](const Eigen::Matrix3d& g) { return strain_rate_magnitude(g); });
  MESSAGE("fitted exponents: sigma " << p_sigma << ", wale " << p_wale << ", smagorinsky "
                                     << p_smag);
  CHECK(std::abs(p_sigma - 3.0) < 0.05);
  CHECK(std::abs(p_wale - 3.0) < 0.05);
  CHECK(std::abs(p_smag) < 0.05);
}

TEST_CASE("hand-computed nu_sgs values") {
  const double delta = 2e-3;
  std::mt19937_64 rng(7);
  SUBCASE("sigma: singular values (3, 2, 1) -> D = 1*1*1/9, any orientation") {
    const Eigen::Matrix3d g = random_rotation(rng) * Eigen::Vector3d(3.0, 2.0, 1.0).asDiagonal() *
                              random_rotation(rng).transpose();
    CHECK(sigma_nu(g, delta, 1.35) ==
          doctest::Approx(1.35 * 1.35 * delta * delta / 9.0).epsilon(1e-13));
    // (4, 2, 1): D = 1 * 2 * 1 / 16.
    CHECK(sigma_operator(Eigen::Vector3d(1.0, 4.0, 2.0).asDiagonal()) ==
          doctest::Approx(0.125).epsilon(1e-14));
  }
  SUBCASE("wale and smagorinsky for g = [[0,2,0],[1,0,0],[0,0,0]]") {
    // S = [[0,3/2,0],[3/2,0,0],0]: S:S = 9/2, |S| = sqrt(2 S:S) = 3.
    // g^2 = diag(2, 2, 0), tr = 4: Sd = diag(2/3, 2/3, -4/3), Sd:Sd = 8/3.
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    g(0, 1) = 2.0;
    g(1, 0) = 1.0;
    const double sdsd = 8.0 / 3.0, ss = 4.5;
    const double wale =
        std::pow(0.5 * delta, 2) * std::pow(sdsd, 1.5) / (std::pow(ss, 2.5) + std::pow(sdsd, 1.25));
    CHECK(wale_nu(g, delta, 0.5) == doctest::Approx(wale).epsilon(1e-14));
    CHECK(smagorinsky_nu(g, delta, 0.17) ==
          doctest::Approx(0.17 * 0.17 * delta * delta * 3.0).epsilon(1e-14));
    CHECK(sigma_nu(g, delta, 1.35) == 0.0);  // 2D gradient
  }
  SUBCASE("wale vanishes for pure shear (g^2 = 0), smagorinsky gives (C_s Delta)^2 |S|") {
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    g(0, 1) = 5.0;
    CHECK(wale_nu(g, delta, 0.5) == 0.0);
    CHECK(smagorinsky_nu(g, delta, 0.17) ==
          doctest::Approx(0.17 * 0.17 * delta * delta * 5.0).epsilon(1e-14));
  }
}

TEST_CASE("zero gradient gives zero, a NaN gradient gives NaN (never a silent zero)") {
  const Eigen::Matrix3d zero = Eigen::Matrix3d::Zero();
  CHECK(sigma_nu(zero, 1e-3, 1.35) == 0.0);
  CHECK(wale_nu(zero, 1e-3, 0.5) == 0.0);
  CHECK(smagorinsky_nu(zero, 1e-3, 0.17) == 0.0);
  Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
  bad(2, 0) = std::nan("");
  CHECK(std::isnan(sigma_nu(bad, 1e-3, 1.35)));
  CHECK(std::isnan(wale_nu(bad, 1e-3, 0.5)));
  CHECK(std::isnan(smagorinsky_nu(bad, 1e-3, 0.17)));
}

TEST_CASE("model constants follow their sources") {
  // Lilly: (1/pi)(3*1.5/2)^(-3/4) = 0.1733; the default 0.17 is its two-digit value.
  CHECK(lilly_smagorinsky_constant(1.5) == doctest::Approx(0.17330).epsilon(1e-4));
  CHECK(std::abs(default_c_smagorinsky - lilly_smagorinsky_constant(1.5)) < 0.005);
  // Nicoud & Ducros: C_w = sqrt(10.6) C_s; C_w = 0.5 <-> C_s = 0.1536, C_w = 0.325 <-> C_s = 0.1.
  CHECK(wale_constant_from_smagorinsky(0.1) == doctest::Approx(0.3256).epsilon(1e-3));
  CHECK(default_c_wale / std::sqrt(10.6) == doctest::Approx(0.15357).epsilon(1e-4));
  CHECK(default_c_sigma == 1.35);
}

TEST_CASE("model factory") {
  CHECK(make_sgs_model(SgsKind::sigma).kind == SgsKind::sigma);
  CHECK(make_sgs_model(SgsKind::sigma).constant == 1.35);
  CHECK(make_sgs_model(SgsKind::sigma, 1.5).constant == 1.5);
  CHECK(make_sgs_model(SgsKind::wale).constant == 0.5);
  CHECK(make_sgs_model(SgsKind::smagorinsky).constant == 0.17);
  CHECK(make_sgs_model(SgsKind::none).kind == SgsKind::none);
  for (const char* n : {"sigma", "wale", "smagorinsky", "none"})
    CHECK(to_string(parse_sgs_kind(n)) == n);
  std::string msg;
  try {
    parse_sgs_kind("Sigma");
  } catch (const std::invalid_argument& e) {
    msg = e.what();
  }
  CHECK(msg.find("'Sigma'") != std::string::npos);
  CHECK(msg.find("none, sigma, wale, smagorinsky") != std::string::npos);
  CHECK_THROWS_AS(make_sgs_model(SgsKind::wale, -0.5), std::invalid_argument);
  CHECK_THROWS_AS(make_sgs_model(SgsKind::wale, std::nan("")), std::invalid_argument);
}

TEST_CASE("array loop equals the kernels node by node") {
  std::mt19937_64 rng(3);
  const std::size_t n = 1000;
  std::vector<Eigen::Matrix3d> grad(n);
  std::vector<double> volume(n), delta(n), nu(n);
  std::uniform_real_distribution<double> vol(1e-10, 1e-9);
  for (std::size_t i = 0; i < n; ++i) grad[i] = 100.0 * gaussian_matrix(rng), volume[i] = vol(rng);
  filter_width(volume, delta);
  CHECK(delta[17] * delta[17] * delta[17] == doctest::Approx(volume[17]).epsilon(1e-14));
  for (const SgsKind kind : {SgsKind::sigma, SgsKind::wale, SgsKind::smagorinsky, SgsKind::none}) {
    const SgsModel model = make_sgs_model(kind);
    compute_nu_sgs(model, grad, delta, nu);
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double ref = 0.0;
      if (model.kind == SgsKind::sigma) ref = sigma_nu(grad[i], delta[i], 1.35);
      if (model.kind == SgsKind::wale) ref = wale_nu(grad[i], delta[i], 0.5);
      if (model.kind == SgsKind::smagorinsky) ref = smagorinsky_nu(grad[i], delta[i], 0.17);
      worst = std::max(worst, std::abs(nu[i] - ref));
    }
    CHECK(worst == 0.0);
    // Flat row-major layout gives the same values.
    std::vector<double> flat(9 * n), nu_flat(n);
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) flat[9 * i + 3 * r + c] = grad[i](r, c);
    compute_nu_sgs(model, std::span<const double>(flat), delta, nu_flat);
    CHECK(nu_flat == nu);
  }
  std::vector<double> bad_flat(9 * n - 1);
  CHECK_THROWS_AS(
      compute_nu_sgs(make_sgs_model(SgsKind::wale), std::span<const double>(bad_flat), delta, nu),
      std::invalid_argument);
  std::vector<double> short_out(n - 1);
  CHECK_THROWS_AS(compute_nu_sgs(make_sgs_model(SgsKind::sigma), grad, delta, short_out),
                  std::invalid_argument);
}
