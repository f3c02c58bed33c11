/// @file physiology_sample.h
/// @brief What lungar takes from a mannequin's physiology engine (AMM) or a ventilator (OpenICE) over DDS, and
///        what it drops: each waveform sample checked on the thread that reads it, before the frame sees it.
///
/// A sample is dropped, and counted under its reason, when its value is not finite, a volume is negative, its unit
/// is not one lungar knows for its quantity, its rate is absurd (an array's sampling frequency outside
/// [kMinFrequencyHz, kMaxFrequencyHz], a volume changing faster than kMaxVolumeRateMlPerS), or its time runs
/// backwards. Waveforms lungar does not follow (a heart rate, another metric) are ignored, not dropped.
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "config/base/enum_names.h"

namespace lungar::breath::physiology {

/// What a sample measures: the whole breath, or one lung.
enum class Channel : std::uint8_t { breath, left_lung, right_lung };
inline constexpr std::size_t kChannels = 3;

/// The quantity, in lungar's units.
enum class Quantity : std::uint8_t { volume_ml, flow_ml_per_s, pressure_cmh2o };
inline constexpr EnumNames<Quantity, 3> kQuantityNames{
    {{{Quantity::volume_ml, "volume"}, {Quantity::flow_ml_per_s, "flow"}, {Quantity::pressure_cmh2o, "pressure"}}}};

enum class Drop : std::uint8_t { not_finite, negative_volume, unit, rate, time };
inline constexpr std::size_t kDropReasons = 5;
inline constexpr EnumNames<Drop, kDropReasons> kDropNames{{{{Drop::not_finite, "not_finite"},
                                                            {Drop::negative_volume, "negative_volume"},
                                                            {Drop::unit, "unit"},
                                                            {Drop::rate, "rate"},
                                                            {Drop::time, "time"}}}};

/// Sampling frequencies of a waveform array lungar believes (a ventilator samples at 25 to 200 Hz).
inline constexpr double kMinFrequencyHz = 1.0, kMaxFrequencyHz = 1000.0;
/// Faster than this no lung fills or empties (a cough peaks near 12 L/s).
inline constexpr double kMaxVolumeRateMlPerS = 20000.0;

struct Sample {
  double t_s = 0;    ///< on the source's clock: AMM's simulation time, the ventilator's device time
  double value = 0;  ///< in lungar's unit for `quantity`
  Channel channel = Channel::breath;
  Quantity quantity = Quantity::volume_ml;
};

/// AMM's BioGears lung-volume nodes and the channel each moves; nullopt for a node lungar does not follow.
std::optional<Channel> amm_channel(std::string_view name);

/// An AMM PhysiologyWaveform sample's checks, with what they remember of the samples before (each channel's last
/// time and volume).
class AmmChecks {
 public:
  /// The sample (a lung volume in mL, at simulation_time in s), or why it is dropped; nullopt for a node lungar
  /// does not follow.
  std::optional<Sample> check(std::string_view name, std::string_view unit, std::int64_t simulation_time_ms,
                              double value, const std::function<void(Drop)>& dropped);

 private:
  std::array<double, kChannels> last_t_{-std::numeric_limits<double>::infinity(),
                                        -std::numeric_limits<double>::infinity(),
                                        -std::numeric_limits<double>::infinity()};
  std::array<double, kChannels> last_ml_{};
};

/// OpenICE's metric id for a quantity: MDC_VOL_AWAY_TIDAL, MDC_FLOW_AWAY, MDC_PRESS_AWAY.
const char* openice_metric(Quantity q);

/// One ice::SampleArray, as lungar reads it.
struct OpenIceArray {
  std::string_view metric_id, unit_id;
  std::int32_t frequency_hz = 0;
  std::span<const float> values;
  double end_s = 0;  ///< the last value's time (the device's clock)
};

/// The checks of the arrays of one followed metric.
class OpenIceChecks {
 public:
  explicit OpenIceChecks(Quantity followed) : followed_(followed) {}
  /// Calls `keep` for each of the array's samples that passes (the breath's channel, times spaced by the
  /// frequency and ending at end_s) and `dropped` for each refused value or whole array; an array of another
  /// metric is ignored.
  void check(const OpenIceArray& a, const std::function<void(const Sample&)>& keep,
             const std::function<void(Drop)>& dropped);

 private:
  Quantity followed_;
  double last_end_s_ = -std::numeric_limits<double>::infinity();
};

}  // namespace lungar::breath::physiology
