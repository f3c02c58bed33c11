/// @file followed_breath_share.h
/// @brief A trainee's share of an instructor's followed breath (a trace, a chest marker, a mannequin): the dV the
///        instructor's frames drew, carried by its heartbeats, evaluated at the trainee's frame on the instructor's
///        breathing time. No trainee can compute a followed breath from shared parameters, as it does the model's.
///
/// The frame's dV is the instructor's between the two newest points around its time, or carried along their
/// slope at most kMaxAheadS past the newest (a heartbeat arrives a frame or so after the instructor drew it).
/// With no point fresher than kStaleS (the instructor stopped following, or went away) the shared model answers;
/// a change between the two moves dV at most sim::kHandoverMlPerS, as the follower's own handovers do.
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include "config/base/spsc_ring.h"
#include "sim/breathing/driver.h"

namespace lungar::classroom {

class FollowedBreathShare {
 public:
  static constexpr double kStaleS = 0.5;
  static constexpr double kMaxAheadS = 0.1;

  struct Point {
    double t_s = 0;    ///< the instructor's breathing time of its frame
    double dv_ml = 0;  ///< what that frame drew
    std::array<double, 2> lung_dv_ml{std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN()};
  };

  /// The sync thread: one checked heartbeat's point.
  void push(const Point& p) { ring_.push(p); }
  /// The frame thread: `out` is the shared model's sample at the instructor's breathing time out.t_s; its dV
  /// becomes the instructor's followed dV there, when it has one. Allocates nothing.
  void apply(sim::BreathingSample& out);
  /// Whether the last apply() drew the instructor's followed breath (frame thread).
  bool following() const { return following_; }

 private:
  SpscRing<Point, 256> ring_;
  // The frame thread.
  Point older_, newest_;
  int points_ = 0;
  bool following_ = false, caught_up_ = true, started_ = false;
  double out_ml_ = 0, out_t_ = 0;
};

}  // namespace lungar::classroom
