// Tests of drivers/pose: the seqlock mailbox under a concurrent writer, the history ring and prediction.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>

#include "drivers/pose/mailbox.h"
#include "drivers/pose/pose_history.h"

using namespace lungar::drivers;

TEST(Mailbox, ReadsAreNeverTornUnderAConcurrentWriter) {
  LatestMailbox<PoseSample> box;
  EXPECT_FALSE(box.read().valid());
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (int k = 1; k <= 200000; ++k) {
      PoseSample s;
      s.flags = kPoseValid;
      s.t_device_ns = k;  // every field carries k: a torn copy would mix two values
      s.position_mm = {double(k), double(k), double(k)};
      s.orientation_wxyz = {double(k), double(k), double(k), double(k)};
      box.publish(s);
    }
    done = true;
  });
  std::int64_t last = 0;
  int reads = 0;
  while (!done || reads == 0) {
    const PoseSample s = box.read();
    ++reads;
    if (!s.valid()) continue;
    const double k = static_cast<double>(s.t_device_ns);
    ASSERT_EQ(s.position_mm[0], k);
    ASSERT_EQ(s.position_mm[2], k);
    ASSERT_EQ(s.orientation_wxyz[3], k);
    ASSERT_GE(s.t_device_ns, last);  // never goes back
    last = s.t_device_ns;
  }
  writer.join();
  EXPECT_EQ(box.read().t_device_ns, 200000);
  EXPECT_EQ(box.published(), 200000u);
}

TEST(History, KeepsTheNewestInOrder) {
  PoseHistory h;
  for (int k = 0; k < 20; ++k) {
    PoseSample s;
    s.t_device_ns = k;
    h.push(s);
  }
  EXPECT_EQ(h.count, PoseHistory::kCapacity);
  EXPECT_EQ(h.newest(0).t_device_ns, 19);
  EXPECT_EQ(h.newest(PoseHistory::kCapacity - 1).t_device_ns, 20 - static_cast<int>(PoseHistory::kCapacity));
}

TEST(History, PredictionExtrapolatesConstantLinearAndAngularVelocity) {
  PoseHistory h;
  const double v_mm_s = 100, w_rad_s = 1.0;
  for (int k = 0; k < 10; ++k) {
    PoseSample s;
    s.flags = kPoseValid;
    s.t_device_ns = s.t_arrival_ns = k * 16'000'000LL;
    const double t = k * 0.016;
    s.position_mm = {v_mm_s * t, 5, 0};
    s.set_orientation(Eigen::Quaterniond(Eigen::AngleAxisd(w_rad_s * t, Eigen::Vector3d::UnitZ())));
    h.push(s);
  }
  const std::int64_t now = 9 * 16'000'000LL;
  const PoseSample p = predict(h, now + 20'000'000, 50'000'000);
  const double t = 9 * 0.016 + 0.020;
  EXPECT_TRUE(p.flags & kPosePredicted);
  EXPECT_NEAR(p.position_mm[0], v_mm_s * t, 1e-6);
  EXPECT_NEAR(p.position_mm[1], 5, 1e-9);
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(w_rad_s * t, Eigen::Vector3d::UnitZ()));
  EXPECT_LT(p.orientation().angularDistance(turned), 1e-9);
  // The lead is capped.
  const PoseSample capped = predict(h, now + 1'000'000'000, 50'000'000);
  EXPECT_NEAR(capped.position_mm[0], v_mm_s * (9 * 0.016 + 0.050), 1e-6);
  // One sample: nothing to extrapolate from.
  PoseHistory one;
  one.push(h.newest());
  EXPECT_EQ(predict(one, now + 20'000'000, 50'000'000).position_mm, h.newest().position_mm);
  EXPECT_FALSE(predict(PoseHistory{}, 0, 0).valid());
}
