/// @file xr_test_runtime.h
/// @brief The OpenXR runtime the tests run against: Monado, built by scripts/setup-openxr, loaded in-process through
/// XR_RUNTIME_JSON, with its null compositor (no display, 20 Hz) and a simulated head, moving or fixed.
///
/// Monado reads its environment once per process, so every test that makes an instance runs in its own process
/// (ctest runs each test so; run one at a time with --gtest_filter when running the executable by hand).
#pragma once

#include <string>

namespace lungar::test {

enum class SimulatedHead {
  Moving,  ///< SIMULATED_ENABLE=1: the simulated HMD wobbles (a few cm, a few degrees, over seconds)
  Fixed,   ///< P_OVERRIDE_ACTIVE_CONFIG=remote: the remote-driver HMD, which stays put (repeatable pictures)
};

/// Points XR_RUNTIME_JSON at scripts/setup-openxr's Monado unless it is set already, and sets Monado's variables
/// for a display-less run. Returns the manifest in use; empty (with a test failure that says how to build it)
/// when the file is missing.
std::string use_test_runtime(SimulatedHead head);

}  // namespace lungar::test
