/// @file system_info.cpp
/// @brief Reads /proc/cpuinfo and /proc/loadavg (Linux); missing files leave the fields empty, never fail.
#include "platform/bench/system_info.h"

#include "config/base/clock.h"

#include <fstream>
#include <thread>

namespace lungar::platform::bench {

double load_average_1min() {
  std::ifstream f("/proc/loadavg");
  double one = -1;
  if (!(f >> one)) return -1;
  return one;
}

SystemInfo read_system_info() {
  SystemInfo info;
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      const auto start = colon == std::string::npos ? colon : line.find_first_not_of(" \t", colon + 1);
      if (start != std::string::npos) info.cpu_model = line.substr(start);
      break;
    }
  }
  info.cores = std::thread::hardware_concurrency();
  std::ifstream load("/proc/loadavg");
  load >> info.load_avg[0] >> info.load_avg[1] >> info.load_avg[2];
  info.utc_time = utc_timestamp();
  return info;
}

}  // namespace lungar::platform::bench
