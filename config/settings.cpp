/// @file settings.cpp
/// @brief Names of the settings' enumerations, as they are spelled in TOML, and a start-up summary.
#include "config/settings.h"

#include <sstream>

#include "config/settings_load.h"

namespace lungar::config {

const char* to_string(Output v) {
  switch (v) {
    case Output::Auto: return "auto";
    case Output::Window: return "window";
    case Output::Fullscreen: return "fullscreen";
    case Output::Headless: return "headless";
  }
  return "?";
}
const char* to_string(View v) { return v == View::Mono ? "mono" : "stereo"; }
const char* to_string(RenderMode v) { return v == RenderMode::Points ? "points" : "mesh"; }
const char* to_string(Deform v) {
  switch (v) {
    case Deform::Gpu: return "gpu";
    case Deform::Cpu7: return "cpu7";
    case Deform::Cpu1: return "cpu1";
    case Deform::None: return "none";
  }
  return "?";
}
const char* to_string(StereoStrategy v) { return v == StereoStrategy::PerEye ? "per_eye" : "deform_once"; }
const char* to_string(TrackerSource v) {
  switch (v) {
    case TrackerSource::Mock: return "mock";
    case TrackerSource::Hid: return "hid";
    case TrackerSource::Replay: return "replay";
  }
  return "?";
}
const char* to_string(OrientationMode v) { return v == OrientationMode::Exact ? "exact" : "paper_interp"; }

const char* to_string(FieldType v) {
  switch (v) {
    case FieldType::I16: return "i16";
    case FieldType::I32: return "i32";
    case FieldType::F32: return "f32";
    case FieldType::Fixed16: return "fixed16";
    case FieldType::Fixed32: return "fixed32";
  }
  return "?";
}
const char* to_string(Endian v) { return v == Endian::Little ? "little" : "big"; }
const char* to_string(OrientationKind v) { return v == OrientationKind::Quaternion ? "quaternion" : "euler"; }

std::string summarize(const Settings& s) {
  std::ostringstream o;
  o << "config " << s.source << ": output " << to_string(s.display.output) << ", view " << to_string(s.hmd.view)
    << " (" << s.hmd.eye_width_px << "x" << s.hmd.eye_height_px << " per eye, IPD " << s.hmd.ipd_mm << " mm)"
    << ", " << to_string(s.render.mode) << " at " << s.render.point_size_px << " px, deform "
    << to_string(s.render.deform) << ", breathing " << s.breathing.preset << " " << s.breathing.rate_bpm
    << "/min V_T " << s.breathing.tidal_volume_ml << " mL, tracker " << to_string(s.trackers.source)
    << (s.trackers.source == TrackerSource::Mock ? " (" + s.trackers.mock_trajectory + ")" : std::string())
    << ", orientation " << to_string(s.sim.orientation_mode);
  return o.str();
}

}  // namespace lungar::config
