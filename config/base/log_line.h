/// @file log_line.h
/// @brief The one log-line format, for every tool: "HH:MM:SS.mmm TOOL: message" on stderr, local wall-clock time,
/// so a trainer can match a line with what happened in the room.
/// @ingroup base
#pragma once

#include <cstdio>
#include <ctime>
#include <string>
#include <string_view>

namespace lungar {

/// The line as it is printed, without the newline.
inline std::string format_log_line(std::string_view tool, std::string_view message) {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  std::tm tm{};
  localtime_r(&ts.tv_sec, &tm);
  char stamp[16];
  std::snprintf(stamp, sizeof stamp, "%02d:%02d:%02d.%03d", tm.tm_hour, tm.tm_min, tm.tm_sec,
                static_cast<int>(ts.tv_nsec / 1'000'000));
  std::string line(stamp);
  line.append(" ").append(tool).append(": ").append(message);
  return line;
}

/// Prints one timestamped line on stderr (one fputs, so lines from two threads do not interleave).
inline void log_line(std::string_view tool, std::string_view message) {
  const std::string line = format_log_line(tool, message) + "\n";
  std::fputs(line.c_str(), stderr);
}

}  // namespace lungar
