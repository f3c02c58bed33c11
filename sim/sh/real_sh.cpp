/// @file real_sh.cpp
/// @brief Real SH from Cartesian coordinates: associated Legendre recurrences in z, and (x + iy)^m for the
///        azimuth, so no trigonometry per evaluation.
#include "sim/sh/real_sh.h"

#include <array>
#include <cmath>
#include <numbers>

namespace lungar::sim {
namespace {

/// K_l^m = sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!), times sqrt(2) for m > 0 (the real form's normalisation).
struct Norms {
  std::array<std::array<double, kMaxBands>, kMaxBands> k{};
  Norms() {
    for (int l = 0; l < kMaxBands; ++l)
      for (int m = 0; m <= l; ++m) {
        double ratio = 1;  // (l-m)!/(l+m)!
        for (int i = l - m + 1; i <= l + m; ++i) ratio /= i;
        k[l][m] = std::sqrt((2 * l + 1) / (4 * std::numbers::pi) * ratio) * (m > 0 ? std::numbers::sqrt2 : 1.0);
      }
  }
};

}  // namespace

void real_sh(int bands, const Eigen::Vector3d& u, double* out) {
  static const Norms norms;
  const double x = u.x(), y = u.y(), z = u.z();
  // P~_l^m(z) = P_l^m(z) / sin^m(theta); the sin^m(theta) e^{i m phi} factor is (x + i y)^m.
  double cm = 1, sm = 0;   // Re and Im of (x + iy)^m
  double pmm = 1;          // P~_m^m = (-1)^m (2m-1)!!
  for (int m = 0; m < bands; ++m) {
    if (m > 0) {
      const double c = cm * x - sm * y, s = cm * y + sm * x;
      cm = c;
      sm = s;
      pmm *= -(2.0 * m - 1);
    }
    double p_lm2 = 0, p_lm1 = pmm;  // P~_{l-2}^m, P~_{l-1}^m while walking up l
    for (int l = m; l < bands; ++l) {
      double p;
      if (l == m) p = pmm;
      else if (l == m + 1) p = z * (2 * m + 1) * pmm;
      else p = ((2 * l - 1) * z * p_lm1 - (l + m - 1) * p_lm2) / (l - m);
      if (l > m) {
        p_lm2 = p_lm1;
        p_lm1 = p;
      }
      const double kp = norms.k[l][m] * p;
      if (m == 0) {
        out[sh_index(l, 0)] = kp;
      } else {
        out[sh_index(l, m)] = kp * cm;
        out[sh_index(l, -m)] = kp * sm;
      }
    }
  }
}

}  // namespace lungar::sim
