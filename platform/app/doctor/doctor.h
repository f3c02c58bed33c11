/// @file doctor.h
/// @brief `lungar doctor`: runs every check against the settings the runtime would use and prints one line each.
/// @ingroup platform
#pragma once

#include <string>
#include <vector>

#include "platform/app/doctor/doctor_check.h"

namespace lungar::platform::doctor {

/// Every check, in the order a lab engineer fixes things: config, graphics, output, tracker, asset, disk.
std::vector<Check> run_checks(const std::string& config_path, const DoctorEnv& env);

/// Prints the checks on stdout; 0 when none failed (warnings allowed), 1 otherwise.
int run_doctor(const std::string& config_path);

}  // namespace lungar::platform::doctor
