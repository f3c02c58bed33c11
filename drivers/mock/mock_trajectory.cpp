/// @file mock_trajectory.cpp
/// @brief The patient's upright -> supine turn, a head standing in front or orbiting, a stylus circling.
#include "drivers/mock/mock_trajectory.h"

#include <algorithm>
#include <cmath>


namespace lungar::drivers {

std::string unknown_trajectory(const std::string& field, const std::string& name) {
  std::string line = field;
  line.append(": expected ").append(kMockTrajectoriesExpected).append(", got \"").append(name).append("\"");
  return line;
}

namespace {

/// The orientation of a sensor at `eye` that looks at `target` (its +y forward, +z as close to world up as can be).
Eigen::Quaterniond look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  Eigen::Matrix3d m;  // columns: the sensor's x (right), y (forward), z (up) in the world
  m << right, forward, right.cross(forward);
  return Eigen::Quaterniond(m);
}

}  // namespace

double upright_to_supine_angle(double t_s) {
  const double s = std::clamp((t_s - kMockTurnStartS) / kMockTurnS, 0.0, 1.0);
  return -M_PI / 2 * (0.5 - 0.5 * std::cos(M_PI * s));
}

std::optional<PoseSample> mock_pose(const std::string& trajectory, Role role, double t_s) {
  const bool turn = trajectory == "upright_to_supine";
  const bool orbit = trajectory == "head_orbit", bedside = trajectory == "bedside";
  if (!turn && !orbit && !bedside && trajectory != "static") return std::nullopt;
  const Eigen::Vector3d centre(kMockPatientCentreMm.data());
  PoseSample p;
  p.role = role;
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  switch (role) {
    case Role::Patient:
      p.set_position(centre);
      if (turn) q = Eigen::AngleAxisd(upright_to_supine_angle(t_s), Eigen::Vector3d::UnitX());
      break;
    case Role::Head: {
      Eigen::Vector3d eye(0.0, -700.0, 1300.0);  // standing in front of (anterior to) the patient, a little above
      if (orbit) {
        const double a = 2 * M_PI * t_s / 10.0;  // one turn every 10 s, radius 700 mm
        eye = {700.0 * std::sin(a), -700.0 * std::cos(a), 1300.0};
      } else if (bedside) {
        eye = centre + Eigen::Vector3d(-90.0, -300.0, 160.0);  // at the foot of the bed, a little to the right
      } else if (turn) {
        // A small sway, so that prediction has something to do.
        eye.x() = 40.0 * std::sin(2 * M_PI * t_s / 3.0);
      }
      p.set_position(eye);
      q = look_at(eye, centre);
      break;
    }
    case Role::Stylus: {
      const double a = 2 * M_PI * t_s / 2.0;
      p.set_position(centre + Eigen::Vector3d(100.0 * std::cos(a), -200.0, 100.0 * std::sin(a)));
      q = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ());
      break;
    }
  }
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  p.set_orientation(q);
  return p;
}

}  // namespace lungar::drivers
