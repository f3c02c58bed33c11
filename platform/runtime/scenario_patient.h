/// @file scenario_patient.h
/// @brief A teaching scenario's patient turns as a PoseSource: the patient's orientation follows the scenario's
/// track from the run's start, everything else (head, positions, counters) comes from the wrapped source. Used
/// with the mock tracker, where no real patient is there to turn.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <memory>

#include "platform/runtime/pose_source.h"
#include "sim/breathing/script.h"

namespace lungar::platform {

class ScenarioPatient final : public PoseSource {
 public:
  ScenarioPatient(std::unique_ptr<PoseSource> inner, std::shared_ptr<const sim::BreathingScript> script,
                  std::int64_t t0_ns)
      : inner_(std::move(inner)), script_(std::move(script)), t0_ns_(t0_ns) {}

  std::string describe() const override { return inner_->describe() + ", patient turned by the scenario"; }
  drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const override;
  drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const override;
  const char* state() const override { return inner_->state(); }
  bool finished() const override { return inner_->finished(); }
  SourceCounters counters(double wall_s) const override { return inner_->counters(wall_s); }
  void add_stats(nlohmann::json& stats, double wall_s) const override { inner_->add_stats(stats, wall_s); }
  void stop() override { inner_->stop(); }

 private:
  drivers::PoseSample turned(drivers::PoseSample s, std::int64_t t_ns) const;
  std::unique_ptr<PoseSource> inner_;
  std::shared_ptr<const sim::BreathingScript> script_;
  std::int64_t t0_ns_;
};

}  // namespace lungar::platform
