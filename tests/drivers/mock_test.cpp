// Tests of drivers/mock: the upright -> supine turn in the frames of docs/design.md (The mathematics), and the
// mock's reports decoding back to the trajectory through the configured layout (the code path shared with synth
// and replay).
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/decode/decoder.h"
#include "drivers/mock/mock_reports.h"
#include "drivers/mock/mock_trajectory.h"
#include "drivers/tracker/tracker_config.h"

using namespace lungar;
using namespace lungar::drivers;

TEST(MockTrajectory, PatientTurnsFromUprightToSupine) {
  const auto up = *mock_pose("upright_to_supine", Role::Patient, 0.0);
  const auto down = *mock_pose("upright_to_supine", Role::Patient, kMockTurnStartS + kMockTurnS + 1.0);
  // Upright: the lung frame is the world's (+z superior = world up).
  EXPECT_LT(up.orientation().angularDistance(Eigen::Quaterniond::Identity()), 1e-12);
  // Supine: posterior (+y of the lung frame) points world down, superior points along world +y.
  const Eigen::Vector3d posterior = down.orientation() * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d superior = down.orientation() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(posterior.z(), -1.0, 1e-12);
  EXPECT_NEAR(superior.y(), 1.0, 1e-12);
  // Halfway through the turn: 45 degrees.
  const auto mid = *mock_pose("upright_to_supine", Role::Patient, kMockTurnStartS + kMockTurnS / 2);
  EXPECT_NEAR(mid.orientation().angularDistance(up.orientation()), M_PI / 4, 1e-9);
  EXPECT_FALSE(mock_pose("somersault", Role::Patient, 0.0));
}

TEST(MockTrajectory, HeadLooksAtThePatient) {
  for (const char* name : {"static", "upright_to_supine", "head_orbit", "bedside"}) {
    for (double t : {0.0, 1.3, 4.0, 7.7}) {
      const auto head = *mock_pose(name, Role::Head, t);
      const Eigen::Vector3d forward = head.orientation() * Eigen::Vector3d::UnitY();  // the head looks along its +y
      const Eigen::Vector3d to = (Eigen::Vector3d(kMockPatientCentreMm.data()) - head.position()).normalized();
      EXPECT_NEAR(forward.dot(to), 1.0, 1e-9) << name << " t=" << t;
      EXPECT_NEAR((head.orientation() * Eigen::Vector3d::UnitX()).z(), 0.0, 1e-9);  // no roll
    }
  }
}

TEST(MockReports, DecodeBackToTheTrajectory) {
  TrackerConfig t;
  t.stylus.enabled = true;
  const ReportLayout l = *make_layout(t);
  MockReports reports(t.mock, l);
  int n = 0;
  for (std::int64_t k = 0; k < 400; k += 37) {
    reports.tick(k, [&](std::span<const std::uint8_t> bytes) {
      const DecodedReport d = decode_report(bytes, l);
      ASSERT_EQ(d.error, DecodeError::None);
      ASSERT_EQ(d.count, 1);
      const auto want = *mock_pose(t.mock.trajectory, d.poses[0].role, static_cast<double>(k) / t.mock.rate_hz);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(d.poses[0].position_mm[i], want.position_mm[i], 0.005);
      EXPECT_LT(d.poses[0].orientation().angularDistance(want.orientation()), 2e-4);
      EXPECT_EQ(d.device_ticks, static_cast<std::uint32_t>(std::llround(k * 16000.0)));
      ++n;
    });
  }
  EXPECT_EQ(n, 11 * 3);  // three sensors, one report each per tick
}

TEST(MockReports, DropoutDropsAboutTheConfiguredShare) {
  TrackerConfig t;
  t.mock.dropout = 0.25;
  const ReportLayout l = *make_layout(t);
  MockReports reports(t.mock, l);
  int n = 0;
  for (std::int64_t k = 0; k < 2000; ++k) reports.tick(k, [&](std::span<const std::uint8_t>) { ++n; });
  EXPECT_NEAR(n / 4000.0, 0.75, 0.03);  // 4000 reports offered; binomial sigma ~0.007
}
