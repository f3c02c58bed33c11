/// @file spaam_session_test.cpp
/// @brief The interactive SPAAM without a window: a simulated user on a known HMD lines every crosshair up with
///        the stylus tip (the head moving between alignments), and the alignments gathered fit the eyes back;
///        undo drops the newest, a pose the tracker does not vouch for is refused, and an abort writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>

#include <Eigen/Geometry>

#include "platform/app/spaam_command.h"
#include "platform/registration/spaam_session.h"
#include "platform/registration/display_calibration.h"

namespace lungar::platform {
namespace {

constexpr int kEyeW = 1280, kEyeH = 720;

/// A known eye looking along the sensor's +z: 900 px focal lengths, the principal point off centre.
Eigen::Matrix<double, 3, 4> known_eye(const Eigen::Vector3d& centre, double tilt) {
  Eigen::Matrix3d k;
  k << 900, 0, 630, 0, 905, 372, 0, 0, 1;
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.5 * tilt, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  Eigen::Matrix<double, 3, 4> rt;
  rt << r, -r * centre;
  return k * rt;
}

drivers::PoseSample sample(drivers::Role role, const Eigen::Isometry3d& pose) {
  drivers::PoseSample s;
  s.role = role;
  s.flags = drivers::kPoseValid;
  s.set_position(pose.translation());
  s.set_orientation(Eigen::Quaterniond(pose.linear()));
  return s;
}

Eigen::Isometry3d random_pose(std::mt19937& rng, double spread_mm) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() =
      Eigen::Quaterniond(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), 2.0).normalized()).toRotationMatrix();
  p.translation() = spread_mm * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  return p;
}

/// A user wearing the known HMD: for the session's target, the head somewhere, the stylus held so that its tip
/// lies on the crosshair's ray at 0.3 .. 0.9 m (aimed within `aim_px`).
struct SimulatedUser {
  std::array<Eigen::Matrix<double, 3, 4>, 2> eyes{known_eye({-31.5, -78, -72}, 0.04),
                                                  known_eye({31.5, -78, -72}, -0.03)};
  Eigen::Vector3d tip_mm{0, 0, 152.5};
  double aim_px = 0.5;
  std::mt19937 rng{7};
  int confirms = 0;

  std::array<drivers::PoseSample, 2> poses(const SpaamSession& s) {
    const SpaamTarget t = s.target();
    const Eigen::Matrix<double, 3, 4>& p = eyes[static_cast<std::size_t>(t.eye)];
    std::normal_distribution<double> aim(0.0, aim_px);
    const Eigen::Matrix3d m = p.leftCols<3>();
    const Eigen::Vector3d centre = -m.inverse() * p.col(3);
    const Eigen::Vector3d ray = m.inverse() * Eigen::Vector3d(t.pixel.x() + aim(rng), t.pixel.y() + aim(rng), 1.0);
    const double depth = 300.0 + 600.0 * (confirms++ % 7) / 6.0;
    const Eigen::Vector3d in_sensor = centre + depth * ray / ray.z();
    const Eigen::Isometry3d head = random_pose(rng, 500.0);
    Eigen::Isometry3d stylus = random_pose(rng, 0.0);
    stylus.translation() = head * in_sensor - stylus.linear() * tip_mm;
    return {sample(drivers::Role::Head, head), sample(drivers::Role::Stylus, stylus)};
  }
};

/// Keys and poses from the simulated user; `close_after` confirms, the screen closes (Esc).
SpaamIo scripted(SpaamSession& session, SimulatedUser& user, int close_after = -1) {
  SpaamIo io;
  io.poll = [&user, close_after] { return close_after < 0 || user.confirms < close_after; };
  io.keys = [] { return std::string(" "); };
  io.poses = [&session, &user] { return user.poses(session); };
  io.draw = [](const SpaamSession&, const std::string&) { return ok(); };
  io.say = [](const std::string&) {};
  return io;
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(SpaamSession, PositionsSpreadOverTheViewportAndConsecutiveOnesJump) {
  const std::vector<Eigen::Vector2d> at = spaam_positions(kEyeW, kEyeH, 5);
  ASSERT_EQ(at.size(), 25u);
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_GE(at[i].x(), 0.1 * kEyeW);
    EXPECT_LE(at[i].x(), 0.9 * kEyeW + 1);
    EXPECT_GE(at[i].y(), 0.1 * kEyeH);
    EXPECT_LE(at[i].y(), 0.9 * kEyeH + 1);
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_NE(at[i], at[j]) << "each grid position once";
    }
    if (i > 0) {
      EXPECT_GT((at[i] - at[i - 1]).norm(), 0.3 * kEyeH) << "position " << i << " next to the last";
    }
  }
}

TEST(SpaamSession, GatheredAlignmentsFitTheKnownEyesBack) {
  const auto dir = fresh_dir("lungar_spaam_session_fit");
  SimulatedUser user;
  SpaamSession session(kEyeW, kEyeH, {drivers::Role::Stylus, user.tip_mm});
  CalibrateDisplayOptions o;
  o.out_path = (dir / "display.toml").string();
  ASSERT_EQ(gather_and_fit(o, session, scripted(session, user)), 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "display.toml"));
  auto read = read_alignments_csv((dir / "display-alignments.csv").string());
  ASSERT_TRUE(read) << read.error();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(100, 1180), v(80, 640), depth(300, 900);
  for (int e = 0; e < 2; ++e) {
    ASSERT_EQ((*read)[e].size(), 25u);
    auto fit = calibrate_eye((*read)[e]);
    ASSERT_TRUE(fit) << fit.error();
    EXPECT_LT(fit->rms_px, 2.0);
    const Eigen::Matrix<double, 3, 4>& truth = user.eyes[static_cast<std::size_t>(e)];
    const Eigen::Matrix3d m = truth.leftCols<3>();
    double worst = 0;
    for (int i = 0; i < 100; ++i) {  // held-out points over the viewport and the depths aligned
      const Eigen::Vector3d ray = m.inverse() * Eigen::Vector3d(u(rng), v(rng), 1.0);
      const Eigen::Vector3d x = -m.inverse() * truth.col(3) + depth(rng) * ray / ray.z();
      worst = std::max(worst, (project(fit->projection, x) - project(truth, x)).norm());
    }
    EXPECT_LT(worst, 2.0) << "eye " << e << ": worst reprojection of held-out points, px";
  }
}

TEST(SpaamSession, UndoDropsTheNewestEvenAcrossTheEyes) {
  SimulatedUser user;
  SpaamSession session(kEyeW, kEyeH, {drivers::Role::Stylus, user.tip_mm});
  EXPECT_FALSE(session.undo());
  for (int i = 0; i < 3; ++i) {
    const auto p = user.poses(session);
    ASSERT_TRUE(session.confirm(p[0], p[1]));
  }
  const Alignment second = session.alignments()[0][1];
  ASSERT_TRUE(session.undo());
  ASSERT_EQ(session.alignments()[0].size(), 2u);
  EXPECT_EQ(session.alignments()[0][1].pixel, second.pixel);
  EXPECT_EQ(session.target().index, 2) << "the undone position is asked again";
  while (session.target().eye == 0) {
    const auto p = user.poses(session);
    ASSERT_TRUE(session.confirm(p[0], p[1]));
  }
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.target().eye, 0);
  EXPECT_EQ(session.target().index, 24);
  EXPECT_EQ(session.prompt()[0], "LEFT EYE 25/25 (CLOSE THE RIGHT EYE)");
}

TEST(SpaamSession, APoseTheTrackerDoesNotVouchForIsRefused) {
  SimulatedUser user;
  SpaamSession session(kEyeW, kEyeH, {drivers::Role::Stylus, user.tip_mm});
  auto p = user.poses(session);
  drivers::PoseSample none;  // before the first report
  Status refused = session.confirm(none, p[1]);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(), "head pose: none from the tracker yet (is [trackers.head] enabled?); not recorded");
  p[1].flags |= drivers::kPoseStale;
  refused = session.confirm(p[0], p[1]);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("stylus pose: stale"), std::string::npos) << refused.error();
  EXPECT_TRUE(session.alignments()[0].empty());
  EXPECT_EQ(session.target().index, 0);
}

TEST(SpaamSession, KeysConfirmUndoAndAnAbortWritesNothing) {
  const auto dir = fresh_dir("lungar_spaam_session_abort");
  SimulatedUser user;
  SpaamSession session(kEyeW, kEyeH, {drivers::Role::Stylus, user.tip_mm});
  std::vector<std::string> keys{" ", "\n", "x", "\b", " "};
  std::vector<std::string> notes;
  SpaamIo io = scripted(session, user);
  io.poll = [&keys] { return !keys.empty(); };  // then Esc
  io.keys = [&keys] {
    std::string k = keys.front();
    keys.erase(keys.begin());
    return k;
  };
  io.draw = [&notes](const SpaamSession&, const std::string& note) {
    notes.push_back(note);
    return ok();
  };
  CalibrateDisplayOptions o;
  o.out_path = (dir / "display.toml").string();
  o.report_json = (dir / "report.json").string();
  EXPECT_EQ(gather_and_fit(o, session, io), 1);
  EXPECT_EQ(session.alignments()[0].size(), 2u) << "space, enter, undo, space";
  EXPECT_EQ(notes, (std::vector<std::string>{"recorded left 1", "recorded left 2", "recorded left 2",
                                             "undone: the last alignment is dropped", "recorded left 2"}));
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "aborted: no alignments, no calibration, no report";
}

}  // namespace
}  // namespace lungar::platform
