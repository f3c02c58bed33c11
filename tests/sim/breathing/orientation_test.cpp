// Tests of sim/breathing/orientation: named poses put gravity where anatomy says, and turns are smooth.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/breathing/orientation.h"

using namespace lungar::sim;
using Eigen::Vector3d;

namespace {

void expect_near(const Vector3d& a, const Vector3d& b, double tol) {
  EXPECT_LT((a - b).norm(), tol) << "got (" << a.transpose() << "), expected (" << b.transpose() << ")";
}

}  // namespace

// Lung frame LPS: +x left, +y posterior, +z superior.
TEST(Orientation, GravityPointsWhereThePatientLies) {
  expect_near(gravity_in_lung_frame(pose_rotation(Pose::Upright)), Vector3d(0, 0, -1), 1e-12);      // feet
  expect_near(gravity_in_lung_frame(pose_rotation(Pose::Supine)), Vector3d(0, 1, 0), 1e-12);        // back
  expect_near(gravity_in_lung_frame(pose_rotation(Pose::Prone)), Vector3d(0, -1, 0), 1e-12);        // front
  expect_near(gravity_in_lung_frame(pose_rotation(Pose::LeftLateral)), Vector3d(1, 0, 0), 1e-12);   // left side
  expect_near(gravity_in_lung_frame(pose_rotation(Pose::RightLateral)), Vector3d(-1, 0, 0), 1e-12); // right side
  EXPECT_NEAR(tilt_from_upright_deg(pose_rotation(Pose::Supine)), 90.0, 1e-9);
  EXPECT_NEAR(tilt_from_upright_deg(pose_rotation(Pose::Upright)), 0.0, 1e-9);
}

TEST(Orientation, PoseNamesRoundTrip) {
  for (Pose p : kAllPoses) EXPECT_EQ(pose_from_name(to_string(p)), p);
  EXPECT_FALSE(pose_from_name("sitting"));
}

TEST(Orientation, ATurnEasesFromStartToTarget) {
  auto c = OrientationTrack::create(pose_rotation(Pose::Upright), {{20.0, 5.0, pose_rotation(Pose::Supine)}});
  ASSERT_TRUE(c) << c.error();
  const OrientationTrack& track = *c;
  EXPECT_NEAR(tilt_from_upright_deg(track.at(0.0)), 0.0, 1e-9);
  EXPECT_NEAR(tilt_from_upright_deg(track.at(20.0)), 0.0, 1e-9);
  EXPECT_NEAR(tilt_from_upright_deg(track.at(22.5)), 45.0, 1e-6);  // smoothstep(1/2) = 1/2
  EXPECT_NEAR(tilt_from_upright_deg(track.at(25.0)), 90.0, 1e-9);
  EXPECT_NEAR(tilt_from_upright_deg(track.at(99.0)), 90.0, 1e-9);
  // Monotone, no step larger than the fastest point of the ease (1.5 x 90 deg / 5 s) allows.
  double prev = 0;
  for (double t = 20.0; t <= 25.0; t += 0.01) {
    const double a = tilt_from_upright_deg(track.at(t));
    EXPECT_GE(a, prev - 1e-9);
    EXPECT_LE(a - prev, 1.5 * 90.0 / 5.0 * 0.01 + 1e-9);
    prev = a;
  }
  EXPECT_NEAR(track.at(22.5).norm(), 1.0, 1e-12);
}

TEST(Orientation, TurnsChainFromTheLastTarget) {
  auto c = OrientationTrack::create(pose_rotation(Pose::Upright), {{30.0, 2.0, pose_rotation(Pose::LeftLateral)},
                                                                   {10.0, 5.0, pose_rotation(Pose::Supine)}});
  ASSERT_TRUE(c) << c.error();
  // Sorted by start: supine first, then from supine to the left side.
  expect_near(gravity_in_lung_frame(c->at(20.0)), Vector3d(0, 1, 0), 1e-9);
  const Vector3d mid = gravity_in_lung_frame(c->at(31.0));
  expect_near(mid, Vector3d(std::sqrt(0.5), std::sqrt(0.5), 0), 1e-9);
  expect_near(gravity_in_lung_frame(c->at(40.0)), Vector3d(1, 0, 0), 1e-9);
}

TEST(Orientation, OverlappingOrBadTurnsAreRejected) {
  const auto supine = pose_rotation(Pose::Supine);
  EXPECT_EQ(OrientationTrack::create(Eigen::Quaterniond::Identity(), {{20.0, 5.0, supine}, {24.0, 2.0, supine}}).error(),
            "turn at 24 s: expected turns that do not overlap, but the turn at 20 s runs until 25 s");
  EXPECT_EQ(OrientationTrack::create(Eigen::Quaterniond::Identity(), {{-1.0, 5.0, supine}}).error(),
            "turn at -1 s: expected a start time >= 0 s");
  EXPECT_EQ(OrientationTrack::create(Eigen::Quaterniond::Identity(), {{1.0, 0.0, supine}}).error(),
            "turn at 1 s: expected a duration > 0 s, got 0");
  // Back to back is fine.
  EXPECT_TRUE(OrientationTrack::create(Eigen::Quaterniond::Identity(), {{20.0, 5.0, supine}, {25.0, 2.0, supine}}));
}
