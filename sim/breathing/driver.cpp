/// @file driver.cpp
/// @brief Time to phase (with smooth rate ramps), phase to pressure and volume (cross-fading patterns).
#include "sim/breathing/driver.h"

#include <algorithm>
#include <cmath>

#include "config/base/enum_names.h"
#include "config/base/number_text.h"

namespace lungar::sim {

namespace {

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

/// A hold stops (and restarts) the cycle over this time, s: fast, but without a step in the flow.
constexpr double kHoldRampS = 0.2;
/// Phases sampled when comparing two patterns or measuring a peak flow.
constexpr int kPhaseSamples = 256;

/// A generic breath index for comparisons: no sigh is ever scheduled there.
constexpr double kGenericBreath = -1000.0;

/// The largest |dV/dt| of steady breathing with `p` (and of its sigh, if one is to come), mL/s.
double peak_flow_ml_per_s(const Pattern& p) {
  double peak = 0;
  for (double breath : {kGenericBreath, static_cast<double>(p.sigh_breath)}) {
    if (breath < kGenericBreath + 1) breath = kGenericBreath;
    double prev = evaluate(p, breath).v_ml;
    for (int k = 1; k <= 4 * kPhaseSamples; ++k) {
      const double v = evaluate(p, breath + static_cast<double>(k) / (4 * kPhaseSamples)).v_ml;
      peak = std::max(peak, std::abs(v - prev));
      prev = v;
    }
  }
  return peak * 4 * kPhaseSamples * p.params.rate_bpm / 60.0;
}

/// Largest differences in volume (mL) and in pressures (cmH2O) between two patterns over one breath.
struct Difference {
  double v_ml = 0;
  double p_cmh2o = 0;
};
Difference max_difference(const Pattern& a, const Pattern& b) {
  Difference d;
  for (int k = 0; k < kPhaseSamples; ++k) {
    const double phi = kGenericBreath + static_cast<double>(k) / kPhaseSamples;
    const PatternPoint pa = evaluate(a, phi), pb = evaluate(b, phi);
    d.v_ml = std::max(d.v_ml, std::abs(pa.v_ml - pb.v_ml));
    d.p_cmh2o = std::max({d.p_cmh2o, std::abs(pa.p_cmh2o - pb.p_cmh2o),
                          std::abs(pa.p_applied_cmh2o - pb.p_applied_cmh2o)});
  }
  return d;
}

/// The names of the log lines and error messages ("change at 11 s: ...").
constexpr EnumNames<BreathPhase, 4> kBreathPhaseNames{{{{BreathPhase::Inspiration, "inspiration"},
                                                       {BreathPhase::Expiration, "expiration"},
                                                       {BreathPhase::Hold, "hold"},
                                                       {BreathPhase::Apnoea, "apnoea"}}}};
constexpr EnumNames<EventKind, 6> kEventKindNames{{{{EventKind::Change, "change"},
                                                   {EventKind::Sigh, "sigh"},
                                                   {EventKind::HoldStart, "hold start"},
                                                   {EventKind::HoldEnd, "hold end"},
                                                   {EventKind::ApnoeaStart, "apnoea start"},
                                                   {EventKind::ApnoeaEnd, "apnoea end"}}}};

}  // namespace

const char* to_string(BreathPhase phase) { return kBreathPhaseNames.name(phase); }

const char* to_string(EventKind kind) { return kEventKindNames.name(kind); }

BreathingDriver::BreathingDriver(Segment first) { segments_.push_back(first); }

Result<BreathingDriver> BreathingDriver::create(const BreathingParams& params) {
  Pattern pattern;
  pattern.params = params;
  if (Status e = solve(pattern); !e) return e.with_context("");
  Segment first;
  first.f0 = first.f1 = params.rate_bpm / 60.0;
  first.pattern = pattern;
  return BreathingDriver(first);
}

double BreathingDriver::phase_at(const Segment& s, double t) {
  const double dt = t - s.t0;
  if (s.ramp_s <= 0 || dt <= 0) return s.phi0 + (s.ramp_s <= 0 ? s.f1 : s.f0) * dt;
  // The integral of a smoothstep speed ramp: S(x) = x^3 - x^4/2 on [0, 1], then x - 1/2.
  const double x = dt / s.ramp_s;
  const double ramp = x < 1.0 ? x * x * x - 0.5 * x * x * x * x : x - 0.5;
  return s.phi0 + s.f0 * dt + (s.f1 - s.f0) * s.ramp_s * ramp;
}

double BreathingDriver::speed_at(const Segment& s, double t) {
  if (s.ramp_s <= 0) return s.f1;
  return s.f0 + (s.f1 - s.f0) * smoothstep((t - s.t0) / s.ramp_s);
}

double BreathingDriver::blend_weight(const Segment& s, double t) {
  if (s.from < 0 || s.blend_s <= 0) return 1.0;
  return smoothstep((t - s.blend_t0) / s.blend_s);
}

double BreathingDriver::settled_s() const {
  const Segment& s = segments_.back();
  return std::max(s.blend_t0 + s.blend_s, s.t0 + s.ramp_s);
}

std::size_t BreathingDriver::segment_at(double t) const {
  // The last segment starting at or before t (the first one also covers t < 0).
  auto it = std::upper_bound(segments_.begin(), segments_.end(), t,
                             [](double v, const Segment& s) { return v < s.t0; });
  return it == segments_.begin() ? 0 : static_cast<std::size_t>(it - segments_.begin()) - 1;
}

double BreathingDriver::correction_at(const Segment& s, double t) {
  if (s.correction.empty() || t < s.t0) return 0.0;
  const double x = (t - s.t0) / kLimiterStepS;
  const auto n = static_cast<std::size_t>(x);
  if (n + 1 >= s.correction.size()) return 0.0;  // the table ends where the correction has come back to zero
  const double f = x - static_cast<double>(n);
  return s.correction[n] + f * (s.correction[n + 1] - s.correction[n]);
}

BreathingSample BreathingDriver::at(double t) const {
  const std::size_t i = segment_at(t);
  BreathingSample out = raw_at(i, t);
  out.v_ml += correction_at(segments_[i], t);
  out.dv_ml = out.v_ml - out.v_frc_ml;
  return out;
}

BreathingSample BreathingDriver::raw_at(std::size_t i, double t) const {
  const Segment& seg = segments_[i];
  const double phi = phase_at(seg, t);
  BreathingSample out;
  out.t_s = t;
  // Walk the chain of fades: this segment's pattern with weight w, the rest of the chain with 1 - w.
  double carry = 1.0;
  for (std::ptrdiff_t j = static_cast<std::ptrdiff_t>(i); j >= 0;) {
    const Segment& s = segments_[static_cast<std::size_t>(j)];
    const double w = blend_weight(s, t);
    const PatternPoint pt = evaluate(s.pattern, phi);
    const double k = carry * w;
    out.p_cmh2o += k * pt.p_cmh2o;
    out.p_applied_cmh2o += k * pt.p_applied_cmh2o;
    out.v_ml += k * pt.v_ml;
    out.v_frc_ml += k * s.pattern.v_frc_ml;
    carry *= 1.0 - w;
    if (carry <= 0.0) break;
    j = s.from;
  }
  out.dv_ml = out.v_ml - out.v_frc_ml;
  const double breath = std::floor(phi);
  out.breath = static_cast<std::int64_t>(breath);
  if (seg.pattern.held) {
    out.phase = BreathPhase::Hold;
  } else if (seg.pattern.apnoea) {
    out.phase = BreathPhase::Apnoea;
  } else {
    out.phase = phi - breath < inspiratory_fraction(seg.pattern.params.ie_ratio) ? BreathPhase::Inspiration
                                                                                 : BreathPhase::Expiration;
  }
  return out;
}

double BreathingDriver::transition_for(const Pattern& from, const Pattern& to, double requested) const {
  const Difference diff = max_difference(from, to);
  if (diff.v_ml < 1e-6 && diff.p_cmh2o < 1e-9) return 0.0;  // the same waveform: nothing to fade
  const double minimum = requested >= 0 ? requested : 0.5 * 60.0 / to.params.rate_bpm;
  // A smoothstep fade of length T moves the volume by at most 1.5 diff / T per second; keep that under a
  // quarter of the faster pattern's peak flow, so the fade hides inside the breathing.
  const double flow = std::max(peak_flow_ml_per_s(from), peak_flow_ml_per_s(to));
  const double floor = flow > 0 ? 1.5 * diff.v_ml / (0.25 * flow) : 0.0;
  return std::max(minimum, floor);
}

Status BreathingDriver::apply(const Event& e) {
  const Segment& back = segments_.back();
  const std::string what = std::string(to_string(e.kind)) + " at " + number_text(e.t_s) + " s: ";
  if (!std::isfinite(e.t_s) || e.t_s < back.t0) {
    return fail(what + "expected a time at or after the last event (" + number_text(back.t0) + " s)");
  }
  if (!(e.transition_s < 0 || (std::isfinite(e.transition_s) && e.transition_s <= 600.0))) {
    return fail(what + "transition_s: expected [0, 600] s, got " + number_text(e.transition_s));
  }
  const double phi = phase_at(back, e.t_s);
  Pattern before = back.pattern;
  if (before.sigh_breath >= 0 && phi >= static_cast<double>(before.sigh_breath + 1)) before.sigh_breath = -1;
  Pattern to = before;  // a sigh that is over is forgotten
  bool rate_changed = false;
  switch (e.kind) {
    case EventKind::Change: {
      const PatternChange& c = e.change;
      BreathingParams& p = to.params;
      if (c.preset) p.preset = *c.preset;
      if (c.rate_bpm) rate_changed = *c.rate_bpm != p.rate_bpm, p.rate_bpm = *c.rate_bpm;
      if (c.ie_ratio) p.ie_ratio = *c.ie_ratio;
      if (c.tidal_volume_ml) p.tidal_volume_ml = *c.tidal_volume_ml;
      if (c.mode) p.mode = *c.mode;
      if (c.ventilator_tau_s) p.ventilator_tau_s = *c.ventilator_tau_s;
      if (c.peep_cmh2o) p.peep_cmh2o = *c.peep_cmh2o;
      if (p.mode == Mode::Ventilator) to.sigh_breath = -1;  // a pending sigh does not survive intubation
      break;
    }
    case EventKind::Sigh:
      to.sigh_breath = static_cast<std::int64_t>(std::floor(phi)) + 1;
      to.sigh_volume_ml = e.sigh_volume_ml > 0 ? e.sigh_volume_ml : 2.0 * to.params.tidal_volume_ml;
      if (!(std::isfinite(to.sigh_volume_ml) && to.sigh_volume_ml <= 3000.0)) {
        return fail(what + "volume_ml: expected (0, 3000] mL, got " + number_text(to.sigh_volume_ml));
      }
      break;
    case EventKind::HoldStart: to.held = true; break;
    case EventKind::HoldEnd: to.held = false; break;
    case EventKind::ApnoeaStart: to.apnoea = true; break;
    case EventKind::ApnoeaEnd: to.apnoea = false; break;
  }
  if (Status err = solve(to); !err) return fail(what + err.error());

  Segment s;
  s.t0 = e.t_s;
  s.phi0 = phi;
  s.f0 = speed_at(back, e.t_s);
  s.f1 = to.held ? 0.0 : to.params.rate_bpm / 60.0;
  if (s.f1 != s.f0) {
    const double rest_of_ramp = back.t0 + back.ramp_s - e.t_s;
    if (e.kind == EventKind::HoldStart || e.kind == EventKind::HoldEnd) {
      s.ramp_s = kHoldRampS;
    } else if (rate_changed) {
      s.ramp_s = e.transition_s >= 0 ? e.transition_s : 0.5 * 60.0 / to.params.rate_bpm;
    } else {
      s.ramp_s = std::max(rest_of_ramp, kHoldRampS);
    }
  }
  const double blend = e.kind == EventKind::Change || e.kind == EventKind::ApnoeaStart ||
                               e.kind == EventKind::ApnoeaEnd
                           ? transition_for(before, to, e.transition_s)
                           : 0.0;
  if (blend > 0) {
    s.blend_t0 = e.t_s;
    s.blend_s = blend;
    s.from = static_cast<std::ptrdiff_t>(segments_.size()) - 1;
  } else {
    // The waveform is the same now (a hold, a sigh to come, a spontaneous rate change): this segment takes the
    // place of the last one in whatever fade it was in.
    s.blend_t0 = back.blend_t0;
    s.blend_s = back.blend_s;
    s.from = back.from;
  }
  s.pattern = to;
  const double carried = correction_at(back, e.t_s);
  const double limit = kLimiterFlowShare * std::max(peak_flow_ml_per_s(before), peak_flow_ml_per_s(to));
  const double horizon = std::max(s.blend_t0 + s.blend_s, s.t0 + s.ramp_s);
  segments_.push_back(s);
  if (blend > 0 || carried != 0.0) limit_flow(carried, limit, horizon);
  return ok();
}

void BreathingDriver::limit_flow(double carried, double limit, double horizon) {
  // Follow the cross-faded volume, but never faster than `limit`: where the fade would add a step beyond the
  // steadiest breathing's largest, the output lags a little and catches up when the flow falls. The table holds
  // the difference (output - cross-fade) every kLimiterStepS from the segment's start until it is back to zero.
  Segment& s = segments_.back();
  const std::size_t i = segments_.size() - 1;
  const double step = limit * kLimiterStepS;
  const auto max_n = static_cast<std::size_t>((horizon - s.t0 + kLimiterMaxTailS) / kLimiterStepS);
  std::vector<double> table;
  double v = raw_at(i, s.t0).v_ml + carried;
  table.push_back(carried);
  for (std::size_t n = 1; n <= max_n; ++n) {
    const double t = s.t0 + static_cast<double>(n) * kLimiterStepS;
    const double target = raw_at(i, t).v_ml;
    v += std::clamp(target - v, -step, step);
    table.push_back(v - target);
    if (t >= horizon && std::abs(v - target) < 1e-9) break;
  }
  table.push_back(0.0);
  s.correction = std::move(table);
}

}  // namespace lungar::sim
