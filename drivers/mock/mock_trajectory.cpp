/// @file mock_trajectory.cpp
/// @brief The patient's upright -> supine turn, a head standing in front or orbiting, a stylus circling.
#include "drivers/mock/mock_trajectory.h"

#include <algorithm>
#include <cmath>

#include "drivers/pose/quat.h"

namespace lungar::drivers {

namespace {

/// The orientation of a sensor at `eye` that looks at `target` (its +y forward, +z as close to world up as can be).
quat::Q look_at(const quat::V& eye, const quat::V& target) {
  quat::V f = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
  const double n = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (double& v : f) v /= n;
  // right = forward x up, up' = right x forward
  quat::V r = {f[1] * 1.0 - f[2] * 0.0, f[2] * 0.0 - f[0] * 1.0, 0.0};
  const double rn = std::sqrt(r[0] * r[0] + r[1] * r[1]);
  r = {r[0] / rn, r[1] / rn, 0.0};
  const quat::V u = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
  // Columns are the sensor's x (right), y (forward), z (up) in the world.
  const quat::M m = {{{r[0], f[0], u[0]}, {r[1], f[1], u[1]}, {r[2], f[2], u[2]}}};
  return quat::from_matrix(m);
}

}  // namespace

double upright_to_supine_angle(double t_s) {
  const double s = std::clamp((t_s - kMockTurnStartS) / kMockTurnS, 0.0, 1.0);
  return -M_PI / 2 * (0.5 - 0.5 * std::cos(M_PI * s));
}

std::optional<DecodedPose> mock_pose(const std::string& trajectory, Role role, double t_s) {
  const bool turn = trajectory == "upright_to_supine";
  const bool orbit = trajectory == "head_orbit";
  if (!turn && !orbit && trajectory != "static") return std::nullopt;
  const quat::V centre = kMockPatientCentreMm;
  DecodedPose p;
  p.role = role;
  switch (role) {
    case Role::Patient:
      p.position_mm = centre;
      p.orientation_wxyz = turn ? quat::about(0, upright_to_supine_angle(t_s)) : quat::Q{1, 0, 0, 0};
      break;
    case Role::Head: {
      quat::V eye = {0.0, -700.0, 1300.0};  // standing in front of (anterior to) the patient, a little above
      if (orbit) {
        const double a = 2 * M_PI * t_s / 10.0;  // one turn every 10 s, radius 700 mm
        eye = {700.0 * std::sin(a), -700.0 * std::cos(a), 1300.0};
      } else if (turn) {
        // A small sway, so that prediction has something to do.
        eye[0] = 40.0 * std::sin(2 * M_PI * t_s / 3.0);
      }
      p.position_mm = eye;
      p.orientation_wxyz = look_at(eye, centre);
      break;
    }
    case Role::Stylus: {
      const double a = 2 * M_PI * t_s / 2.0;
      p.position_mm = {centre[0] + 100.0 * std::cos(a), centre[1] - 200.0, centre[2] + 100.0 * std::sin(a)};
      p.orientation_wxyz = quat::about(2, a);
      break;
    }
  }
  if (p.orientation_wxyz[0] < 0) {
    for (double& v : p.orientation_wxyz) v = -v;
  }
  return p;
}

}  // namespace lungar::drivers
