/// @file settings.cpp
/// @brief TrackersBox's copy and lifetime, where [trackers]' type is complete (settings.h says why it is boxed).
/// @ingroup platform
#include "platform/app/settings.h"

#include "drivers/tracker/tracker_config.h"

namespace lungar::platform {

TrackersBox::TrackersBox() : trackers_(std::make_unique<drivers::TrackerConfig>()) {}
TrackersBox::~TrackersBox() = default;
TrackersBox::TrackersBox(const TrackersBox& other)
    : trackers_(std::make_unique<drivers::TrackerConfig>(*other.trackers_)) {}

TrackersBox& TrackersBox::operator=(const TrackersBox& other) {
  *trackers_ = *other.trackers_;
  return *this;
}

}  // namespace lungar::platform
