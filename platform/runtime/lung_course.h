/// @file lung_course.h
/// @brief How the lungs' shapes change while they are drawn (a scenario's pathology events: a tension pneumothorax
///        dropping, a needle decompression re-expanding it), the asset on the GPU staying the one loaded: each
///        frame the Runtime asks for every lung's shape (a map of its loaded rest shape) and figures at that time.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sim/pathology/lung_shapes.h"

namespace lungar::platform {

class LungCourse {
 public:
  virtual ~LungCourse() = default;
  /// Every lung's shape at `now_ns` (monotonic), in the asset's order.
  virtual const std::vector<sim::LungShape>& at(std::int64_t now_ns) = 0;
  /// The pathologies in force at the last at(), for the status line and the log ("pneumothorax:right:30:tension
  /// (coming)"); null: the course does not know them (the run's own, RuntimeConfig::pathologies, are shown).
  virtual const std::string* pathologies_now() const { return nullptr; }
  /// Its keys in the stats JSON (`pathologies`: those present at the last frame).
  virtual void add_stats(nlohmann::json& stats) const { (void)stats; }
};

}  // namespace lungar::platform
