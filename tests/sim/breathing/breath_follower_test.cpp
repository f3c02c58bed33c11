/// @file breath_follower_test.cpp
/// @brief The breath follower on traces like real ones: drift, irregular breaths, noise, a 15 s loss, a marker
///        moving along an oblique axis; and the trace files refused in one line naming the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>

#include <Eigen/Core>

#include "sim/breathing/breath_follower.h"
#include "sim/breathing/breath_trace.h"

namespace lungar::sim {
namespace {

/// A surrogate like a chest marker's excursion (mm): breaths of varying depth (+-30 %) and period (3.5-5 s), I:E
/// about 1:2, a baseline sinking 3 mm a minute, 0.1 mm of noise. `breath_peaks` gets each breath's peak time.
struct Trace {
  std::vector<TraceSample> samples;
  std::vector<double> peaks, drift;
};

Trace make_trace(double seconds, double gap_from = -1, double gap_to = -1) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> depth(0.7, 1.3), period(3.5, 5.0);
  std::normal_distribution<double> noise(0.0, 0.1);
  Trace out;
  double start = 0, p = period(rng), a = 10.0 * depth(rng);
  for (double t = 0; t < seconds; t += 0.025) {
    while (t >= start + p) {
      start += p;
      p = period(rng);
      a = 10.0 * depth(rng);
    }
    const double u = (t - start) / p, rise = 1.0 / 3.0;
    const double shape = u < rise ? 0.5 - 0.5 * std::cos(M_PI * u / rise) : std::exp(-4.0 * (u - rise) / (1 - rise)) *
                                                                                 (1 - (u - rise) / (1 - rise) * 0.018);
    if (u < rise && u + 0.025 / p >= rise) out.peaks.push_back(start + rise * p);
    const double drift = -3.0 * t / 60.0;
    if (t >= gap_from && t < gap_to) continue;  // the signal lost
    out.samples.push_back({t, drift + a * shape + noise(rng)});
    out.drift.push_back(drift);
  }
  return out;
}

struct Followed {
  std::vector<double> t, dv;
  std::vector<BreathState> state;
};

Followed follow(const Trace& trace, double seconds, FollowerParams p = {}) {
  BreathFollower f(p);
  Followed r;
  std::size_t next = 0;
  for (double t = 0; t <= seconds; t += 0.01) {
    for (; next < trace.samples.size() && trace.samples[next].t_s <= t; ++next)
      f.add(trace.samples[next].t_s, trace.samples[next].value);
    const double model = 250.0 - 250.0 * std::cos(2 * M_PI * t / 5.0);
    const FollowerOutput o = f.at(t, model);
    r.t.push_back(t);
    r.dv.push_back(o.dv_ml);
    r.state.push_back(o.state);
  }
  return r;
}

TEST(BreathFollower, FollowsADriftingIrregularTraceBreathByBreath) {
  const Trace trace = make_trace(120);
  const Followed run = follow(trace, 120);
  // Peaks: the highest dV within each breath's window falls within 0.3 s of the trace's own peak.
  int near = 0, counted = 0;
  for (double peak : trace.peaks) {
    if (peak < 20 || peak > 115) continue;  // after calibration
    double best_t = 0, best = -1e300;
    for (std::size_t i = 0; i < run.t.size(); ++i)
      if (std::abs(run.t[i] - peak) < 1.2 && run.dv[i] > best) best = run.dv[i], best_t = run.t[i];
    ++counted;
    near += std::abs(best_t - peak) <= 0.3;
  }
  ASSERT_GT(counted, 15);
  EXPECT_GE(static_cast<double>(near) / counted, 0.8) << near << " of " << counted;
  // Correlation with the trace less its drift, over the followed part.
  std::vector<double> x, y;
  std::size_t s = 0;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    if (run.t[i] < 20) continue;
    while (s + 1 < trace.samples.size() && trace.samples[s + 1].t_s <= run.t[i]) ++s;
    x.push_back(run.dv[i]);
    y.push_back(trace.samples[s].value - trace.drift[s]);
  }
  const auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); };
  const double mx = mean(x), my = mean(y);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  EXPECT_GE(sxy / std::sqrt(sxx * syy), 0.9);
  // The median breath swings V_T +- 15 %, and end-exhale comes back to within 15 % of V_T.
  std::vector<double> swings, lows;
  for (std::size_t b = 0; b + 1 < trace.peaks.size(); ++b) {
    if (trace.peaks[b] < 20 || trace.peaks[b + 1] > 118) continue;
    double hi = -1e300, lo = 1e300;
    for (std::size_t i = 0; i < run.t.size(); ++i)
      if (run.t[i] >= trace.peaks[b] - 0.3 && run.t[i] < trace.peaks[b + 1] - 0.3) {
        hi = std::max(hi, run.dv[i]);
        lo = std::min(lo, run.dv[i]);
      }
    swings.push_back(hi - lo);
    lows.push_back(std::abs(lo));
  }
  std::nth_element(swings.begin(), swings.begin() + swings.size() / 2, swings.end());
  EXPECT_NEAR(swings[swings.size() / 2], 500.0, 75.0);
  std::nth_element(lows.begin(), lows.begin() + lows.size() / 2, lows.end());
  EXPECT_LE(lows[lows.size() / 2], 75.0);
}

TEST(BreathFollower, ALostSignalHandsOverWithoutAJumpAndIsPickedUpAgain) {
  const Trace trace = make_trace(90, 40, 55);  // 15 s without samples
  // The held signal, so that "its own step" below is the samples' (predicted, it is the extrapolation's, which
  // moves between samples: BreathPrediction.* covers that).
  FollowerParams held;
  held.predict = false;
  const Followed run = follow(trace, 90, held);
  double biggest_before = 0;  // the signal's own steps while followed, away from the loss
  for (std::size_t i = 1; i < run.t.size(); ++i) {
    const double step = std::abs(run.dv[i] - run.dv[i - 1]);
    if ((run.t[i] > 20 && run.t[i] < 40) || run.t[i] > 70) biggest_before = std::max(biggest_before, step);
    if (run.t[i] > 40.5 && run.t[i] < 55) {
      EXPECT_LE(step, 5.0 + 1e-9) << "while lost, at " << run.t[i];
    }
  }
  // At the return each step is what the signal itself moved (its last sample at or before each step, at the
  // scale of a median breath, 50 mL/mm, give or take the breaths' spread) plus at most the 5 mL handover.
  const auto sample_at = [&](double t) {
    double v = 0;
    for (const TraceSample& x : trace.samples) {
      if (x.t_s > t) break;
      v = x.value;
    }
    return v;
  };
  for (std::size_t i = 1; i < run.t.size(); ++i) {
    if (run.t[i] >= 55 && run.t[i] < 70) {
      const double own = 1.4 * 50.0 * std::abs(sample_at(run.t[i]) - sample_at(run.t[i - 1]));
      EXPECT_LE(std::abs(run.dv[i] - run.dv[i - 1]), own + 5.0 + 1e-9) << "at the return, " << run.t[i];
    }
  }
  EXPECT_GT(biggest_before, 5.0) << "the signal's own steps are bigger than the handover's";
  const auto state_at = [&](double t) { return run.state[static_cast<std::size_t>(std::lround(t / 0.01))]; };
  EXPECT_EQ(state_at(39), BreathState::Following);
  EXPECT_NE(state_at(41), BreathState::Following);
  EXPECT_EQ(state_at(50), BreathState::Model);
  EXPECT_EQ(state_at(67), BreathState::Following) << "within 12 s of the return";
}

TEST(BreathTrace, AMarkerIsReadAlongItsBreathingAxisInhaleUp) {
  const auto dir = std::filesystem::temp_directory_path() / "lungar_trace_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "marker.csv").string();
  const Trace trace = make_trace(60);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.9, 0.4).normalized();  // out of the chest, and up a little
  {
    std::ofstream o(path);
    o << "t_s,x_mm,y_mm,z_mm\n";
    for (const TraceSample& s : trace.samples) {
      const Eigen::Vector3d p = Eigen::Vector3d(10, -150, 900) + s.value * axis;
      o << s.t_s + 100.0 << "," << p.x() << "," << p.y() << "," << p.z() << "\n";
    }
  }
  auto read = read_breath_trace(path);
  ASSERT_TRUE(read) << read.error();
  EXPECT_TRUE(read->marker);
  EXPECT_DOUBLE_EQ(read->samples.front().t_s, 0.0);
  // Inhale up: the projection rises with the trace (up to its mean).
  double c = 0;
  for (std::size_t i = 1; i < read->samples.size(); ++i)
    c += (read->samples[i].value - read->samples[i - 1].value) * (trace.samples[i].value - trace.samples[i - 1].value);
  EXPECT_GT(c, 0.0);
  const std::pair<const char*, const char*> bad[] = {{"time,value\n0,1\n", ":1: header"},
                                                     {"t_s,value\n0,1\n0.1,x\n", ":3: expected finite numbers"},
                                                     {"t_s,value\n0,1\n0,2\n", ":3: t_s: expected times that increase"},
                                                     {"t_s,value\n0,1,2\n", ":2: expected 2 numbers"},
                                                     // milliseconds under a t_s header: it would never lock on
                                                     {"t_s,value\n0,1\n40,2\n80,3\n120,2\n",
                                                      ": t_s: expected times in seconds (a median interval from "
                                                      "0.001 to 2 s), got a median of 40 s"},
                                                     {"t_s,value\n0,1\n0.0002,2\n0.0004,3\n",
                                                      ": t_s: expected times in seconds"},
                                                     {"\"Frame\";\"Time\";\"x\"\n0;0;1\n", ":1: header: expected ExtMarker's"},
                                                     {"\"Frame\";\"Timestamp\";\"x\";\"y\";\"z\"\n0;0;1,5;2;3\n6;100;1;2\n",
                                                      ":3: expected 5 fields"}};
  for (const auto& [text, why] : bad) {
    std::ofstream(path) << text;
    auto r = read_breath_trace(path);
    ASSERT_FALSE(r) << text;
    EXPECT_NE(r.error().find(path + why), std::string::npos) << r.error();
  }
  std::filesystem::remove_all(dir);
}

TEST(BreathTrace, AMarkerWhoseClockStartedLongBeforeTheRecordingIsReadAlongTheSameAxis) {
  // A tracker's clock reads the time since it was switched on, not since the recording began: the axis comes from
  // the recording's first kAxisWindowS whatever the first time reads, and the excursion keeps the breath's depth.
  const Trace trace = make_trace(60);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.9, 0.4).normalized();
  std::vector<double> from_zero, an_hour_on;
  std::vector<Eigen::Vector3d> p;
  for (const TraceSample& s : trace.samples) {
    from_zero.push_back(s.t_s);
    an_hour_on.push_back(s.t_s + 3600.0);
    p.push_back(Eigen::Vector3d(10, -150, 900) + s.value * axis);
  }
  EXPECT_GT(breathing_axis(from_zero, p, kAxisWindowS).dot(axis), 1.0 - 1e-9);
  EXPECT_GT(breathing_axis(an_hour_on, p, kAxisWindowS).dot(axis), 1.0 - 1e-9);
  const std::vector<TraceSample> excursion = marker_excursion(an_hour_on, p);
  ASSERT_EQ(excursion.size(), trace.samples.size());
  EXPECT_DOUBLE_EQ(excursion.front().t_s, 0.0);
  for (std::size_t i = 0; i < excursion.size(); ++i)
    ASSERT_NEAR(excursion[i].value, trace.samples[i].value - trace.samples.front().value, 1e-6) << "sample " << i;
}

TEST(BreathTrace, AMarkerSampledUnevenlyIsReadInhaleUpByTheTimeSpentRisingNotBySamples) {
  // Near-sinusoidal breaths (no skew to go by): inhalation is the shorter phase, a third of each 4 s breath. The
  // tracker loses frames while the chest falls (5 Hz then, 50 Hz while it rises), so the rising phase has five
  // times the samples of the falling one: it is the time spent rising that tells which way is inhalation.
  const Eigen::Vector3d inhale = Eigen::Vector3d(0.1, -0.95, 0.3).normalized();
  std::vector<double> t;
  std::vector<Eigen::Vector3d> p;
  for (double s = 0; s < 60.0;) {
    const double u = std::fmod(s, 4.0) / 4.0, rise = 1.0 / 3.0;
    const double depth =
        u < rise ? 0.5 - 0.5 * std::cos(M_PI * u / rise) : 0.5 + 0.5 * std::cos(M_PI * (u - rise) / (1 - rise));
    t.push_back(s);
    p.push_back(Eigen::Vector3d(10, -150, 900) + 10.0 * depth * inhale);
    s += u < rise ? 0.02 : 0.2;
  }
  EXPECT_GT(breathing_axis(t, p, kAxisWindowS).dot(inhale), 1.0 - 1e-9);
}

TEST(BreathTrace, AnExtMarkerFileDropsAGarbledTimeAndRefusesMany) {
  const auto dir = std::filesystem::temp_directory_path() / "lungar_extmarker_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "marker.csv").string();
  const auto write = [&](int garbled) {  // 300 rows at 10 Hz, decimal commas, `garbled` times gone back
    std::ofstream o(path);
    o << "\"Frame\";\"Timestamp\";\"x\";\"y\";\"z\"\n";
    for (int i = 0; i < 300; ++i) {
      const int ms = i % 50 == 25 && i / 50 < garbled ? 89 : 100 * i;
      o << 6 * i << ";" << ms << ";-290,2;" << (i % 40 < 13 ? i % 40 : 13 - (i % 40 - 13) / 2) << ",5;96,7\n";
    }
    o << "0;0;0;0;0\n";  // as some of the set's files end
  };
  write(1);
  auto one = read_breath_trace(path);
  ASSERT_TRUE(one) << one.error();
  EXPECT_EQ(one->format, "extmarker");
  EXPECT_TRUE(one->marker);
  EXPECT_EQ(one->skipped, 1);
  EXPECT_EQ(one->first_skipped_line, 27);
  EXPECT_EQ(one->samples.size(), 299u) << "the garbled row and the zero row dropped";
  EXPECT_NEAR(one->samples.back().t_s, 29.9, 1e-9) << "ms read as s";
  write(6);  // 2 % of the rows
  auto many = read_breath_trace(path);
  ASSERT_FALSE(many);
  EXPECT_NE(many.error().find(path + ":27: Timestamp: expected times (ms) that increase, got 6 rows"),
            std::string::npos)
      << many.error();
  std::filesystem::remove_all(dir);
}

TEST(BreathTrace, AnExtMarkerRowThatRepeatsTheLastTimeIsDroppedAndCounted) {
  // A repeated time is no new sample, as one gone back is not: two positions at one instant would give the
  // excursion an infinite speed. The row is dropped and counted like a garbled one.
  const auto dir = std::filesystem::temp_directory_path() / "lungar_extmarker_repeat_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "marker.csv").string();
  {
    std::ofstream o(path);
    o << "\"Frame\";\"Timestamp\";\"x\";\"y\";\"z\"\n";
    // 30 s at 10 Hz, as in the file above; row 30 (line 32) repeats row 29's time.
    for (int i = 0; i < 300; ++i) {
      const int ms = 100 * (i == 30 ? i - 1 : i);
      o << 6 * i << ";" << ms << ";-290,2;" << (i % 40 < 13 ? i % 40 : 13 - (i % 40 - 13) / 2) << ",5;96,7\n";
    }
  }
  auto r = read_breath_trace(path);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->skipped, 1);
  EXPECT_EQ(r->first_skipped_line, 32);
  EXPECT_EQ(r->samples.size(), 299u);
  std::filesystem::remove_all(dir);
}

TEST(BreathFollower, AVolumeSourceGivesItsOwnMillilitresNotTheTidalVolumesScale) {
  // A mannequin's lung volume: FRC 2300 mL, breaths of 400 mL at 15 a minute, then two of 700 mL.
  FollowerParams p;
  p.tidal_volume_ml = 500.0;
  p.predict = false;
  p.in_ml = true;
  BreathFollower f(p);
  FollowerParams scaled_params = p;
  scaled_params.in_ml = false;
  BreathFollower scaled(scaled_params);
  double peak = 0, scaled_peak = 0, deep_peak = 0;
  for (double t = 0; t < 40.0; t += 0.02) {
    const double depth = t < 32.0 ? 400.0 : 700.0;
    const double v = 2300.0 + 0.5 * depth * (1.0 - std::cos(2.0 * M_PI * t / 4.0));
    f.add(t, v);
    scaled.add(t, v);
    const FollowerOutput o = f.at(t, 0.0), so = scaled.at(t, 0.0);
    if (t > 20.0 && t < 32.0) {
      ASSERT_EQ(o.state, BreathState::Following) << t;
      peak = std::max(peak, o.dv_ml);
      scaled_peak = std::max(scaled_peak, so.dv_ml);
    }
    if (t > 34.0) deep_peak = std::max(deep_peak, o.dv_ml);
  }
  EXPECT_NEAR(peak, 400.0, 4.0);         // the volume's own excursion over its end-exhale level
  EXPECT_NEAR(scaled_peak, 500.0, 5.0);  // a surrogate's is scaled to V_T
  EXPECT_NEAR(deep_peak, 700.0, 7.0);    // and a deeper breath is deeper at once, no rescaling
}

}  // namespace
}  // namespace lungar::sim
