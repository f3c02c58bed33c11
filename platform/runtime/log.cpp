/// @file log.cpp
/// @brief Wall-clock timestamps for log lines, so a trainer can match them with what happened in the room.
#include "platform/runtime/log.h"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace lungar::platform {

void log_line(const std::string& message) {
  const auto now = std::chrono::system_clock::now();
  const std::time_t secs = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  localtime_r(&secs, &tm);
  std::fprintf(stderr, "%02d:%02d:%02d.%03d lungar: %s\n", tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms),
               message.c_str());
}

}  // namespace lungar::platform
