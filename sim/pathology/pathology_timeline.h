/// @file pathology_timeline.h
/// @brief What the lungs have during a run: the pathologies from the start and the events that change them (a
///        tension pneumothorax dropping at 10 s over 15 s, its needle decompression at 40 s over 20 s). A scenario
///        gives it; an instructor shares it with the classroom, and every station draws the same course from it.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::sim {

/// A pathology coming (add) or going (remove) at breathing time at_s over over_s; both set: one becomes the other (a
/// change of severity, as an instructor's console makes it), the lungs going from one state to the other.
struct PathologyEvent {
  double at_s = 0;
  double over_s = 0;
  std::string add;
  std::string remove;

  bool operator==(const PathologyEvent&) const = default;
};

struct PathologyTimeline {
  std::vector<std::string> start;      ///< present from breathing time 0, as --pathology takes them
  std::vector<PathologyEvent> events;  ///< in time order

  bool empty() const { return start.empty() && events.empty(); }
  bool operator==(const PathologyTimeline&) const = default;
};

/// Every spec parses, each event adds, removes or replaces one and lasts a real, positive time, the events are in time
/// order, each removal takes away what the start and the events before it put there, and nothing added is there
/// already (check_pathologies: a second pneumothorax of a lung would compound the first). The error names the
/// event (from 1) and what was expected.
Status check_timeline(const PathologyTimeline& timeline);

/// The pathologies present after the first `events` events (the start's, then each added, less each removed).
std::vector<std::string> present_after(const PathologyTimeline& timeline, std::size_t events);

/// "ards:0.6, then pneumothorax:right:40:tension at 10.0 s over 15.0 s, then ..." for logs.
std::string describe(const PathologyTimeline& timeline);

}  // namespace lungar::sim
