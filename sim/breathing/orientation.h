/// @file orientation.h
/// @brief The patient's orientation over time: named poses and timed turns between them.
///
/// An orientation is the unit quaternion of the lung frame (DICOM LPS: +x left, +y posterior, +z superior) in
/// the world frame, whose +z points up (gravity is -z). Upright is the identity; supine is -90 degrees about the
/// left-right (x) axis, which brings the patient's back (+y) down and the head to world +y; prone and the lateral
/// poses keep the head there, rolled about the long axis. A turn goes from the orientation at its start
/// to its target along the shorter arc (slerp) with smoothstep easing, so it starts and stops without a jerk.
#pragma once

#include "config/base/patient_names.h"
#include "config/base/result.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

#include "sim/force/gravity.h"  // gravity_in_lung_frame(): g-hat for an orientation

namespace lungar::sim {

using lungar::Pose;  // config/base/patient_names.h: the names are spelled there
inline constexpr Pose kAllPoses[] = {Pose::Upright, Pose::Supine, Pose::Prone, Pose::LeftLateral,
                                     Pose::RightLateral};

/// "upright", "supine", "prone", "left_lateral" (lying on the left side), "right_lateral".
std::string_view to_string(Pose pose);
std::optional<Pose> pose_from_name(std::string_view name);
/// Lung frame -> world rotation of a pose.
Eigen::Quaterniond pose_rotation(Pose pose);

/// Angle between the patient's superior axis and the world's up, degrees: 0 upright, 90 supine or lateral.
double tilt_from_upright_deg(const Eigen::Quaterniond& lung_to_world);

struct Turn {
  double t_s = 0;          ///< start
  double duration_s = 0;   ///< > 0
  Eigen::Quaterniond target = Eigen::Quaterniond::Identity();
};

class OrientationTrack {
 public:
  /// Turns must have t_s >= 0, duration_s > 0, and not overlap; they are sorted by start here.
  static Result<OrientationTrack> create(const Eigen::Quaterniond& start, std::vector<Turn> turns);

  /// The orientation at t (s). Allocates nothing.
  Eigen::Quaterniond at(double t_s) const;
  const std::vector<Turn>& turns() const { return turns_; }
  const Eigen::Quaterniond& start() const { return start_; }

 private:
  Eigen::Quaterniond start_ = Eigen::Quaterniond::Identity();
  std::vector<Turn> turns_;
  std::vector<Eigen::Quaterniond> from_;  ///< orientation at each turn's start
};

}  // namespace lungar::sim
