/// @file excursion_tracker.h
/// @brief A lesion's excursion over a run, frame by frame, in constant memory: its peak-to-peak (the largest distance
///        between two of its positions, radiotherapy's figure; lesion.h, peak_to_peak_mm) and its cranio-caudal
///        range.
///
/// The positions are not kept. The farthest pair of a set lies on its convex hull, and the hull is followed
/// through its extreme points along 13 directions (the axes, the face and the body diagonals of a cube: both
/// ends of each); the peak-to-peak is the largest distance among those 26 points. For a lesion that moves along
/// one line (one posture: its path is dV times a fixed vector) it is exact; for any path it is never above the
/// true figure and at least 0.88 of it (every direction lies within 27.6 degrees of one of the 13, and the two
/// extremes along that one are at least the width along it apart).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <limits>

namespace lungar::sim {

class ExcursionTracker {
 public:
  void add(const Eigen::Vector3d& p) {
    for (std::size_t d = 0; d < kDirections; ++d) {
      const double s = p.dot(direction(d));
      if (count_ == 0 || s < low_[d]) low_[d] = s, low_at_[d] = p;
      if (count_ == 0 || s > high_[d]) high_[d] = s, high_at_[d] = p;
    }
    ++count_;
  }
  /// The largest distance between two positions added (0 before two).
  double peak_to_peak_mm() const {
    double most = 0;
    if (count_ == 0) return most;
    for (std::size_t i = 0; i < 2 * kDirections; ++i)
      for (std::size_t j = 0; j < i; ++j) most = std::max(most, (extreme(i) - extreme(j)).norm());
    return most;
  }
  /// The range of z (superior +), the cranio-caudal part.
  double si_mm() const { return count_ == 0 ? 0.0 : high_[2] - low_[2]; }
  long positions() const { return count_; }

 private:
  static constexpr std::size_t kDirections = 13;
  static Eigen::Vector3d direction(std::size_t d) {
    static const std::array<Eigen::Vector3d, kDirections> all = {
        Eigen::Vector3d(1, 0, 0),  Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1),  Eigen::Vector3d(1, 1, 0),
        Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(1, 0, -1), Eigen::Vector3d(0, 1, 1),
        Eigen::Vector3d(0, 1, -1), Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, -1), Eigen::Vector3d(1, -1, 1),
        Eigen::Vector3d(-1, 1, 1)};
    return all[d];
  }
  const Eigen::Vector3d& extreme(std::size_t i) const {
    return i < kDirections ? low_at_[i] : high_at_[i - kDirections];
  }

  std::array<double, kDirections> low_{}, high_{};
  std::array<Eigen::Vector3d, kDirections> low_at_{}, high_at_{};
  long count_ = 0;
};

}  // namespace lungar::sim
