/// @file breathing_settings.cpp
/// @brief The [breathing] keys: a preset of the pressure-volume curve, rate, I:E, tidal volume, the scenario file.
#include "config/breathing_settings.h"

namespace lungar::config {

void read_breathing_settings(TomlSection s, BreathingSettings& b) {
  s.choice("preset", b.preset, kPresetNames);
  s.number("rate_bpm", b.rate_bpm, 2.0, 60.0, "breaths/min");
  s.number("ie_ratio", b.ie_ratio, 0.1, 4.0, "(inspiration:expiration)");
  s.number("tidal_volume_ml", b.tidal_volume_ml, 50.0, 3000.0, "mL");
  s.text("scenario", b.scenario);
  s.text("source", b.source);
  s.choice("rpm_flagged", b.rpm_flagged, {"follow", "skip"});
  if (b.source.empty()) {
    s.fail("source", "expected " + breath_source_forms() + ", got \"\"");
  }
  s.finish();
}

}  // namespace lungar::config
