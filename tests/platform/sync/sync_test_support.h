/// @file sync_test_support.h
/// @brief Test support for the classroom: the loopback Cyclone XML, a DDS domain id and a classroom name of
/// this test process's own (so parallel ctest runs never meet), a temporary folder, the realtime clock, a sleep.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <string>
#include <thread>

namespace lungar::testing {

inline const std::string kLoopbackXml = std::string(LUNGAR_SOURCE_DIR) + "/config/cyclonedds/loopback-tests.xml";

/// A domain id in [1, 230] from the process id: two test processes running at once rarely share one, and
/// when they do their classrooms (below) still keep them apart.
inline std::uint32_t test_domain() { return 1 + static_cast<std::uint32_t>(getpid()) % 230; }
/// A classroom name unique to this process and `tag`.
inline std::string test_classroom(const std::string& tag) { return tag + "-" + std::to_string(getpid()); }

/// CLOCK_REALTIME in ns: the clock of a station's sync_transitions (and of a test that kills one).
inline std::int64_t realtime_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

inline void sleep_s(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

inline std::filesystem::path test_dir(const std::string& tag) {
  auto dir = std::filesystem::temp_directory_path() / ("lungar_sync_" + tag + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lungar::testing
