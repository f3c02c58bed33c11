/// @file xr_test_runtime.cpp
/// @brief Environment for the in-process Monado runtime.
#include "tests/platform/openxr/xr_test_runtime.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace lungar::test {

std::string use_test_runtime(SimulatedHead head) {
  setenv("XR_RUNTIME_JSON", LUNGAR_XR_RUNTIME_JSON, /*overwrite=*/0);
  const std::string json = std::getenv("XR_RUNTIME_JSON");
  if (!std::filesystem::exists(json)) {
    ADD_FAILURE() << "XR_RUNTIME_JSON=" << json << ": no such runtime manifest; run scripts/setup-openxr";
    return {};
  }
  setenv("XRT_COMPOSITOR_NULL", "1", 1);  // no display: Monado's null compositor (20 Hz)
  setenv("XRT_NO_STDIN", "1", 1);         // ctest's stdin is no terminal
  setenv("XRT_LOG", "warning", 0);
  if (head == SimulatedHead::Moving) {
    setenv("SIMULATED_ENABLE", "1", 1);
  } else {
    setenv("P_OVERRIDE_ACTIVE_CONFIG", "remote", 1);
  }
  return json;
}

}  // namespace lungar::test
