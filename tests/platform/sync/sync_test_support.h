/// @file sync_test_support.h
/// @brief Test support for the classroom: the loopback Cyclone XML, a DDS domain id and a classroom name of
/// this test process's own (so parallel ctest runs never meet), and a temporary folder.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace lungar::testing {

inline const std::string kLoopbackXml = std::string(LUNGAR_SOURCE_DIR) + "/config/cyclonedds/loopback-tests.xml";

/// A domain id in [1, 230] from the process id: two test processes running at once rarely share one, and
/// when they do their classrooms (below) still keep them apart.
inline std::uint32_t test_domain() { return 1 + static_cast<std::uint32_t>(getpid()) % 230; }
/// A classroom name unique to this process and `tag`.
inline std::string test_classroom(const std::string& tag) { return tag + "-" + std::to_string(getpid()); }

inline std::filesystem::path test_dir(const std::string& tag) {
  auto dir = std::filesystem::temp_directory_path() / ("lungar_sync_" + tag + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lungar::testing
