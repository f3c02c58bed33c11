/// @file breath_judge.h
/// @brief The figures a followed breath is judged by on a real marker recording, computed as
///        `../shared/tools/breath-check` computes them (and as the team does on its own recordings): |corr| between
///        dV and the marker's breathing axis (the first principal axis of all its positions), both detrended by an
///        8 s running median, after the first 20 s; the marker's main period (the highest peak of its spectrum);
///        the median swing of dV per period; dV's range.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace lungar::sim::testing {

/// An ExtMarker file's rows as the checker reads them: rows whose time does not increase are dropped.
struct MarkerRecording {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> p;
};

inline MarkerRecording read_marker_recording(const std::string& path) {
  MarkerRecording m;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', '.');
    std::erase(line, '"');
    std::replace(line.begin(), line.end(), ';', ' ');
    std::istringstream f(line);
    double frame = 0, ms = 0, x = 0, y = 0, z = 0;
    if (!(f >> frame >> ms >> x >> y >> z)) continue;
    if (!m.t_s.empty() && !(ms / 1000.0 > m.t_s.back())) continue;
    m.t_s.push_back(ms / 1000.0);
    m.p.emplace_back(x, y, z);
  }
  return m;
}

struct BreathFigures {
  double corr = 0;            ///< |corr| of the detrended dV and marker axis after 20 s
  double period_s = 0;        ///< the marker's main period
  double median_swing_ml = 0; ///< dV's peak to trough per period, the median
  double lo_ml = 0, hi_ml = 0;
};

/// `y` less its running median over `window_s` (centred) at each time of `t`.
inline std::vector<double> detrended(const std::vector<double>& t, const std::vector<double>& y, double window_s) {
  std::vector<double> out(y.size()), w;
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    while (t[a] < t[i] - window_s / 2) ++a;
    while (b < y.size() && t[b] <= t[i] + window_s / 2) ++b;
    w.assign(y.begin() + static_cast<std::ptrdiff_t>(a), y.begin() + static_cast<std::ptrdiff_t>(b));
    std::sort(w.begin(), w.end());
    const double median = w.size() % 2 ? w[w.size() / 2] : 0.5 * (w[w.size() / 2 - 1] + w[w.size() / 2]);
    out[i] = y[i] - median;
  }
  return out;
}

/// Pearson's correlation of `a` and `b` (the same length).
inline double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const auto n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sab += (a[i] - ma) * (b[i] - mb), saa += (a[i] - ma) * (a[i] - ma), sbb += (b[i] - mb) * (b[i] - mb);
  return sab / std::sqrt(saa * sbb);
}

/// The figures of dV (`dv` at times `lt`, every 10 ms from 0) against the marker recording `m`.
inline BreathFigures judge(const MarkerRecording& m, const std::vector<double>& lt, const std::vector<double>& dv) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : m.p) mean += p;
  mean /= static_cast<double>(m.p.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : m.p) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::Vector3d axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(2);
  std::vector<double> t, marker, followed;
  for (std::size_t i = 0; i < m.t_s.size(); ++i) {
    if (!(m.t_s[i] > 20.0) || m.t_s[i] > lt.back()) continue;
    t.push_back(m.t_s[i]);
    marker.push_back(axis.dot(m.p[i] - mean));
    const auto k = static_cast<std::size_t>(std::lower_bound(lt.begin(), lt.end(), m.t_s[i]) - lt.begin());
    const double u = k == 0 ? 0.0 : (m.t_s[i] - lt[k - 1]) / (lt[k] - lt[k - 1]);
    followed.push_back(k == 0 ? dv[0] : dv[k - 1] + u * (dv[k] - dv[k - 1]));
  }
  const std::vector<double> a = detrended(t, marker, 8.0), b = detrended(t, followed, 8.0);
  const auto n = static_cast<double>(a.size());
  BreathFigures f;
  f.corr = std::abs(correlation(a, b));
  // The main period: the strongest bin of the detrended marker's spectrum (bin k is k / (N dt)).
  std::vector<double> dts;
  for (std::size_t i = 1; i < t.size(); ++i) dts.push_back(t[i] - t[i - 1]);
  std::nth_element(dts.begin(), dts.begin() + static_cast<std::ptrdiff_t>(dts.size() / 2), dts.end());
  const double dt = dts[dts.size() / 2];
  double best = -1;
  for (std::size_t k = 1; k <= a.size() / 2; ++k) {
    std::complex<double> s = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      s += a[i] * std::polar(1.0, -2.0 * M_PI * static_cast<double>(k * i) / n);
    if (std::abs(s) > best) best = std::abs(s), f.period_s = n * dt / static_cast<double>(k);
  }
  std::vector<double> swings;
  for (double a0 = 20.0; a0 < lt.back() - f.period_s; a0 += f.period_s) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < lt.size(); ++i)
      if (lt[i] >= a0 && lt[i] < a0 + f.period_s) lo = std::min(lo, dv[i]), hi = std::max(hi, dv[i]);
    swings.push_back(hi - lo);
  }
  std::sort(swings.begin(), swings.end());
  f.median_swing_ml = swings.empty() ? 0.0
                      : swings.size() % 2 ? swings[swings.size() / 2]
                                          : 0.5 * (swings[swings.size() / 2 - 1] + swings[swings.size() / 2]);
  f.lo_ml = *std::min_element(dv.begin(), dv.end());
  f.hi_ml = *std::max_element(dv.begin(), dv.end());
  return f;
}

}  // namespace lungar::sim::testing
