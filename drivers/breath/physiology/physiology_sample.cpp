/// @file physiology_sample.cpp
/// @brief The checks of AMM and OpenICE waveform samples (physiology_sample.h).
#include "drivers/breath/physiology/physiology_sample.h"

#include <cmath>

namespace lungar::breath::physiology {

namespace {

/// Each quantity's metric, as OpenICE names it (IEEE 11073 MDC).
constexpr EnumNames<Quantity, 3> kOpenIceMetrics{{{{Quantity::volume_ml, "MDC_VOL_AWAY_TIDAL"},
                                                   {Quantity::flow_ml_per_s, "MDC_FLOW_AWAY"},
                                                   {Quantity::pressure_cmh2o, "MDC_PRESS_AWAY"}}}};

/// The factor to lungar's unit of `q` for a unit as OpenICE names it (IEEE 11073 MDC), or nullopt.
std::optional<double> openice_unit_factor(Quantity q, std::string_view unit) {
  switch (q) {
    case Quantity::volume_ml:
      if (unit == "MDC_DIM_MILLI_L") return 1.0;
      if (unit == "MDC_DIM_L") return 1000.0;
      break;
    case Quantity::flow_ml_per_s:
      if (unit == "MDC_DIM_L_PER_MIN") return 1000.0 / 60.0;
      if (unit == "MDC_DIM_MILLI_L_PER_SEC") return 1.0;
      break;
    case Quantity::pressure_cmh2o:
      if (unit == "MDC_DIM_CM_H2O") return 1.0;
      if (unit == "MDC_DIM_HECTO_PASCAL") return 1.0197;
      break;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Channel> amm_channel(std::string_view name) {
  if (name == "Respiratory_LungTotal_Volume") return Channel::breath;
  if (name == "Respiratory_LeftLung_Volume") return Channel::left_lung;
  if (name == "Respiratory_RightLung_Volume") return Channel::right_lung;
  return std::nullopt;
}

std::optional<Sample> AmmChecks::check(std::string_view name, std::string_view unit, std::int64_t simulation_time_ms,
                                       double value, const std::function<void(Drop)>& dropped) {
  const std::optional<Channel> channel = amm_channel(name);
  if (!channel) return std::nullopt;
  const double factor = unit == "mL" ? 1.0 : unit == "L" ? 1000.0 : 0.0;
  const double t = static_cast<double>(simulation_time_ms) / 1000.0;
  const double ml = value * factor;
  const auto c = static_cast<std::size_t>(*channel);
  std::optional<Drop> why;
  if (!std::isfinite(value))
    why = Drop::not_finite;
  else if (factor == 0.0)
    why = Drop::unit;
  else if (value < 0)
    why = Drop::negative_volume;
  else if (t < last_t_[c])
    why = Drop::time;
  else if (t > last_t_[c] && std::abs(ml - last_ml_[c]) > kMaxVolumeRateMlPerS * (t - last_t_[c]))
    why = Drop::rate;
  if (why) {
    dropped(*why);
    return std::nullopt;
  }
  last_t_[c] = t;
  last_ml_[c] = ml;
  return Sample{t, ml, *channel, Quantity::volume_ml};
}

const char* openice_metric(Quantity q) { return kOpenIceMetrics.name(q); }

void OpenIceChecks::check(const OpenIceArray& a, const std::function<void(const Sample&)>& keep,
                          const std::function<void(Drop)>& dropped) {
  if (a.metric_id != openice_metric(followed_) || a.values.empty()) return;
  const std::optional<double> factor = openice_unit_factor(followed_, a.unit_id);
  if (!factor) return dropped(Drop::unit);
  if (!(a.frequency_hz >= kMinFrequencyHz && a.frequency_hz <= kMaxFrequencyHz)) return dropped(Drop::rate);
  if (!std::isfinite(a.end_s) || a.end_s <= last_end_s_) return dropped(Drop::time);
  last_end_s_ = a.end_s;
  const double dt = 1.0 / a.frequency_hz;
  const std::size_t n = a.values.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double v = static_cast<double>(a.values[i]) * *factor;
    if (!std::isfinite(v))
      dropped(Drop::not_finite);
    else if (followed_ == Quantity::volume_ml && v < 0)
      dropped(Drop::negative_volume);
    else
      keep({a.end_s - static_cast<double>(n - 1 - i) * dt, v, Channel::breath, followed_});
  }
}

}  // namespace lungar::breath::physiology
