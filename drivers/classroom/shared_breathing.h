/// @file shared_breathing.h
/// @brief A trainee's breathing clock: the instructor's breathing driver, rebuilt from the shared start
/// parameters and scenario events, evaluated at the instructor's time base through the estimated clock offset.
/// @ingroup platform
///
/// ΔV(t) is computed here from the shared time base, never from per-frame messages: a trainee breathes on when
/// the instructor goes away. The offset it applies follows the estimate smoothly (a quarter of the way per
/// exchange) so that estimator jitter never makes the lungs twitch; a jump larger than kStepNs (a first
/// estimate, a restarted instructor) is taken at once.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>

#include "config/base/result.h"
#include "sim/breathing/driver.h"

namespace lungar::classroom {

class SharedBreathing {
 public:
  static constexpr std::int64_t kStepNs = 5'000'000;

  /// The instructor's driver: `start`, then every event in order; or the line saying which event fails.
  static Result<sim::BreathingDriver> build(const sim::BreathingParams& start, std::span<const sim::Event> events);

  /// Replaces the driver and the time base (instructor's clock at breathing time 0). Sync thread.
  void install(sim::BreathingDriver driver, std::int64_t time_base_ns);
  /// Takes a new offset estimate (instructor clock minus this station's clock). Sync thread.
  void update_offset(std::int64_t estimate_ns);
  bool ready() const { return ready_.load(std::memory_order_acquire); }
  /// The offset applied now, ns.
  std::int64_t applied_offset_ns() const { return applied_ns_.load(std::memory_order_relaxed); }

  /// The breathing state at `station_ns`; false before install(). Allocates nothing (frame loop).
  bool sample_at(std::int64_t station_ns, sim::BreathingSample& out) const;
  /// The instructor's breathing time at `station_ns` (what its scenario's events are timed on); false before
  /// install().
  bool time_at(std::int64_t station_ns, double& t_s) const;

 private:
  mutable std::mutex mutex_;  ///< guards driver_ against install() while the frame evaluates it
  std::optional<sim::BreathingDriver> driver_;
  std::atomic<std::int64_t> time_base_ns_{0};
  std::atomic<std::int64_t> applied_ns_{0};
  std::atomic<bool> ready_{false};
  bool have_offset_ = false;
};

}  // namespace lungar::classroom
