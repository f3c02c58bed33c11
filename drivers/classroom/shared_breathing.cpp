/// @file shared_breathing.cpp
/// @brief Rebuilding the instructor's driver, and the trainee's breathing time through the applied offset.
#include "drivers/classroom/shared_breathing.h"

#include <cstdlib>

namespace lungar::classroom {

Result<sim::BreathingDriver> SharedBreathing::build(const sim::BreathingParams& start,
                                                    std::span<const sim::Event> events) {
  auto created = sim::BreathingDriver::create(start);
  if (!created) return created.with_context("lungar_breathing_state: ");
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (Status e = created->apply(events[i]); !e) {
      return e.with_context("lungar_scenario_events: events[" + std::to_string(i) + "]: ");
    }
  }
  return created.take();
}

void SharedBreathing::install(sim::BreathingDriver driver, std::int64_t time_base_ns) {
  std::optional<sim::BreathingDriver> old;  // freed outside the lock: the frame never waits on free()
  {
    std::lock_guard lock(mutex_);
    old = std::move(driver_);
    driver_.emplace(std::move(driver));
    time_base_ns_.store(time_base_ns, std::memory_order_relaxed);
  }
  ready_.store(true, std::memory_order_release);
}

void SharedBreathing::update_offset(std::int64_t estimate_ns) {
  const std::int64_t applied = applied_ns_.load(std::memory_order_relaxed);
  const std::int64_t error = estimate_ns - applied;
  if (!have_offset_ || std::llabs(error) > kStepNs) {
    applied_ns_.store(estimate_ns, std::memory_order_relaxed);
    have_offset_ = true;
  } else {
    applied_ns_.store(applied + error / 4, std::memory_order_relaxed);
  }
}

bool SharedBreathing::sample_at(std::int64_t station_ns, sim::BreathingSample& out) const {
  std::lock_guard lock(mutex_);
  double t_s = 0;
  if (!driver_ || !time_at(station_ns, t_s)) return false;
  out = driver_->at(t_s);
  return true;
}

bool SharedBreathing::time_at(std::int64_t station_ns, double& t_s) const {
  if (!ready()) return false;
  const std::int64_t instructor_ns = station_ns + applied_ns_.load(std::memory_order_relaxed);
  t_s = static_cast<double>(instructor_ns - time_base_ns_.load(std::memory_order_relaxed)) * 1e-9;
  return true;
}

}  // namespace lungar::classroom
