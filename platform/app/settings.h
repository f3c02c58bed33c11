/// @file settings.h
/// @brief lungar's whole settings tree, seen here and nowhere else: each part is the type of the library that
/// reads it ([display] and [hmd] the outputs', [trackers] the drivers', [sync] the classroom's, [breathing]
/// config's), and the parts only the program itself uses are declared below. The values are the defaults;
/// `config/default.toml` documents each key and its unit; settings_load.h overlays a TOML file on them.
/// @ingroup platform
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "config/base/enum_names.h"
#include "config/breathing_settings.h"
#include "drivers/classroom/sync_settings.h"
#include "platform/output/output_settings.h"
#include "platform/runtime/runtime_config.h"
#include "render/draw_modes.h"
#include "sim/force/force_sh.h"

namespace lungar::drivers {
struct TrackerConfig;  // drivers/tracker/tracker_config.h: [trackers], every device's table
}  // namespace lungar::drivers

namespace lungar::platform {

/// [render]: how the lungs are deformed and drawn.
struct RenderSettings {
  render::DrawMode mode = render::DrawMode::Points;
  double point_size_px = 5.0;
  bool overlay_rest = false;
  Deform deform = Deform::Gpu;
  render::StereoStrategy stereo_strategy = render::StereoStrategy::PerEye;  ///< docs/measurements.md compares both
  bool lod = true;
  bool half_float = false;
  bool hud = true;
  /// The ventilation map (render/renderer.h, FrameInputs::ventilation_full_scale_mm) instead of the lungs' colours;
  /// `--view ventilation` and the V key turn it on.
  bool ventilation_map = false;
  double ventilation_full_scale_mm = 20.0;  ///< the sweep per breath at the ramp's top
  std::array<double, 3> color_left = {0.90, 0.45, 0.45};
  std::array<double, 3> color_right = {0.45, 0.60, 0.95};
  std::array<double, 3> color_lesion = {1.00, 0.85, 0.10};
  std::array<double, 3> background = {0.0, 0.0, 0.0};
};

/// [registration]: where the lung model sits on the patient sensor, and the OpenXR space in the tracker world.
struct RegistrationSettings {
  std::array<double, 3> translation_mm = {0.0, 0.0, 0.0};        ///< lung model -> patient tracker
  std::array<double, 4> rotation_wxyz = {1.0, 0.0, 0.0, 0.0};    ///< unit quaternion, model -> tracker
  /// The OpenXR reference space's pose in the tracker world (the runtime's tracking -> the trackers'), with
  /// display.openxr.head = "openxr". Default: LOCAL's origin (the head where the session started) at the default
  /// viewer's eyes, 0.8 m in front of the patient and looking at it, as the window output's default view.
  std::array<double, 3> xr_space_translation_mm = {0.0, -801.1, 1267.2};
  std::array<double, 4> xr_space_rotation_wxyz = {0.83485, 0.55048, 0.0, 0.0};
};

/// [sim]: the baked asset and how the patient's orientation becomes the force.
struct SimSettings {
  std::string asset;  ///< baked asset; empty: the demo's lungs, baked once and cached
  sim::ForceMode orientation_mode = sim::ForceMode::Exact;
  /// Pathologies applied to the asset when it is loaded, in order (sim/pathology/pathology.h), e.g.
  /// "pneumothorax:right:30"; empty: healthy lungs.
  std::vector<std::string> pathologies;
  /// Lesions drawn inside the lungs and moved by the interior field (sim/motion/lesion.h), "NAME=x,y,z,radius_mm"
  /// in the asset's frame (LPS, mm); empty: none.
  std::vector<std::string> lesions;
};

/// [console]: the instructor's console, a web page over HTTPS (platform/console/) that runs the class live.
struct ConsoleSettings {
  std::string listen;  ///< "[ADDR:]PORT" the console is served on (an instructor only); empty: no console
  /// The console's folder of `lungar classroom-keys` (its certificate and logins); empty: the folder `console`
  /// beside this station's [sync] security folder.
  std::string keys;
  /// The folder of scenario TOML files the console may load and run on the class; empty: the shipped scenarios
  /// ($LUNGAR_DATA_DIR/scenarios, <exe dir>/../share/lungar/scenarios, the source tree's config/scenarios).
  std::string scenarios;
};

/// [trackers] behind a pointer, a value all the same: copied whole, never null (a move copies too; settings are
/// copied a few times at start, never per frame). Its members are defined in settings.cpp, where the type is
/// complete, so that Settings' own copy, assignment and destruction stay the compiler's, member by member.
class TrackersBox {
 public:
  TrackersBox();
  ~TrackersBox();
  TrackersBox(const TrackersBox& other);
  TrackersBox& operator=(const TrackersBox& other);

  drivers::TrackerConfig& get() { return *trackers_; }
  const drivers::TrackerConfig& get() const { return *trackers_; }

 private:
  std::unique_ptr<drivers::TrackerConfig> trackers_;
};

/// The whole tree. `source` names the file it came from ("<defaults>" when none).
///
/// [trackers] is boxed (TrackersBox): the settings are seen by some thirty files (outputs, the bench, the doctor's
/// checks) that never touch a tracker, and the trackers' table composes every device's settings. Only the files
/// that call trackers() include drivers/tracker/tracker_config.h.
struct Settings {
  drivers::TrackerConfig& trackers() { return trackers_.get(); }
  const drivers::TrackerConfig& trackers() const { return trackers_.get(); }

  DisplaySettings display;
  HmdSettings hmd;
  RenderSettings render;
  config::BreathingSettings breathing;
  RegistrationSettings registration;
  SimSettings sim;
  classroom::SyncSettings sync;
  ConsoleSettings console;
  std::string source = "<defaults>";

 private:
  TrackersBox trackers_;
};

}  // namespace lungar::platform
