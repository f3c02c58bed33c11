/// @file breath_clarity_test.cpp
/// @brief The clearest of several markers: on a real session with talking and irregular breathing (ExtMarker
///        `LT`, tests/data/breath/) the abdomen, not the upper chest whose recording fails the breath figures;
///        quiet breathing is nearly all in the band, talking and a slow sway nearly none.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/breathing/breath_clarity.h"

namespace lungar::sim {
namespace {

BreathTrace wave(double hz, double seconds = 60.0) {
  BreathTrace t;
  for (int i = 0; i * 0.04 <= seconds; ++i) t.samples.push_back({i * 0.04, 5.0 * std::sin(2 * M_PI * hz * i * 0.04)});
  return t;
}

/// 60 s at 25 Hz on an exact time grid (i / 25 s), so that a tone of k / 60 Hz fills one bin of the 10 Hz
/// resampling's spectrum: the sum of a breath and a second tone, each 5 units, the breath starting at `phase`.
BreathTrace tones(double breath_hz, double phase, double other_hz = 0.0) {
  BreathTrace t;
  for (int i = 0; i <= 1500; ++i) {
    const double s = i / 25.0;
    t.samples.push_back({s, 5.0 * std::sin(2 * M_PI * breath_hz * s + phase) +
                                (other_hz > 0 ? 5.0 * std::sin(2 * M_PI * other_hz * s) : 0.0)});
  }
  return t;
}

TEST(BreathClarity, BreathingIsInTheBandTalkingAndSwayAreNot) {
  EXPECT_GT(breathing_clarity(wave(0.25)), 0.9) << "15 a minute";
  EXPECT_LT(breathing_clarity(wave(3.0)), 0.1) << "talking's 3 Hz";
  EXPECT_LT(breathing_clarity(wave(0.05)), 0.1) << "a sway of 3 a minute";
  EXPECT_EQ(clearest_breathing({wave(3.0), wave(0.05), wave(0.3), wave(1.5)}), 2u);
}

TEST(BreathClarity, ATremorUpToHalfTheSamplingRateCountsAgainstTheBreath) {
  // The spectrum runs to 5 Hz, half the 10 Hz it is resampled at: a 4 Hz tremor as strong as the breath takes
  // its share of the power as a 2 Hz one does (the resampling's interpolation softens 4 Hz a little).
  const double with_2hz = breathing_clarity(tones(0.25, 0.0, 2.0)), with_4hz = breathing_clarity(tones(0.25, 0.0, 4.0));
  EXPECT_NEAR(with_2hz, 0.5, 0.05);
  EXPECT_NEAR(with_4hz, with_2hz, 0.05);
}

TEST(BreathClarity, ASteadyBreathHoldsAllItsPowerInTheBandWhateverPhaseTheTraceStartsIn) {
  // 15 a minute over exactly 60 s: one bin of the spectrum, every sample in the sum. A trace that starts at the
  // top of a breath rather than halfway up has the same spectrum, bar the phase.
  for (const double phase : {0.0, 0.5 * M_PI, M_PI, 1.5 * M_PI})
    EXPECT_GT(breathing_clarity(tones(0.25, phase)), 1.0 - 1e-4) << "phase " << phase;
}

TEST(BreathClarity, OnARealSessionTheAbdomenIsClearerThanTheTalkingUpperChest) {
  const std::string dir = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/breath/extmarker/201205101536-";
  std::vector<BreathTrace> session;
  for (const char* marker : {"UCC-1-LT-142-6.csv", "UAC-1-LT-142-6.csv", "LAC-1-LT-142-6.csv"}) {
    auto t = read_breath_trace(dir + marker);
    ASSERT_TRUE(t) << t.error();
    session.push_back(t.take());
  }
  std::vector<double> clarity;
  EXPECT_EQ(clearest_breathing(session, &clarity), 2u) << "the lower abdomen";
  ASSERT_EQ(clarity.size(), 3u);
  EXPECT_LT(clarity[0], clarity[1]);
  EXPECT_LT(clarity[0], clarity[2]);
}

}  // namespace
}  // namespace lungar::sim
