/// @file force_sh_test.cpp
/// @brief The paper's rotation angles of an orientation (sim/force/force_sh.h): R = Rz(c) Ry(b) Rx(a), each angle in
///        [0, 2 pi), from any non-zero quaternion's direction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "sim/force/force_sh.h"

namespace lungar::sim {
namespace {

TEST(Force, EulerAnglesAreThePapersXyzInZeroToTwoPi) {
  const double a = 0.3, b = -0.4, c = 2.0;
  const Eigen::Quaterniond q = Eigen::AngleAxisd(c, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX());
  for (const double scale : {1.0, 2.5}) {  // a quaternion's length is not a rotation
    const EulerXYZ e = euler_xyz(Eigen::Quaterniond(q.coeffs() * scale));
    EXPECT_NEAR(e.a, a, 1e-12) << scale;
    EXPECT_NEAR(e.b, 2 * std::numbers::pi + b, 1e-12) << "wrapped into [0, 2 pi)";
    EXPECT_NEAR(e.c, c, 1e-12) << scale;
  }
  const EulerXYZ zero = euler_xyz(Eigen::Quaterniond(0, 0, 0, 0));
  EXPECT_EQ(zero.a + zero.b + zero.c, 0.0) << "no direction: no rotation";
}

}  // namespace
}  // namespace lungar::sim
