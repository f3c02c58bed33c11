/// @file breath_trace.h
/// @brief Recorded respiratory surrogates for the breath follower (breath_follower.h): CSV with the header
///        `t_s,value` (a scalar, inhale up: a belt, a spirometer, an RPM amplitude exported) or `t_s,x_mm,y_mm,z_mm`
///        (a chest or abdomen marker). A marker is reduced to its excursion along its main breathing axis: the
///        principal axis of its positions over the first 30 s, signed so that inhalation, the shorter of the two
///        phases in quiet breathing, goes up.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::sim {

struct TraceSample {
  double t_s = 0;
  double value = 0;
};

struct BreathTrace {
  std::vector<TraceSample> samples;  ///< time zero is the file's first sample
  bool marker = false;               ///< read from x, y, z (projected on its axis)
};

/// Reads the CSV; the error is one line naming the file, the line and what was expected (times must increase).
Result<BreathTrace> read_breath_trace(const std::string& path);

}  // namespace lungar::sim
