/// @file display_requests.h
/// @brief What another station asks this one's display to show, read by the frame: the ventilation map on or off,
/// as the instructor's console asks every station of its class (platform/sync/class_control.h for the instructor,
/// the trainee's own from the classroom). A station's own choice (its settings, its V key) stands until the next
/// request.
/// @ingroup platform
#pragma once

#include <cstdint>

namespace lungar::platform {

class DisplayRequests {
 public:
  virtual ~DisplayRequests() = default;
  /// True when the ventilation map was asked on or off since `version` (0 at first): `on` and `version` set.
  /// Allocates nothing, never waits.
  virtual bool ventilation_map_since(std::uint64_t& version, bool& on) const = 0;
};

}  // namespace lungar::platform
