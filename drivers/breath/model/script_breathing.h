/// @file script_breathing.h
/// @brief The model (`[breathing] source = "model"`, no `--breath`): this station's own breathing script (steady
/// breathing, or a scenario's events) run from the run's start on the monotonic clock.
/// @ingroup breath
#pragma once

#include <cstdint>
#include <memory>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "drivers/breath/source/breathing_clock.h"
#include "sim/breathing/script.h"

namespace lungar::breath {

class ScriptBreathing final : public BreathingClock {
 public:
  ScriptBreathing(std::shared_ptr<const sim::BreathingScript> script, std::int64_t t0_ns)
      : script_(std::move(script)), t0_ns_(t0_ns) {}
  sim::BreathingSample at(std::int64_t now_ns) const override {
    return script_->driver.at(seconds_between(t0_ns_, now_ns));
  }
  const sim::Pattern* pattern_at(std::int64_t now_ns) const override {
    return &script_->driver.pattern_at(seconds_between(t0_ns_, now_ns));
  }
  /// The preset the script starts with (a pathology may have chosen it), and its time constant R C.
  void add_stats(nlohmann::json& stats) const override {
    stats["breathing_preset"] = std::string(sim::to_string(script_->start.preset));
  }

 private:
  std::shared_ptr<const sim::BreathingScript> script_;
  std::int64_t t0_ns_;
};

}  // namespace lungar::breath
