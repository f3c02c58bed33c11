/// @file spaam_session.h
/// @brief The sequence of an interactive SPAAM calibration, apart from any window so that a test can drive it:
///        the crosshair's positions in each eye's viewport, left eye first, and on each confirm the tracked point
///        (the stylus tip, or a fiducial fixed to the patient tracker) carried into the head tracker's sensor frame
///        and paired with the crosshair's pixel; a pose the tracker does not vouch for is refused, not recorded.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "config/base/result.h"
#include "drivers/pose/pose_sample.h"
#include "platform/registration/display_calibration.h"

namespace lungar::platform {

/// 5 x 5 positions an eye: 25 alignments, the most the fit is advised (20-25) and well over its 6.
inline constexpr int kSpaamGridSide = 5;

/// `side` x `side` pixel positions (pixel centres) spread over a `width_px` x `height_px` viewport from 10 % to
/// 90 % of each side, from the centre (the easiest to line up, while the user finds the way of it) in an order
/// where consecutive ones lie apart: a crosshair that jumps makes the user move, and so spreads the alignments in
/// depth and direction instead of sliding along a row.
std::vector<Eigen::Vector2d> spaam_positions(int width_px, int height_px, int side);

/// The point the user lines the crosshair up with: `offset_mm` in the frame of the tracker's `role` sensor (the
/// stylus's tip, or a fiducial on the patient tracker).
struct SpaamPoint {
  drivers::Role role = drivers::Role::Stylus;
  Eigen::Vector3d offset_mm = Eigen::Vector3d::Zero();
};

/// What the user is asked for now.
struct SpaamTarget {
  int eye = 0;                                      ///< 0 left, 1 right
  int index = 0;                                    ///< among the eye's positions, from 0
  int count = 0;                                    ///< the eye's positions
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  ///< the crosshair in the eye's viewport, origin top-left
};

class SpaamSession {
 public:
  /// `eye_width_px` x `eye_height_px`: one eye's panel ([hmd] eye_width_px, eye_height_px), the pixels the
  /// calibration is in whatever the window's size.
  SpaamSession(int eye_width_px, int eye_height_px, const SpaamPoint& point, int side = kSpaamGridSide);

  /// Every position of both eyes confirmed.
  bool done() const { return alignments_[1].size() == positions_.size(); }
  /// The position to line up (the last one's when done()).
  SpaamTarget target() const;
  /// Records the point (in the head sensor's frame) with the crosshair's pixel and moves on; refused (one line,
  /// nothing recorded) when either pose is invalid or stale, or when done().
  Status confirm(const drivers::PoseSample& head, const drivers::PoseSample& point_sensor);
  /// Drops the newest alignment (back into the left eye when the right has none yet); false when there is none.
  bool undo();
  /// The lines the screen shows: eye, n/N and what to do.
  std::array<std::string, 3> prompt() const;

  const SpaamPoint& point() const { return point_; }
  const std::array<std::vector<Alignment>, 2>& alignments() const { return alignments_; }

 private:
  std::vector<Eigen::Vector2d> positions_;
  SpaamPoint point_;
  std::array<std::vector<Alignment>, 2> alignments_;
};

}  // namespace lungar::platform
