/// @file followed_breath_share.cpp
/// @brief The instructor's followed dV at a trainee's frame (followed_breath_share.h).
#include "drivers/classroom/followed_breath_share.h"

#include <algorithm>
#include <cmath>

#include "sim/breathing/breath_follower.h"

namespace lungar::classroom {

namespace {

/// `a` and `b` (a older) carried linearly to `t`: between them, or along their slope past `b`.
double along(double a_t, double a_v, double b_t, double b_v, double t) {
  if (!(b_t > a_t)) return b_v;
  return b_v + (b_v - a_v) / (b_t - a_t) * (t - b_t);
}

}  // namespace

void FollowedBreathShare::apply(sim::BreathingSample& out) {
  ring_.drain([&](const Point& p) {
    if (points_ > 0 && !(p.t_s > newest_.t_s)) return;  // the instructor's breathing time only goes forward
    older_ = newest_;
    newest_ = p;
    ++points_;
  });
  const double t = out.t_s;
  const bool fresh = points_ > 0 && std::abs(t - newest_.t_s) <= kStaleS;
  const bool two = points_ > 1;
  const double to = std::clamp(t, two ? older_.t_s : newest_.t_s, newest_.t_s + kMaxAheadS);
  const double target = !fresh ? out.dv_ml
                        : two  ? along(older_.t_s, older_.dv_ml, newest_.t_s, newest_.dv_ml, to)
                               : newest_.dv_ml;
  if (fresh != following_) caught_up_ = false;  // a change of source: caught up at a bounded rate
  following_ = fresh;
  if (!started_ || caught_up_) {
    out_ml_ = target;
    caught_up_ = true;
  } else {
    const double limit = sim::kHandoverMlPerS * std::max(0.0, t - out_t_);
    out_ml_ += std::clamp(target - out_ml_, -limit, limit);
    caught_up_ = std::abs(target - out_ml_) < 1e-9;
  }
  started_ = true;
  out_t_ = t;
  out.dv_ml = out_ml_;
  out.v_ml = out.v_frc_ml + out_ml_;
  if (!fresh || !caught_up_) return;
  for (std::size_t l = 0; l < 2; ++l) {
    const double a = older_.lung_dv_ml[l], b = newest_.lung_dv_ml[l];
    if (std::isfinite(b)) out.lung_dv_ml[l] = two && std::isfinite(a) ? along(older_.t_s, a, newest_.t_s, b, to) : b;
  }
}

}  // namespace lungar::classroom
