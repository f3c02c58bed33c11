/// @file checks.h
/// @brief The checks of `lungar doctor`, one function each; every one returns a Check and never throws or exits.
/// @ingroup platform
#pragma once

#include "config/base/result.h"
#include "config/config_paths.h"
#include "platform/app/settings.h"
#include "platform/doctor/doctor_check.h"

namespace lungar::platform::doctor {

/// The settings file the runtime would use, and whether it parses.
Check check_config(const config::ConfigChoice& choice, const Result<Settings>& loaded);
/// EGL and OpenGL ES: versions (ES 3.0 needed) and the renderer; software rendering (llvmpipe) is a warning.
Check check_gles();
/// The configured output: an X display for a window, the named X output for full screen, an OpenXR runtime for
/// display.output = "openxr".
Check check_output(const Settings& s, const DoctorEnv& env);
/// The active OpenXR runtime, found the way the OpenXR loader finds it (XR_RUNTIME_JSON, then XDG config folders,
/// then /etc), without loading OpenXR.
Check check_openxr_runtime(const DoctorEnv& env);
/// The configured tracker: for HID, the device node present and readable by this user; a missing udev rule gives
/// the command that installs one.
Check check_tracker(const drivers::TrackerConfig& t, const DoctorEnv& env);
/// The configured asset loads (or the demo asset's cache is usable or can be made; `procedural`: the procedural
/// pair's, as --procedural draws it).
Check check_asset(const Settings& s, const DoctorEnv& env, bool procedural = false);
/// The classroom: not in one, open (a warning: anyone on the network can join), or secure with a complete station
/// folder (sync.security) and Cyclone's security plugins installed.
Check check_classroom(const Settings& s);
/// Free space where snapshots, stats and recordings go ($XDG_STATE_HOME/lungar).
Check check_disk(const DoctorEnv& env);

}  // namespace lungar::platform::doctor
