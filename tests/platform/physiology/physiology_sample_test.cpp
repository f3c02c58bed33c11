/// @file physiology_sample_test.cpp
/// @brief What lungar takes from AMM's and OpenICE's waveforms and what it drops (by reason), and the
///        `--breath amm|openice` specs it reads, without a network.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "drivers/breath/physiology/physiology_sample.h"
#include "drivers/breath/physiology/physiology_spec.h"

namespace lungar::platform {
namespace {

using breath::physiology::Channel;
using breath::physiology::Drop;
using breath::physiology::parse_physiology_spec;
using breath::physiology::PhysiologySpec;
using breath::physiology::Quantity;
using breath::physiology::Sample;

struct Seen {
  std::vector<Sample> kept;
  std::vector<Drop> dropped;
};

std::optional<Sample> amm(breath::physiology::AmmChecks& c, Seen& seen, const char* name, const char* unit, long t_ms,
                          double v) {
  auto s = c.check(name, unit, t_ms, v, [&](Drop d) { seen.dropped.push_back(d); });
  if (s) seen.kept.push_back(*s);
  return s;
}

TEST(AmmChecks, TakesTheLungVolumesInMillilitresAndIgnoresOtherNodes) {
  breath::physiology::AmmChecks c;
  Seen seen;
  auto total = amm(c, seen, "Respiratory_LungTotal_Volume", "L", 1500, 2.4);
  ASSERT_TRUE(total);
  EXPECT_EQ(total->channel, Channel::breath);
  EXPECT_DOUBLE_EQ(total->value, 2400.0);
  EXPECT_DOUBLE_EQ(total->t_s, 1.5);
  auto left = amm(c, seen, "Respiratory_LeftLung_Volume", "mL", 1500, 1100.0);
  ASSERT_TRUE(left);
  EXPECT_EQ(left->channel, Channel::left_lung);
  EXPECT_EQ(amm(c, seen, "Respiratory_RightLung_Volume", "mL", 1500, 1300.0)->channel, Channel::right_lung);
  EXPECT_FALSE(amm(c, seen, "Cardiovascular_HeartRate", "1/min", 1500, 72.0));
  EXPECT_TRUE(seen.dropped.empty());  // a node lungar does not follow is not a bad sample
}

TEST(AmmChecks, DropsEachBadSampleUnderItsReason) {
  breath::physiology::AmmChecks c;
  Seen seen;
  const char* total = "Respiratory_LungTotal_Volume";
  ASSERT_TRUE(amm(c, seen, total, "mL", 1000, 2400.0));
  EXPECT_FALSE(amm(c, seen, total, "mL", 1020, std::nan("")));
  EXPECT_FALSE(amm(c, seen, total, "mL", 1020, -5.0));
  EXPECT_FALSE(amm(c, seen, total, "mmHg", 1020, 2400.0));
  EXPECT_FALSE(amm(c, seen, total, "mL", 900, 2400.0));    // back in time
  EXPECT_FALSE(amm(c, seen, total, "mL", 1020, 3400.0));   // a litre in 20 ms: 50 L/s
  EXPECT_TRUE(amm(c, seen, total, "mL", 1040, 2410.0));    // the breath goes on from the last good sample
  EXPECT_EQ(seen.dropped, (std::vector<Drop>{Drop::not_finite, Drop::negative_volume, Drop::unit, Drop::time,
                                             Drop::rate}));
  // Each lung keeps its own time: the left lung at 900 ms after the total at 1040 ms is not back in time.
  EXPECT_TRUE(amm(c, seen, "Respiratory_LeftLung_Volume", "mL", 900, 1100.0));
}

TEST(OpenIceChecks, SpacesAnArraysSamplesByItsFrequencyEndingAtItsTime) {
  breath::physiology::OpenIceChecks c(Quantity::flow_ml_per_s);
  Seen seen;
  const std::vector<float> v = {60.0f, 120.0f, -60.0f};  // L/min; expiration negative
  c.check({"MDC_FLOW_AWAY", "MDC_DIM_L_PER_MIN", 50, v, 10.0}, [&](const Sample& s) { seen.kept.push_back(s); },
          [&](Drop d) { seen.dropped.push_back(d); });
  ASSERT_EQ(seen.kept.size(), 3u);
  EXPECT_NEAR(seen.kept[0].t_s, 9.96, 1e-12);
  EXPECT_NEAR(seen.kept[2].t_s, 10.0, 1e-12);
  EXPECT_NEAR(seen.kept[1].value, 2000.0, 1e-9);  // 120 L/min = 2000 mL/s
  EXPECT_NEAR(seen.kept[2].value, -1000.0, 1e-9);
  // Another metric: ignored, not dropped.
  c.check({"MDC_PRESS_AWAY", "MDC_DIM_CM_H2O", 50, v, 10.5}, [&](const Sample& s) { seen.kept.push_back(s); },
          [&](Drop d) { seen.dropped.push_back(d); });
  EXPECT_EQ(seen.kept.size(), 3u);
  EXPECT_TRUE(seen.dropped.empty());
}

TEST(OpenIceChecks, DropsBadValuesOneByOneAndBadArraysWhole) {
  breath::physiology::OpenIceChecks c(Quantity::volume_ml);
  Seen seen;
  const auto keep = [&](const Sample& s) { seen.kept.push_back(s); };
  const auto drop = [&](Drop d) { seen.dropped.push_back(d); };
  const std::vector<float> bad_values = {100.0f, std::nanf(""), -5.0f, 300.0f};
  c.check({"MDC_VOL_AWAY_TIDAL", "MDC_DIM_MILLI_L", 50, bad_values, 1.0}, keep, drop);
  EXPECT_EQ(seen.kept.size(), 2u);  // 100 and 300 stay
  const std::vector<float> good = {100.0f, 200.0f};
  c.check({"MDC_VOL_AWAY_TIDAL", "MDC_DIM_CM_H2O", 50, good, 2.0}, keep, drop);     // a pressure unit
  c.check({"MDC_VOL_AWAY_TIDAL", "MDC_DIM_MILLI_L", 0, good, 2.0}, keep, drop);     // 0 Hz
  c.check({"MDC_VOL_AWAY_TIDAL", "MDC_DIM_MILLI_L", 50000, good, 2.0}, keep, drop); // 50 kHz
  c.check({"MDC_VOL_AWAY_TIDAL", "MDC_DIM_MILLI_L", 50, good, 0.5}, keep, drop);    // before the last array
  EXPECT_EQ(seen.kept.size(), 2u);
  EXPECT_EQ(seen.dropped, (std::vector<Drop>{Drop::not_finite, Drop::negative_volume, Drop::unit, Drop::rate,
                                             Drop::rate, Drop::time}));
  c.check({"MDC_VOL_AWAY_TIDAL", "MDC_DIM_L", 50, good, 2.0}, keep, drop);  // litres
  ASSERT_EQ(seen.kept.size(), 4u);
  EXPECT_DOUBLE_EQ(seen.kept[3].value, 200000.0);
}

TEST(PhysiologySpec, ReadsTheSourceTheMetricAndTheDomain) {
  auto amm = parse_physiology_spec("amm");
  ASSERT_TRUE(amm && *amm);
  EXPECT_EQ((*amm)->source, BreathSource::Amm);
  EXPECT_EQ((*amm)->domain, 0u);
  auto flow = parse_physiology_spec("openice:flow@7");
  ASSERT_TRUE(flow && *flow);
  EXPECT_EQ((*flow)->source, BreathSource::OpenIce);
  EXPECT_EQ((*flow)->quantity, Quantity::flow_ml_per_s);
  EXPECT_EQ((*flow)->domain, 7u);
  auto file = parse_physiology_spec("traces/amm@home.csv");  // a file, not a source
  ASSERT_TRUE(file);
  EXPECT_FALSE(*file);
  for (const char* bad : {"amm:volume", "openice:temperature", "openice@233", "amm@", "amm@x"}) {
    auto r = parse_physiology_spec(bad);
    ASSERT_FALSE(r) << bad;
    EXPECT_NE(r.error().find(std::string("'") + bad + "'"), std::string::npos) << r.error();
  }
}

}  // namespace
}  // namespace lungar::platform
