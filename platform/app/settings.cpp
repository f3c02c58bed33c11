/// @file settings.cpp
/// @brief The settings' copy and move: a value, with [trackers] behind its pointer (settings.h says why).
/// @ingroup platform
#include "platform/app/settings.h"

#include "drivers/tracker/tracker_config.h"

namespace lungar::platform {

Settings::Settings() : trackers_(std::make_unique<drivers::TrackerConfig>()) {}
Settings::~Settings() = default;

Settings::Settings(const Settings& other)
    : display(other.display),
      hmd(other.hmd),
      render(other.render),
      breathing(other.breathing),
      registration(other.registration),
      sim(other.sim),
      sync(other.sync),
      source(other.source),
      trackers_(std::make_unique<drivers::TrackerConfig>(*other.trackers_)) {}

Settings& Settings::operator=(const Settings& other) {
  display = other.display;
  hmd = other.hmd;
  render = other.render;
  breathing = other.breathing;
  registration = other.registration;
  sim = other.sim;
  sync = other.sync;
  source = other.source;
  *trackers_ = *other.trackers_;
  return *this;
}

}  // namespace lungar::platform
