// The frame statistics: percentiles in constant memory within their stated error of the exact nearest rank, and
// the frame keys of the stats JSON with the values recorded.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "config/base/log_histogram.h"
#include "platform/runtime/frame_stats.h"

using lungar::LogHistogram;
using lungar::platform::FrameStats;

namespace {

double exact_percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const double rank = std::max(1.0, std::ceil(p / 100.0 * static_cast<double>(v.size())));
  return v[static_cast<std::size_t>(rank) - 1];
}

}  // namespace

TEST(LogHistogram, PercentilesAreWithinTheStatedErrorOfTheNearestRank) {
  std::mt19937 rng(7);
  std::lognormal_distribution<double> frame_ms(std::log(12.0), 0.4);  // a skewed, frame-time-like spread
  LogHistogram h;
  std::vector<double> all;
  for (int k = 0; k < 200000; ++k) {
    const double v = frame_ms(rng);
    h.add(v);
    all.push_back(v);
  }
  for (double p : {1.0, 50.0, 90.0, 99.0, 99.9}) {
    const double exact = exact_percentile(all, p);
    EXPECT_NEAR(h.percentile(p), exact, exact * LogHistogram::kRelativeError) << "p" << p;
  }
  EXPECT_EQ(h.count(), all.size());
  EXPECT_DOUBLE_EQ(h.min(), *std::min_element(all.begin(), all.end()));
  EXPECT_DOUBLE_EQ(h.percentile(100), *std::max_element(all.begin(), all.end()));
}

TEST(LogHistogram, OutOfRangeAndEmpty) {
  LogHistogram h;
  EXPECT_EQ(h.percentile(50), 0.0);
  h.add(1e-6);     // below the range: the first bucket, reported as the exact minimum
  h.add(1e7);      // above: the last bucket, the exact maximum
  h.add(std::nan(""));  // not counted
  EXPECT_EQ(h.count(), 2u);
  EXPECT_DOUBLE_EQ(h.percentile(1), 1e-6);
  EXPECT_DOUBLE_EQ(h.percentile(100), 1e7);
}

TEST(FrameStats, MemoryDoesNotGrowWithTheFrameCount) {
  // An 8-hour day at 90 Hz is 2.6 million frames; the statistics are a fixed-size object (no heap at all).
  static_assert(sizeof(FrameStats) < 64 * 1024);
  FrameStats stats;
  for (int k = 0; k < 3'000'000; ++k) stats.record(11.0 + (k % 7), 5.0, 250.0, {0.0, 0.0, -1.0});
  EXPECT_EQ(stats.frames(), 3'000'000u);
  EXPECT_NEAR(stats.frame_ms().percentile(50), 14.0, 14.0 * LogHistogram::kRelativeError);
}

TEST(FrameStats, JsonCarriesTheFrameKeysWithRecordedValues) {
  FrameStats stats;
  for (int k = 0; k < 10; ++k) stats.record(20.0 + k, k % 2 ? 4.0 : -1.0, 100.0 * k - 50.0, {0.0, 0.1 * k, -1.0});
  const auto j = stats.to_json();
  for (const char* key : {"frames", "fps_median", "frame_ms_p50", "frame_ms_p99", "frame_ms_mean", "pose_age_ms_p50",
                          "pose_age_ms_p99", "volume_ml_min", "volume_ml_max", "gravity_lung_first",
                          "gravity_lung_last"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  const double tol = LogHistogram::kRelativeError;
  EXPECT_EQ(j["frames"], 10);
  EXPECT_NEAR(j["frame_ms_p50"].get<double>(), 24.0, 24.0 * tol);
  EXPECT_NEAR(j["fps_median"].get<double>(), 1000.0 / 24.0, 1000.0 / 24.0 * tol * 1.01);
  EXPECT_NEAR(j["frame_ms_p99"].get<double>(), 29.0, 29.0 * tol);
  EXPECT_DOUBLE_EQ(j["frame_ms_mean"].get<double>(), 24.5);
  EXPECT_NEAR(j["pose_age_ms_p50"].get<double>(), 4.0, 4.0 * tol);  // frames without a pose are not counted
  EXPECT_DOUBLE_EQ(j["volume_ml_min"].get<double>(), -50.0);
  EXPECT_DOUBLE_EQ(j["volume_ml_max"].get<double>(), 850.0);
  EXPECT_DOUBLE_EQ(j["gravity_lung_first"][1].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["gravity_lung_last"][1].get<double>(), 0.9);
}

TEST(FrameStats, PerLungKeysFollowEachLungsOwnSwing) {
  FrameStats stats;
  EXPECT_FALSE(stats.to_json().contains("per_lung")) << "no lungs named, no per-lung keys";
  stats.name_lungs({"left", "right"});
  for (int k = 0; k <= 10; ++k) {
    const double dv = 50.0 * k;  // 0 .. 500 mL
    const std::array<double, 2> lungs{0.58 * dv, 0.42 * dv};
    const std::array<double, 2> rest{1800.0, 2100.0 - 20.0 * k};  // the right lung collapsing
    stats.record(16.0, 2.0, dv, {1.0, 0.0, 0.0});
    stats.record_lungs(lungs, rest);
  }
  const auto j = stats.to_json();
  ASSERT_TRUE(j.contains("per_lung"));
  ASSERT_EQ(j["per_lung"].size(), 2u);
  EXPECT_EQ(j["per_lung"][0]["name"], "left");
  EXPECT_DOUBLE_EQ(j["per_lung"][0]["tidal_ml"].get<double>(), 290.0);
  EXPECT_DOUBLE_EQ(j["per_lung"][0]["volume_ml_min"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["per_lung"][1]["volume_ml_max"].get<double>(), 210.0);
  EXPECT_DOUBLE_EQ(j["per_lung"][1]["tidal_ml"].get<double>(), 210.0);
  EXPECT_DOUBLE_EQ(j["per_lung"][0]["rest_volume_ml"].get<double>(), 1800.0);
  EXPECT_DOUBLE_EQ(j["per_lung"][1]["rest_volume_ml"].get<double>(), 1900.0) << "the last frame's";
}

TEST(FrameStats, VentralShareIsTheLastFramesPosture) {
  FrameStats stats;
  EXPECT_FALSE(stats.to_json().contains("ventral_share")) << "nothing recorded, no key";
  stats.record_ventral_share(0.38);
  stats.record_ventral_share(0.44);  // turned prone
  EXPECT_DOUBLE_EQ(stats.to_json()["ventral_share"].get<double>(), 0.44);
}
