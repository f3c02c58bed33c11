/// @file scenario_patient.h
/// @brief A simulated patient's turns as a PoseSource: the patient's orientation follows a track over breathing
/// time (a teaching scenario's, or the one the instructor's console turns), everything else (head, positions,
/// counters) comes from the wrapped source. Used with the mock tracker, where no real patient is there to turn.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "platform/runtime/pose_source.h"
#include "sim/breathing/script.h"

namespace lungar::platform {

/// The simulated patient's orientation (lung -> world) at breathing time t_s. Read by the frame: allocates nothing,
/// never waits.
class PatientTrack {
 public:
  virtual ~PatientTrack() = default;
  virtual Eigen::Quaterniond orientation_at(double t_s) const = 0;
  /// Who turns the patient ("the scenario"), for the log.
  virtual std::string turned_by() const = 0;
};

/// A scenario's or a breathing script's turns, fixed for the run.
class ScriptTrack final : public PatientTrack {
 public:
  explicit ScriptTrack(std::shared_ptr<const sim::BreathingScript> script) : script_(std::move(script)) {}
  Eigen::Quaterniond orientation_at(double t_s) const override { return script_->orientation.at(t_s); }
  std::string turned_by() const override { return "the scenario"; }

 private:
  std::shared_ptr<const sim::BreathingScript> script_;
};

class ScenarioPatient final : public PoseSource {
 public:
  ScenarioPatient(std::unique_ptr<PoseSource> inner, std::shared_ptr<const PatientTrack> track, std::int64_t t0_ns)
      : inner_(std::move(inner)), track_(std::move(track)), t0_ns_(t0_ns) {}

  std::string describe() const override { return inner_->describe() + ", patient turned by " + track_->turned_by(); }
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
  std::shared_ptr<const PatientTrack> track_;
  std::int64_t t0_ns_;
};

}  // namespace lungar::platform
