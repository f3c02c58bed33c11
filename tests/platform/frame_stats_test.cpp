// The stats JSON: its keys (the runtime's contract) and percentiles computed from what was recorded.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "platform/runtime/frame_stats.h"

using lungar::platform::FrameStats;

TEST(FrameStats, PercentilesUseNearestRank) {
  std::vector<double> v;
  for (int k = 100; k >= 1; --k) v.push_back(k);
  EXPECT_DOUBLE_EQ(FrameStats::percentile(v, 50), 50.0);
  EXPECT_DOUBLE_EQ(FrameStats::percentile(v, 99), 99.0);
  EXPECT_DOUBLE_EQ(FrameStats::percentile(v, 100), 100.0);
  EXPECT_DOUBLE_EQ(FrameStats::percentile({}, 50), 0.0);
}

TEST(FrameStats, JsonCarriesEveryContractKeyWithRecordedValues) {
  FrameStats stats;
  for (int k = 0; k < 10; ++k) stats.record(20.0 + k, k % 2 ? 4.0 : -1.0, 100.0 * k - 50.0);
  lungar::platform::TrackerCounters t{1234, 3, 1, 62.5, "streaming"};
  const auto j = nlohmann::json::parse(stats.to_json("stereo", "gpu", 400000, t, 1.5));
  for (const char* key : {"frames", "fps_median", "frame_ms_p50", "frame_ms_p99", "nodes", "view", "deform",
                          "tracker_reports", "tracker_malformed", "tracker_reconnects", "tracker_rate_hz",
                          "pose_age_ms_p50", "pose_age_ms_p99", "volume_ml_min", "volume_ml_max"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["frames"], 10);
  EXPECT_DOUBLE_EQ(j["frame_ms_p50"].get<double>(), 24.0);
  EXPECT_DOUBLE_EQ(j["fps_median"].get<double>(), 1000.0 / 24.0);
  EXPECT_DOUBLE_EQ(j["frame_ms_p99"].get<double>(), 29.0);
  EXPECT_DOUBLE_EQ(j["pose_age_ms_p50"].get<double>(), 4.0);  // frames without a pose are not counted
  EXPECT_DOUBLE_EQ(j["volume_ml_min"].get<double>(), -50.0);
  EXPECT_DOUBLE_EQ(j["volume_ml_max"].get<double>(), 850.0);
  EXPECT_EQ(j["tracker_malformed"], 3);
  EXPECT_EQ(j["view"], "stereo");
}
