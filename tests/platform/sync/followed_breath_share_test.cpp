/// @file followed_breath_share_test.cpp
/// @brief A trainee drawing its instructor's followed breath: the dV between the heartbeats' points, carried a
///        little past the newest, each lung's own; and the model's, reached at a bounded rate, once the points stop.
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/classroom/followed_breath_share.h"
#include "sim/breathing/breath_follower.h"

namespace lungar::classroom {
namespace {

sim::BreathingSample model_at(double t, double dv = 100.0) {
  sim::BreathingSample s;
  s.t_s = t;
  s.v_frc_ml = 2400.0;
  s.dv_ml = dv;
  s.v_ml = 2400.0 + dv;
  return s;
}

TEST(FollowedBreathShare, DrawsTheInstructorsDvBetweenAndJustPastItsPoints) {
  FollowedBreathShare share;
  share.push({1.00, 300.0, {100.0, 200.0}});
  share.push({1.02, 340.0, {120.0, 220.0}});
  sim::BreathingSample s = model_at(1.01);
  share.apply(s);
  EXPECT_TRUE(share.following());
  EXPECT_NEAR(s.dv_ml, 320.0, 1e-9);  // between the two
  EXPECT_NEAR(s.v_ml, 2720.0, 1e-9);
  EXPECT_NEAR(s.lung_dv_ml[0], 110.0, 1e-9);
  EXPECT_NEAR(s.lung_dv_ml[1], 210.0, 1e-9);
  s = model_at(1.03);
  share.apply(s);
  EXPECT_NEAR(s.dv_ml, 360.0, 1e-9);  // a frame past the newest: along their slope
  s = model_at(1.40);
  share.apply(s);
  EXPECT_NEAR(s.dv_ml, 340.0 + 2000.0 * FollowedBreathShare::kMaxAheadS, 1e-6);  // but not far
}

TEST(FollowedBreathShare, APointOutOfOrderIsIgnoredAndALungWithoutItsOwnKeepsItsShare) {
  FollowedBreathShare share;
  share.push({2.00, 300.0});
  share.push({1.50, 900.0});  // late: the instructor's breathing time only goes forward
  sim::BreathingSample s = model_at(2.0);
  share.apply(s);
  EXPECT_NEAR(s.dv_ml, 300.0, 1e-9);
  EXPECT_TRUE(std::isnan(s.lung_dv_ml[0]));
  EXPECT_TRUE(std::isnan(s.lung_dv_ml[1]));
}

TEST(FollowedBreathShare, WhenThePointsStopTheModelTakesOverWithoutAJump) {
  FollowedBreathShare share;
  double t = 0;
  for (; t < 1.0; t += 0.016) {
    share.push({t, 600.0});
    sim::BreathingSample s = model_at(t);
    share.apply(s);
    ASSERT_NEAR(s.dv_ml, 600.0, 1e-9);
  }
  // No more points: stale after kStaleS, then dV goes to the model's 100 mL at most kHandoverMlPerS.
  double last = 600.0;
  bool reached = false;
  for (; t < 3.5; t += 0.016) {
    sim::BreathingSample s = model_at(t);
    share.apply(s);
    EXPECT_LE(std::abs(s.dv_ml - last), sim::kHandoverMlPerS * 0.016 + 1e-9) << t;
    last = s.dv_ml;
    reached = reached || std::abs(s.dv_ml - 100.0) < 1e-9;
  }
  EXPECT_FALSE(share.following());
  EXPECT_TRUE(reached);
}

}  // namespace
}  // namespace lungar::classroom
