/// @file run_limit.cpp
/// @brief The run's length and its log line.
#include "platform/app/run_limit.h"

#include <cstdio>

namespace lungar::platform {

namespace {

constexpr double kDemoSeconds = 10.0;

}  // namespace

double run_limit_s(const RuntimeOptions& o, const config::Scenario* scenario) {
  if (o.seconds) return *o.seconds;
  if (scenario != nullptr) return scenario->duration_s;
  return o.frames ? 0.0 : kDemoSeconds;
}

std::string describe_limit(const RuntimeOptions& o, const config::Scenario* scenario) {
  const double limit_s = run_limit_s(o, scenario);
  char limit[96];
  if (o.frames && limit_s > 0) {
    std::snprintf(limit, sizeof limit, "%ld frames or %.1f s", *o.frames, limit_s);
  } else if (o.frames) {
    std::snprintf(limit, sizeof limit, "%ld frames", *o.frames);
  } else if (limit_s > 0) {
    std::snprintf(limit, sizeof limit, "%.1f s", limit_s);
  } else {
    std::snprintf(limit, sizeof limit, "until stopped");
  }
  std::string why;
  if (!o.seconds && scenario != nullptr) {
    why = ", the scenario " + (scenario->name.empty() ? scenario->source : scenario->name) +
          "'s length (--seconds changes it)";
  }
  return std::string("running ") + limit + why + " (Ctrl-C stops)";
}

}  // namespace lungar::platform
