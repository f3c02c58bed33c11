/// @file xr_lifecycle_test.cpp
/// @brief The session state machine's decisions, including the branches Monado does not take in CI: the runtime
/// stopping the session on its own, the headset lost (LOSS_PENDING), the runtime restarting (instance loss).
#include <gtest/gtest.h>

#include "platform/openxr/xr_lifecycle.h"

namespace lungar::platform::openxr {
namespace {

TEST(XrLifecycle, FollowsOpenXrsOrderFromReadyToExiting) {
  Lifecycle l;
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_IDLE), LifecycleAction::None);
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_READY), LifecycleAction::BeginSession);
  EXPECT_NE(l.last_line().find("READY"), std::string::npos);
  l.on_begun();
  EXPECT_TRUE(l.running());
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_SYNCHRONIZED), LifecycleAction::None);
  EXPECT_FALSE(l.visible());
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_VISIBLE), LifecycleAction::None);
  EXPECT_TRUE(l.visible());
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_FOCUSED), LifecycleAction::None);
  EXPECT_TRUE(l.visible());
  l.on_exit_requested();
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_STOPPING), LifecycleAction::EndSession);
  EXPECT_NE(l.last_line().find("lungar asked to exit"), std::string::npos) << l.last_line();
  l.on_ended();
  EXPECT_FALSE(l.running());
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_IDLE), LifecycleAction::None);
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_EXITING), LifecycleAction::DestroySession);
  for (auto s : {XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY, XR_SESSION_STATE_SYNCHRONIZED,
                 XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_FOCUSED, XR_SESSION_STATE_STOPPING,
                 XR_SESSION_STATE_EXITING}) {
    EXPECT_TRUE(l.reached(s)) << to_string(s);
  }
  EXPECT_FALSE(l.reached(XR_SESSION_STATE_LOSS_PENDING));
}

TEST(XrLifecycle, RuntimeStoppingTheSessionSaysSo) {
  Lifecycle l;
  l.on_session_state(XR_SESSION_STATE_READY);
  l.on_begun();
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_STOPPING), LifecycleAction::EndSession);
  EXPECT_NE(l.last_line().find("the runtime asked"), std::string::npos) << l.last_line();
}

TEST(XrLifecycle, LossPendingReconnectsTheSessionWithOneLine) {
  Lifecycle l;
  l.on_session_state(XR_SESSION_STATE_READY);
  l.on_begun();
  l.on_session_state(XR_SESSION_STATE_FOCUSED);
  EXPECT_EQ(l.on_session_state(XR_SESSION_STATE_LOSS_PENDING), LifecycleAction::ReconnectSession);
  EXPECT_NE(l.last_line().find("LOSS_PENDING"), std::string::npos);
  EXPECT_NE(l.last_line().find("reconnecting"), std::string::npos);
  EXPECT_EQ(l.last_line().find('\n'), std::string::npos);
}

TEST(XrLifecycle, InstanceLossMeansTheRuntimeRestarts) {
  Lifecycle l;
  EXPECT_EQ(l.on_instance_loss_pending(), LifecycleAction::ReconnectInstance);
  EXPECT_NE(l.last_line().find("instance loss pending"), std::string::npos);
  EXPECT_NE(l.last_line().find("restarting"), std::string::npos);
}

TEST(XrLifecycle, NamesEveryState) {
  EXPECT_STREQ(to_string(XR_SESSION_STATE_FOCUSED), "FOCUSED");
  EXPECT_STREQ(to_string(XR_SESSION_STATE_LOSS_PENDING), "LOSS_PENDING");
  EXPECT_STREQ(to_string(XR_SESSION_STATE_MAX_ENUM), "UNKNOWN");
}

}  // namespace
}  // namespace lungar::platform::openxr
