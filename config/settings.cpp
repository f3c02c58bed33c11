/// @file settings.cpp
/// @brief A start-up summary of the settings.
#include "config/settings.h"

#include <sstream>

#include "config/settings_load.h"

namespace lungar::config {

std::string summarize(const Settings& s) {
  std::ostringstream o;
  o << "config " << s.source << ": output " << to_string(s.display.output)
    << (s.display.output == Output::OpenXr ? std::string(" (head ") + to_string(s.display.openxr.head) + ")" : "")
    << ", view " << to_string(s.hmd.view)
    << " (" << s.hmd.eye_width_px << "x" << s.hmd.eye_height_px << " per eye, IPD " << s.hmd.ipd_mm << " mm)"
    << ", " << to_string(s.render.mode) << " at " << s.render.point_size_px << " px, deform "
    << to_string(s.render.deform) << ", breathing " << s.breathing.preset << " " << s.breathing.rate_bpm
    << "/min V_T " << s.breathing.tidal_volume_ml << " mL, tracker " << to_string(s.trackers.source)
    << (s.trackers.source == TrackerSource::Mock ? " (" + s.trackers.mock_trajectory + ")" : std::string())
    << ", orientation " << to_string(s.sim.orientation_mode);
  return o.str();
}

}  // namespace lungar::config
