/// @file doctor.h
/// @brief `lungar doctor`: runs every check against the settings the runtime would use and prints one line each.
/// @ingroup platform
#pragma once

#include <string>
#include <vector>

#include "platform/doctor/doctor_check.h"
#include "platform/app/runtime_options.h"

namespace lungar::platform::doctor {

/// Every check, in the order a lab engineer fixes things: config, graphics, output, tracker, asset, disk; against
/// the settings the runtime would run with these options (`o.config_paths`' files, then the options given on the
/// command line over it, as the runtime applies them). An option the runtime would refuse is a failed check first.
std::vector<Check> run_checks(const RuntimeOptions& o, const DoctorEnv& env);
/// The same with no option but the settings file.
std::vector<Check> run_checks(const std::string& config_path, const DoctorEnv& env);

/// Prints the checks on stdout; 0 when none failed (warnings allowed), 1 otherwise.
int run_doctor(const RuntimeOptions& o);

}  // namespace lungar::platform::doctor
