/// @file breath_flags_test.cpp
/// @brief The follower's flags on traces a trainer would recognise: quiet breathing flags nothing; a sigh (a breath
///        two and a half times as deep) and a long pause are irregular for that breath alone; breath-holding that
///        lasts 15 s is one apnoea, flagged from 10 s after the last breath; a signal lost for 15 s is no apnoea.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/breathing/breath_follower.h"

namespace lungar::sim {
namespace {

/// Quiet breathing at 15/min (4 s, I:E 1:2), 10 units deep, sampled at 40 Hz; `depth(n)` scales breath n,
/// `hold_from`..`hold_to` holds the chest still at end-exhale (signal present), `gap_from`..`gap_to` loses it.
struct Script {
  double seconds = 60;
  std::vector<std::pair<int, double>> deeper;  ///< breath n, depth factor
  double hold_from = -1, hold_to = -1, gap_from = -1, gap_to = -1, pause_after = -1;
  double talk_from = -1, talk_to = -1;  ///< talking instead of breathing: 3 Hz, 4 units peak to peak
};

struct Flags {
  std::vector<double> t;
  std::vector<FollowerOutput> out;
  int irregular = 0, apnoeas = 0, breaths = 0;
};

Flags run(const Script& s, const FollowerParams& p = {}) {
  BreathFollower f(p);
  Flags r;
  double start = 0;
  int n = 0;
  for (int k = 0; k * 0.025 <= s.seconds; ++k) {
    const double t = k * 0.025;
    double period = 4.0;
    if (n == 9 && s.pause_after > 0) period = 4.0 + s.pause_after;  // breath 9 followed by a pause
    while (t >= start + period) {
      start += period;
      ++n;
      period = n == 9 && s.pause_after > 0 ? 4.0 + s.pause_after : 4.0;
    }
    double depth = 1.0;
    for (const auto& [which, d] : s.deeper)
      if (which == n) depth = d;
    const double u = std::min((t - start) / 4.0, 1.0);
    double v = 10.0 * depth * (u < 1.0 / 3 ? 0.5 - 0.5 * std::cos(3 * M_PI * u) : std::exp(-6.0 * (u - 1.0 / 3)));
    if (t >= s.hold_from && t < s.hold_to) v = 0.0;
    if (t >= s.talk_from && t < s.talk_to) v = 3.0 + 2.0 * std::sin(2 * M_PI * 3.0 * t);
    if (!(t >= s.gap_from && t < s.gap_to)) f.add(t, v);
    r.t.push_back(t);
    r.out.push_back(f.at(t, 0.0));
  }
  r.irregular = f.irregular_breaths();
  r.apnoeas = f.apnoeas();
  r.breaths = f.breaths();
  return r;
}

int flagged(const Flags& f, bool FollowerOutput::*flag) {
  int n = 0;
  for (const FollowerOutput& o : f.out) n += o.*flag ? 1 : 0;
  return n;
}

TEST(BreathFlags, QuietBreathingFlagsNothing) {
  const Flags f = run({});
  EXPECT_EQ(f.irregular, 0);
  EXPECT_EQ(f.apnoeas, 0);
  EXPECT_EQ(flagged(f, &FollowerOutput::apnoea), 0);
}

TEST(BreathFlags, ASighIsIrregularForThatBreathOnly) {
  Script s;
  s.deeper = {{8, 2.5}};
  const Flags f = run(s);
  EXPECT_EQ(f.irregular, 1);
  // Flagged from the sigh's peak (breath 8 peaks at 8 * 4 + 4/3 s) until the next breath's peak, 4 s later.
  double first = -1, last = -1;
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    if (!f.out[i].irregular) continue;
    if (first < 0) first = f.t[i];
    last = f.t[i];
  }
  EXPECT_NEAR(first, 8 * 4 + 4.0 / 3, 0.6);
  EXPECT_NEAR(last - first, 4.0, 0.6);
  EXPECT_EQ(run({}).irregular, 0) << "the same trace without the sigh";
}

TEST(BreathFlags, ASighIsIrregularAsSoonAsThreeBreathsSetTheDepth) {
  // The first breath counted is breath 1 (breath 0 has no trough before it): breath 4 is the first judged against
  // a median of three depths. Its period is the others', so only its depth can flag it.
  Script s;
  s.deeper = {{4, 2.5}};
  EXPECT_EQ(run(s).irregular, 1);
}

TEST(BreathFlags, ABreathShallowerThanTheDepthShareAskedForIsNoBreathFromTheSecondOn) {
  // The default share (0.3) is the turns' own hysteresis, so a turn that shallow is never found; a caller asking
  // for 0.6 gets a half-deep breath right after the first one flagged and not counted.
  FollowerParams p;
  p.min_depth_share = 0.6;
  const Flags quiet = run({}, p);
  EXPECT_EQ(quiet.irregular, 0);
  Script s;
  s.deeper = {{2, 0.5}};
  const Flags f = run(s, p);
  EXPECT_EQ(f.irregular, 1);
  EXPECT_EQ(f.breaths, quiet.breaths - 1);
}

TEST(BreathFlags, APauseBetweenBreathsIsIrregular) {
  Script s;
  s.pause_after = 4.0;  // one 8-s breath: twice the median period
  EXPECT_EQ(run(s).irregular, 1);
}

TEST(BreathFlags, TalkingIsFlaggedAndDoesNotRescaleTheBreathsAfterIt) {
  Script s;
  s.talk_from = 20.0;  // 20 s of talking: 60 turns, each a fifth of a breath's time and 0.4 of its depth
  s.talk_to = 40.0;
  const Flags f = run(s);
  double during = 0, after = 0;
  bool flagged = false;
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    if (f.t[i] >= 22.0 && f.t[i] < 40.0) flagged = flagged || f.out[i].irregular;
    if (f.t[i] >= 22.0 && f.t[i] < 40.0) during = std::max(during, f.out[i].dv_ml);
    if (f.t[i] >= 44.0 && f.t[i] < 56.0) after = std::max(after, f.out[i].dv_ml);
  }
  EXPECT_TRUE(flagged);
  EXPECT_GT(during, 100.0) << "the chest moves while talking, and so do the lungs";
  EXPECT_LT(during, 400.0) << "but by less than a breath";
  // A breath after the talking is a breath: V_T, not V_T scaled by the talking's smaller turns (1,150 mL).
  EXPECT_NEAR(after, 500.0, 75.0);
}

TEST(BreathFlags, HoldingTheBreathFifteenSecondsIsOneApnoeaFromTenSecondsOn) {
  Script s;
  s.hold_from = 30.0;  // end of breath 7; its peak was at 28 + 4/3 s
  s.hold_to = 45.0;
  const Flags f = run(s);
  EXPECT_EQ(f.apnoeas, 1);
  double first = -1;
  for (std::size_t i = 0; i < f.t.size() && first < 0; ++i)
    if (f.out[i].apnoea) first = f.t[i];
  EXPECT_NEAR(first, 28 + 4.0 / 3 + 10.0, 0.1) << "10 s after the last breath's peak";
  EXPECT_FALSE(f.out.back().apnoea) << "breathing again";
}

TEST(BreathFlags, ALostSignalIsNoApnoea) {
  Script s;
  s.gap_from = 30.0;
  s.gap_to = 45.0;
  const Flags f = run(s);
  EXPECT_EQ(f.apnoeas, 0);
  EXPECT_EQ(flagged(f, &FollowerOutput::apnoea), 0);
}

}  // namespace
}  // namespace lungar::sim
