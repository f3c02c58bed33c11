// Constant-velocity head prediction: exact for constant motion, bounded, and safe on bad timing.
#include <gtest/gtest.h>

#include "platform/runtime/pose_prediction.h"

using lungar::platform::predict_pose;
using lungar::platform::TimedPose;

namespace {
constexpr std::int64_t kMs = 1000000;
TimedPose at(std::int64_t t_ms, Eigen::Vector3d p, double angle_rad) {
  return {t_ms * kMs, p, Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()))};
}
}  // namespace

TEST(PosePrediction, ConstantMotionIsExtrapolatedExactly) {
  // 100 mm/s along x and 1 rad/s about z, sampled 16 ms apart, predicted 20 ms ahead.
  const TimedPose a = at(1000, {0, 0, 0}, 0.100);
  const TimedPose b = at(1016, {1.6, 0, 0}, 0.116);
  const TimedPose p = predict_pose(a, b, 1036 * kMs, 50.0);
  EXPECT_NEAR(p.position_mm.x(), 3.6, 1e-9);
  EXPECT_NEAR(p.orientation.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(0.136, Eigen::Vector3d::UnitZ()))),
              0.0, 1e-9);
}

TEST(PosePrediction, ExtrapolationIsBounded) {
  const TimedPose a = at(0, {0, 0, 0}, 0);
  const TimedPose b = at(10, {10, 0, 0}, 0);
  EXPECT_NEAR(predict_pose(a, b, 1000 * kMs, 30.0).position_mm.x(), 40.0, 1e-9);  // 30 ms ahead at most
  EXPECT_NEAR(predict_pose(a, b, 0, 30.0).position_mm.x(), 10.0, 1e-9);           // never backwards
}

TEST(PosePrediction, BadTimingGivesTheNewestPose) {
  const TimedPose a = at(20, {5, 0, 0}, 0.3);
  const TimedPose b = at(20, {7, 0, 0}, 0.1);
  const TimedPose p = predict_pose(a, b, 40 * kMs, 50.0);
  EXPECT_EQ(p.position_mm, b.position_mm);
  EXPECT_NEAR(p.orientation.angularDistance(b.orientation), 0.0, 1e-12);
}
