/// @file pivot_calibration_test.cpp
/// @brief fit_pivot on synthetic stylus poses: a cone about the tip gives the tip back; poses turned about one
///        axis only leave the tip free along that axis and are refused, whatever noise makes the system's rank.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "platform/registration/pivot_calibration.h"

namespace {

const Eigen::Vector3d kTip(2.0, -1.5, -150.0);    // stylus frame: the tip down the handle
const Eigen::Vector3d kPivot(10.0, -20.0, 30.0);  // the dimple, tracker frame

/// The stylus with its tip in the dimple, turned by `turn`, tracked with 0.1 mm and 0.05 degree noise.
Eigen::Isometry3d pose(const Eigen::Matrix3d& turn, std::mt19937& rng) {
  std::normal_distribution<double> mm(0.0, 0.1), rad(0.0, 0.05 * M_PI / 180.0);
  const Eigen::Matrix3d noise =
      (Eigen::AngleAxisd(rad(rng), Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(rad(rng), Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(rad(rng), Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = noise * turn;  // as the tracker reports it; the tip itself stays in the dimple
  p.translation() = kPivot - turn * kTip + Eigen::Vector3d(mm(rng), mm(rng), mm(rng));
  return p;
}

// A hinge: the stylus turned 70 degrees back and forth about one axis. Every tip along that axis fits these poses
// equally well; without the orientation noise the system is singular, with it the fit used to return a tip many
// millimetres off without an error (issue 42).
TEST(PivotCalibration, RefusesPosesTurnedAboutOneAxisOnly) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-0.6, 0.6);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1.0, 0.2).normalized();
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 200; ++i) poses.push_back(pose(Eigen::AngleAxisd(angle(rng), axis).toRotationMatrix(), rng));
  const auto fit = lungar::platform::fit_pivot(poses);
  ASSERT_FALSE(fit) << "returned the tip " << fit->tip_mm.transpose() << ", " << (fit->tip_mm - kTip).norm()
                    << " mm off";
  EXPECT_NE(fit.error().find("about one axis only"), std::string::npos) << fit.error();
}

// A cone of 10 degrees about the tip, swept all round: the tip and the dimple to a fraction of a millimetre, and
// the least-turned direction of the stylus moved enough to say so.
TEST(PivotCalibration, FindsTheTipFromAConeSweptAllRound) {
  std::mt19937 rng(6);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 72; ++i) {
    const double around = 2 * M_PI * i / 72;
    const Eigen::Vector3d tilt_axis(std::cos(around), std::sin(around), 0.0);
    poses.push_back(pose(Eigen::AngleAxisd(10.0 * M_PI / 180.0, tilt_axis).toRotationMatrix(), rng));
  }
  const auto fit = lungar::platform::fit_pivot(poses);
  ASSERT_TRUE(fit) << fit.error();
  EXPECT_LT((fit->tip_mm - kTip).norm(), 0.5) << fit->tip_mm.transpose();
  EXPECT_LT((fit->pivot_mm - kPivot).norm(), 0.5) << fit->pivot_mm.transpose();
  EXPECT_EQ(fit->poses, 72);
  EXPECT_NEAR(fit->spread_deg, 20.0, 0.5) << "opposite sides of the cone";
  EXPECT_GT(fit->least_turn_deg, lungar::platform::kMinPivotLeastTurnDeg);
  EXPECT_LT(fit->rms_mm, 0.3);
  EXPECT_GT(fit->rms_mm, 0.05) << "the noise put in shows in the residual";
}

// The fewest poses it takes, noise-free: eight around a cone give the tip exactly, with no residual.
TEST(PivotCalibration, EightExactPosesGiveTheTipWithNoResidual) {
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < lungar::platform::kMinPivotPoses; ++i) {
    const double around = 2 * M_PI * i / lungar::platform::kMinPivotPoses;
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d(std::cos(around), std::sin(around), 0.0))
            .toRotationMatrix();
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    p.linear() = turn;
    p.translation() = kPivot - turn * kTip;
    poses.push_back(p);
  }
  const auto fit = lungar::platform::fit_pivot(poses);
  ASSERT_TRUE(fit) << fit.error();
  EXPECT_LT((fit->tip_mm - kTip).norm(), 1e-6) << fit->tip_mm.transpose();
  EXPECT_LT(fit->rms_mm, 1e-6);
  EXPECT_LT(fit->max_mm, 1e-6);
}

}  // namespace
