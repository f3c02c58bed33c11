/// @file gravity.cpp
/// @brief Rotates world gravity into the lung frame.
#include "sim/force/gravity.h"

#include <cmath>

namespace lungar::sim {

Eigen::Vector3d gravity_in_lung_frame(const Eigen::Quaterniond& q) {
  const double norm = q.norm();
  if (!(norm > 0) || !std::isfinite(norm)) return Eigen::Vector3d(0, 0, -1);
  const Eigen::Quaterniond unit(q.coeffs() / norm);
  return unit.conjugate() * Eigen::Vector3d(0, 0, -1);
}

Eigen::Quaterniond axis_rotation(int axis, double angle) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)));
}

}  // namespace lungar::sim
