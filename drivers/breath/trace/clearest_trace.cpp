/// @file clearest_trace.cpp
/// @brief The clearest of several recordings (clearest_trace.h).
#include "drivers/breath/trace/clearest_trace.h"

#include <cstdio>

#include "drivers/breath/breath_factory/breath_factory.h"
#include "sim/breathing/breath_clarity.h"
#include "sim/breathing/breath_trace.h"

namespace lungar::breath {

Result<std::string> clearest_trace(const std::vector<std::string>& paths, std::string& said) {
  std::vector<sim::BreathTrace> traces;
  for (const std::string& path : paths) {
    if (breath_kind(path) != BreathKind::Trace)
      return Error{"several sources are compared only as recordings, got '" + path + "'"};
    auto trace = sim::read_breath_trace(path);
    if (!trace) return Error{trace.error()};
    traces.push_back(trace.take());
  }
  std::vector<double> clarity;
  const std::size_t best = sim::clearest_breathing(traces, &clarity);
  std::string others;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    char share[32];
    std::snprintf(share, sizeof share, "%.2f", clarity[i]);
    if (i != best) others += (others.empty() ? "" : ", ") + paths[i] + " " + share;
  }
  char line[160];
  std::snprintf(line, sizeof line, ", the clearest breathing of %zu (its share of power at 6-42/min over the first 60 s: %.2f; ",
                paths.size(), clarity[best]);
  said = "following " + paths[best] + line + others + ")";
  return paths[best];
}

}  // namespace lungar::breath
