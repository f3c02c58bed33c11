/// @file lung_course.h
/// @brief How the lungs' shapes change while they are drawn (a scenario's pathology events: a tension pneumothorax
///        dropping, a needle decompression re-expanding it), the asset on the GPU staying the one loaded: each
///        frame the Runtime asks for every lung's shape (a map of its loaded rest shape) and figures at that time.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sim/pathology/lung_shapes.h"

namespace lungar::platform {

class LungCourse {
 public:
  virtual ~LungCourse() = default;
  /// Every lung's shape at `now_ns` (monotonic), in the asset's order.
  virtual const std::vector<sim::LungShape>& at(std::int64_t now_ns) = 0;
  /// Its keys in the stats JSON (`pathologies`: those present at the last frame).
  virtual void add_stats(nlohmann::json& stats) const { (void)stats; }
};

}  // namespace lungar::platform
