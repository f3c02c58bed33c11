/// @file breath_trace.cpp
/// @brief The CSV surrogates of breath_trace.h, and a marker's projection on its breathing axis.
#include "sim/breathing/breath_trace.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <Eigen/Eigenvalues>

namespace lungar::sim {
std::vector<TraceSample> marker_excursion(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& p) {
  const Eigen::Vector3d axis = breathing_axis(t, p, kAxisWindowS);
  std::vector<TraceSample> out;
  for (std::size_t i = 0; i < p.size(); ++i) out.push_back({t[i] - t.front(), axis.dot(p[i] - p.front())});
  return out;
}

Status check_sample_times(const BreathTrace& trace, const std::string& path) {
  const std::vector<TraceSample>& s = trace.samples;
  std::vector<double> dt;
  for (std::size_t i = 1; i < s.size(); ++i) dt.push_back(s[i].t_s - s[i - 1].t_s);
  if (dt.empty()) return ok();
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  const double median = dt[dt.size() / 2];
  if (median >= 1e-3 && median <= 2.0) return ok();
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g s", median);
  return fail(path + ": t_s: expected times in seconds (a median interval from 0.001 to 2 s), got a median of " +
              buf + (median > 2.0 ? " (milliseconds under a t_s header?)" : ""));
}

BreathTrace without_flagged(BreathTrace trace) {
  std::erase_if(trace.samples, [](const TraceSample& s) { return s.flagged; });
  return trace;
}

Eigen::Vector3d breathing_axis(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& p, double window_s) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (; n < p.size() && t[n] - t.front() <= window_s; ++n) mean += p[n];
  if (n == 0) return Eigen::Vector3d::UnitZ();
  mean /= static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) scatter += (p[i] - mean) * (p[i] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  const Eigen::Vector3d axis = eig.eigenvectors().col(2);
  // Which way is inhalation: two signs of it, which agree in quiet breathing. The chest dwells at end-exhale
  // and leaves it in the inhale direction only (a sigh, a deep breath: the inspiratory capacity is several tidal
  // volumes, the reserve below end-exhale is not breathed into), so the excursion's skewness points the inhale
  // way; and inhalation is the shorter phase, so the signal spends less time rising than falling. A strong tail
  // (|skewness| >= 1) decides; else the phases do, as the skewness of near-sinusoidal breathing is noise.
  std::vector<double> x(n);
  double m = 0;
  for (std::size_t i = 0; i < n; ++i) m += x[i] = axis.dot(p[i]);
  m /= static_cast<double>(n);
  double m2 = 0, m3 = 0;
  for (double v : x) m2 += (v - m) * (v - m), m3 += (v - m) * (v - m) * (v - m);
  const double skew = m2 > 0 ? (m3 / static_cast<double>(n)) / std::pow(m2 / static_cast<double>(n), 1.5) : 0.0;
  if (std::abs(skew) >= 1.0) return skew > 0 ? axis : Eigen::Vector3d(-axis);
  // Count the time spent rising over the window (a 0.2 s difference, so that noise does not count).
  double rising = 0, falling = 0;
  for (std::size_t i = 1; i < n; ++i) {
    std::size_t j = i;
    while (j > 0 && t[i] - t[j] < 0.2) --j;
    (x[i] > x[j] ? rising : falling) += t[i] - t[i - 1];
  }
  return rising > falling ? Eigen::Vector3d(-axis) : axis;
}

Result<BreathTrace> read_breath_trace(const std::string& path) {
  std::ifstream in(path);
  const bool vxp = path.size() > 4 &&
                   (path.compare(path.size() - 4, 4, ".vxp") == 0 || path.compare(path.size() - 4, 4, ".VXP") == 0);
  if (!in)
    return fail(path + ": cannot open: expected " +
                (vxp ? "a Varian RPM .vxp file" : "a CSV trace (t_s,value or t_s,x_mm,y_mm,z_mm)"));
  std::string first;
  std::getline(in, first);
  const bool extmarker = first.rfind("\"Frame\";", 0) == 0 || first.rfind("Frame;", 0) == 0;
  in.clear();
  in.seekg(0);
  auto trace = vxp ? parse_vxp_trace(in, path) : extmarker ? parse_extmarker_trace(in, path) : parse_csv_trace(in, path);
  if (!trace) return trace;
  if (Status times = check_sample_times(*trace, path); !times) return fail(times.error());
  return trace;
}

Result<BreathTrace> parse_csv_trace(std::istream& in, const std::string& path) {
  std::string line;
  int line_no = 0;
  int columns = 0;
  std::vector<double> t;
  std::vector<Eigen::Vector3d> p;
  BreathTrace out;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto at = [&](const std::string& why) { return fail(path + ":" + std::to_string(line_no) + ": " + why); };
    if (columns == 0) {
      if (line == "t_s,value")
        columns = 2;
      else if (line == "t_s,x_mm,y_mm,z_mm")
        columns = 4;
      else
        return at("header: expected 't_s,value' or 't_s,x_mm,y_mm,z_mm', got '" + line + "'");
      continue;
    }
    std::stringstream fields(line);
    std::string cell;
    double v[4];
    int got = 0;
    for (; got < 4 && std::getline(fields, cell, ','); ++got) {
      char* end = nullptr;
      v[got] = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(v[got]))
        return at("expected finite numbers, got '" + line + "'");
    }
    if (got != columns || std::getline(fields, cell, ','))
      return at("expected " + std::to_string(columns) + " numbers, got '" + line + "'");
    if (!t.empty() && v[0] <= t.back()) return at("t_s: expected times that increase, got '" + line + "'");
    t.push_back(v[0]);
    if (columns == 2)
      out.samples.push_back({v[0], v[1]});
    else
      p.emplace_back(v[1], v[2], v[3]);
  }
  if (columns == 0) return fail(path + ": expected a header and samples, got none");
  if (t.size() < 2) return fail(path + ": expected at least two samples, got " + std::to_string(t.size()));
  if (columns == 4) {
    out.marker = true;
    out.samples = marker_excursion(t, p);
  } else {
    const double t0 = out.samples.front().t_s;
    for (TraceSample& s : out.samples) s.t_s -= t0;
  }
  return out;
}

}  // namespace lungar::sim
