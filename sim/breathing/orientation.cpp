/// @file orientation.cpp
/// @brief Named patient poses and eased slerp between them.
#include "sim/breathing/orientation.h"
#include "config/base/number_text.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lungar::sim {

std::string_view to_string(Pose pose) { return kPoseNames.name(pose); }

std::optional<Pose> pose_from_name(std::string_view name) { return kPoseNames.parse(name); }

Eigen::Quaterniond pose_rotation(Pose pose) {
  constexpr double quarter = std::numbers::pi / 2.0;
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  // Supine: -90 deg about the left-right axis brings the back (+y) down and the head to world +y. The other
  // lying poses keep the head there and roll about the body's long axis (+z), so that a turn between two of them
  // is a roll, as on a table.
  const Eigen::Quaterniond supine(AngleAxisd(-quarter, Vector3d::UnitX()));
  auto roll = [&](double angle) { return supine * Eigen::Quaterniond(AngleAxisd(angle, Vector3d::UnitZ())); };
  switch (pose) {
    case Pose::Upright: return Eigen::Quaterniond::Identity();
    case Pose::Supine: return supine;
    case Pose::Prone: return roll(2.0 * quarter);         // front (-y) down
    case Pose::LeftLateral: return roll(quarter);         // left side (+x) down
    case Pose::RightLateral: return roll(-quarter);       // right side (-x) down
  }
  return Eigen::Quaterniond::Identity();
}

double tilt_from_upright_deg(const Eigen::Quaterniond& q) {
  const double c = std::clamp(-gravity_in_lung_frame(q).z(), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi;
}

Result<OrientationTrack> OrientationTrack::create(const Eigen::Quaterniond& start, std::vector<Turn> turns) {
  std::stable_sort(turns.begin(), turns.end(), [](const Turn& a, const Turn& b) { return a.t_s < b.t_s; });
  for (std::size_t k = 0; k < turns.size(); ++k) {
    const Turn& t = turns[k];
    if (!(std::isfinite(t.t_s) && t.t_s >= 0)) {
      return fail("turn at " + number_text(t.t_s) + " s: expected a start time >= 0 s");
    }
    if (!(std::isfinite(t.duration_s) && t.duration_s > 0)) {
      return fail("turn at " + number_text(t.t_s) + " s: expected a duration > 0 s, got " + number_text(t.duration_s));
    }
    if (std::abs(t.target.norm() - 1.0) > 1e-6) {
      return fail("turn at " + number_text(t.t_s) + " s: expected a unit quaternion as target");
    }
    if (k > 0 && turns[k - 1].t_s + turns[k - 1].duration_s > t.t_s) {
      return fail("turn at " + number_text(t.t_s) + " s: expected turns that do not overlap, but the turn at " +
                  number_text(turns[k - 1].t_s) + " s runs until " +
                  number_text(turns[k - 1].t_s + turns[k - 1].duration_s) + " s");
    }
  }
  OrientationTrack track;
  track.start_ = start.normalized();
  track.turns_ = std::move(turns);
  Eigen::Quaterniond current = track.start_;
  for (const Turn& t : track.turns_) {
    track.from_.push_back(current);
    current = t.target;
  }
  return track;
}

Eigen::Quaterniond OrientationTrack::at(double t) const {
  // The last turn started at or before t.
  auto it = std::upper_bound(turns_.begin(), turns_.end(), t, [](double v, const Turn& s) { return v < s.t_s; });
  if (it == turns_.begin()) return start_;
  const std::size_t k = static_cast<std::size_t>(it - turns_.begin()) - 1;
  const Turn& turn = turns_[k];
  const double x = std::clamp((t - turn.t_s) / turn.duration_s, 0.0, 1.0);
  if (x >= 1.0) return turn.target;
  const double eased = x * x * (3.0 - 2.0 * x);
  return from_[k].slerp(eased, turn.target);  // Eigen's slerp takes the shorter arc
}

}  // namespace lungar::sim
