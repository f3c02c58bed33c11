/// @file log.h
/// @brief The runtime's log lines: config/base/log_line.h's one format with the tool name "lungar".
/// @ingroup platform
#pragma once

#include <string>

#include "config/base/log_line.h"

namespace lungar::platform {

inline void log_line(const std::string& message) { lungar::log_line("lungar", message); }

}  // namespace lungar::platform
