/// @file log.h
/// @brief Timestamped log lines on stderr: "HH:MM:SS.mmm lungar: message".
#pragma once

#include <string>

namespace lungar::platform {

void log_line(const std::string& message);

}  // namespace lungar::platform
