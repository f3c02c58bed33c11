/// @file number_text.h
/// @brief A number as lungar's messages print it.
/// @ingroup base
#pragma once

#include <cstdio>
#include <string>

namespace lungar {

/// `v` with `digits` significant digits in %g's shortest form (0.5, 300, 1e-06), as std::ostream prints it at
/// that precision.
inline std::string number_text(double v, int digits = 6) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

}  // namespace lungar
