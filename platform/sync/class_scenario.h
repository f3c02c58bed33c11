/// @file class_scenario.h
/// @brief A scenario the instructor's console runs on a class already going: its steps on the scenario's own time
///        (breathing events, pathologies coming and going, the patient's turns), the state it has brought the
///        class to by any time of it, and its steps from there on shifted onto the class's breathing time.
///        ClassControl starts, pauses, jumps and stops it (class_control.h).
/// @ingroup platform
///
/// Why a state and the steps after it: to start a scenario, or to jump to one of its events, the class is first
/// brought to where the scenario stands at that time (its breathing, its pathologies, the patient's posture: a
/// class that was breathing otherwise goes over smoothly), then the scenario's own steps follow from there. A jump
/// back or forth is the same operation at another time.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "config/base/result.h"
#include "config/scenario.h"
#include "sim/breathing/event.h"
#include "sim/breathing/orientation.h"
#include "sim/breathing/pattern.h"
#include "sim/breathing/script.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::platform::sync {

/// Where a scenario has brought the class by one of its times.
struct ScenarioState {
  sim::BreathingParams params;
  std::vector<std::string> pathologies;  ///< present (one on its way counts), in the order they came
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// One of the scenario's events as the console lists it, to jump to.
struct ScenarioCue {
  double t_s = 0;  ///< scenario time
  std::string kind;
  std::string text;
};

/// Steps a scenario gives the class, on the class's breathing time.
struct ClassSteps {
  std::vector<sim::Event> breath;
  std::vector<sim::PathologyEvent> lungs;
  std::vector<sim::Turn> turns;

  bool empty() const { return breath.empty() && lungs.empty() && turns.empty(); }
};

class ClassScenario {
 public:
  /// A loaded scenario file and its script (platform/app/scenario_adapter.h makes it, with the errors that name the
  /// file and the event); an error when its pathologies' course does not hold (a removal of what is not there).
  static Result<ClassScenario> create(const config::Scenario& scenario, const sim::BreathingScript& script);

  const std::string& name() const { return name_; }
  const std::string& file() const { return file_; }
  const std::string& description() const { return description_; }
  double duration_s() const { return duration_s_; }
  const std::vector<ScenarioCue>& cues() const { return cues_; }

  /// The scenario's start, then every step before scenario time t_s.
  ScenarioState state_before(double t_s) const;
  /// The steps at scenario time t_s and after, shifted by `offset_s` onto class time. The end of a breath hold or
  /// an apnoea that began before t_s is left out: the class is not holding it.
  ClassSteps steps_from(double t_s, double offset_s) const;

 private:
  ClassScenario() = default;

  std::string name_, file_, description_;
  double duration_s_ = 0;
  sim::BreathingParams start_;
  std::vector<sim::Event> breath_;  ///< scenario time, in order
  sim::PathologyTimeline lungs_;    ///< its start and events, scenario time
  sim::OrientationTrack turns_;     ///< the start pose and the turns
  std::vector<ScenarioCue> cues_;
};

}  // namespace lungar::platform::sync
