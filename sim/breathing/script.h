/// @file script.h
/// @brief A whole breathing script: the starting parameters, timed events and the patient's orientation track,
///        ready to run. Built by platform/scenario_adapter from a scenario file, or by hand in tests.
#pragma once

#include <vector>

#include "sim/breathing/driver.h"
#include "sim/breathing/orientation.h"

namespace lungar::sim {

struct BreathingScript {
  BreathingDriver driver;        ///< every event already applied: driver.at(t) for any t
  OrientationTrack orientation;  ///< orientation.at(t)
  double duration_s = 60.0;      ///< how long the script is meant to run
  BreathingParams start;         ///< what the driver started from (a classroom shares start and events)
  std::vector<Event> events;     ///< every event applied, in order
};

}  // namespace lungar::sim
