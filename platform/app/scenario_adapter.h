/// @file scenario_adapter.h
/// @brief Turns config's breathing settings and scenario files into a ready-to-run sim::BreathingScript.
///
/// Per frame the runtime then calls script.driver.at(t) (P, V, dV) and script.orientation.at(t) (the patient's
/// orientation as a lung -> world quaternion; sim::gravity_in_lung_frame gives g-hat), both allocation-free.
#pragma once

#include <optional>
#include <string>

#include "config/base/result.h"
#include "config/scenario.h"
#include "config/breathing_settings.h"
#include "sim/breathing/script.h"

namespace lungar::platform {

/// Every event of `scenario` applied; errors the loader cannot see (e.g. a tidal volume beyond the curve's
/// reach) come back as "FILE:LINE: key 'event[i]': ...".
Result<sim::BreathingScript> make_breathing_script(const config::Scenario& scenario);

/// The config's [breathing]: its scenario file when one is set (missing [start] keys take the config's values),
/// else steady breathing, upright, lasting `duration_s`.
Result<sim::BreathingScript> load_breathing_script(const config::BreathingSettings& breathing,
                                                   double duration_s = 60.0);

/// Breathing parameters from the config's names.
Result<sim::BreathingParams> to_breathing_params(const config::BreathingSettings& b);

}  // namespace lungar::platform
