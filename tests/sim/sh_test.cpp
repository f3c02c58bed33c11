/// @file sh_test.cpp
/// @brief Real SH: orthonormal under an exact product quadrature, and the known low bands.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/sh/real_sh.h"

namespace lungar::sim {
namespace {

/// Gauss-Legendre nodes and weights on [-1, 1] by Newton's method on P_n.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-15) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

TEST(RealSh, OrthonormalUnderExactQuadratureOnAFineSphere) {
  constexpr int bands = kMaxBands, c = bands * bands;
  std::vector<double> z, wz;
  gauss_legendre(24, z, wz);  // exact for the degree-14 products of two band-7 harmonics
  const int nphi = 48;
  std::vector<double> gram(c * c, 0.0), y(c);
  for (std::size_t i = 0; i < z.size(); ++i)
    for (int k = 0; k < nphi; ++k) {
      const double phi = 2 * std::numbers::pi * k / nphi, s = std::sqrt(1 - z[i] * z[i]);
      real_sh(bands, Eigen::Vector3d(s * std::cos(phi), s * std::sin(phi), z[i]), y.data());
      const double w = wz[i] * 2 * std::numbers::pi / nphi;
      for (int a = 0; a < c; ++a)
        for (int b = 0; b < c; ++b) gram[a * c + b] += w * y[a] * y[b];
    }
  for (int a = 0; a < c; ++a)
    for (int b = 0; b < c; ++b) EXPECT_NEAR(gram[a * c + b], a == b ? 1.0 : 0.0, 1e-12) << a << "," << b;
}

TEST(RealSh, LowBandsHaveTheirClosedForms) {
  const Eigen::Vector3d u = Eigen::Vector3d(0.3, -0.5, 0.7).normalized();
  double y[4];
  real_sh(2, u, y);
  const double k1 = std::sqrt(3 / (4 * std::numbers::pi));
  EXPECT_NEAR(y[sh_index(0, 0)], 0.5 / std::sqrt(std::numbers::pi), 1e-15);
  EXPECT_NEAR(std::abs(y[sh_index(1, 0)]), k1 * std::abs(u.z()), 1e-14);
  EXPECT_NEAR(std::abs(y[sh_index(1, 1)]), k1 * std::abs(u.x()), 1e-14);
  EXPECT_NEAR(std::abs(y[sh_index(1, -1)]), k1 * std::abs(u.y()), 1e-14);
}

}  // namespace
}  // namespace lungar::sim
