/// @file pathology_timeline.cpp
/// @brief The timeline's checks, shared by a scenario's course and a classroom sample from the network.
#include "sim/pathology/pathology_timeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/pathology/pathology.h"

namespace lungar::sim {

Status check_timeline(const PathologyTimeline& timeline) {
  if (Status s = check_pathologies(timeline.start); !s) return s.with_context("pathology at the start: ");
  double previous_s = 0;
  for (std::size_t k = 0; k < timeline.events.size(); ++k) {
    const PathologyEvent& e = timeline.events[k];
    const std::string where = "pathology event " + std::to_string(k + 1) + ": ";
    if (!std::isfinite(e.at_s) || e.at_s < previous_s)
      return fail(where + "at_s: expected a time in seconds, not before the event before it");
    if (!std::isfinite(e.over_s) || e.over_s <= 0) return fail(where + "over_s: expected a time in seconds above 0");
    if (e.add.empty() && e.remove.empty()) return fail(where + "expected add, remove, or both (a change of severity)");
    previous_s = e.at_s;
    std::vector<std::string> then = present_after(timeline, k);  // at most 64 events: quadratic is fine
    if (!e.remove.empty()) {
      const auto it = std::find(then.begin(), then.end(), e.remove);
      if (it == then.end())
        return fail(where + "remove: '" + e.remove +
                    "' is not present then (the start and the events before it add "
                    "what can be removed)");
      then.erase(it);
    }
    if (!e.add.empty()) {
      if (auto p = parse_pathology(e.add); !p) return p.with_context(where + "add: ");
      then.push_back(e.add);
      if (Status s = check_pathologies(then); !s) return s.with_context(where + "add: ");
    }
  }
  return {};
}

std::vector<std::string> present_after(const PathologyTimeline& timeline, std::size_t events) {
  std::vector<std::string> present = timeline.start;
  for (std::size_t k = 0; k < events && k < timeline.events.size(); ++k) {
    const PathologyEvent& e = timeline.events[k];
    if (const auto it = std::find(present.begin(), present.end(), e.remove); !e.remove.empty() && it != present.end())
      present.erase(it);
    if (!e.add.empty()) present.push_back(e.add);
  }
  return present;
}

std::string describe(const PathologyTimeline& timeline) {
  std::string out;
  for (const std::string& spec : timeline.start) out += (out.empty() ? "" : ", ") + spec;
  if (out.empty()) out = "healthy";
  for (const PathologyEvent& e : timeline.events) {
    char when[96];
    std::snprintf(when, sizeof when, " at %.1f s over %.1f s", e.at_s, e.over_s);
    if (!e.add.empty() && !e.remove.empty()) {
      out += ", then " + e.remove + " becomes " + e.add + when;
    } else {
      out += e.add.empty() ? ", then " + e.remove + " goes" + when : ", then " + e.add + " comes" + when;
    }
  }
  return out;
}

}  // namespace lungar::sim
