/// @file system_info.h
/// @brief What a benchmark's figures depend on, recorded beside them: CPU model, core count, load average, time.
#pragma once

#include <array>
#include <string>

namespace lungar::platform::bench {

struct SystemInfo {
  std::string cpu_model;             ///< /proc/cpuinfo "model name" (empty when unreadable)
  unsigned cores = 0;                ///< hardware threads the process may use
  std::array<double, 3> load_avg{};  ///< 1, 5 and 15 minute load averages (/proc/loadavg)
  std::string utc_time;              ///< ISO 8601, when read
};

SystemInfo read_system_info();

/// The 1-minute load average now; -1 when unreadable. Sampled around each measurement: the machine is shared.
double load_average_1min();

}  // namespace lungar::platform::bench
