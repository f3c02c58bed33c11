/// @file output_settings.h
/// @brief [display] and [hmd]: where frames go and the geometry of the eyes that lungar places itself, owned by
/// the outputs that read them, with their TOML readers (output_settings.cpp).
/// @ingroup platform
#pragma once

#include <array>
#include <optional>
#include <string>

#include "config/base/enum_names.h"
#include "config/toml_section.h"

namespace lungar::platform {

/// Where frames go.
enum class Output { Auto, Window, Fullscreen, Headless, OpenXr };
/// With Output::OpenXr: whose head pose places the eyes (the runtime's tracking, or lungar's head tracker).
enum class XrHead { OpenXr, Tracker };
/// The OpenXR reference space the runtime's poses are located in.
enum class XrReferenceSpace { Local, Stage };
enum class View { Mono, Stereo };

inline constexpr EnumNames<Output, 5> kOutputNames{{{{Output::Auto, "auto"},
                                                      {Output::Window, "window"},
                                                      {Output::Fullscreen, "fullscreen"},
                                                      {Output::Headless, "headless"},
                                                      {Output::OpenXr, "openxr"}}}};
inline constexpr EnumNames<XrHead, 2> kXrHeadNames{{{{XrHead::OpenXr, "openxr"}, {XrHead::Tracker, "tracker"}}}};
inline constexpr EnumNames<XrReferenceSpace, 2> kXrReferenceSpaceNames{{{{XrReferenceSpace::Local, "local"}, {XrReferenceSpace::Stage, "stage"}}}};
inline constexpr EnumNames<View, 2> kViewNames{{{{View::Mono, "mono"}, {View::Stereo, "stereo"}}}};
inline const char* to_string(Output v) { return kOutputNames.name(v); }
inline const char* to_string(XrHead v) { return kXrHeadNames.name(v); }
inline const char* to_string(XrReferenceSpace v) { return kXrReferenceSpaceNames.name(v); }
inline const char* to_string(View v) { return kViewNames.name(v); }

/// [display.openxr]: the OpenXR output (an HMD through its OpenXR runtime).
struct OpenXrSettings {
  XrHead head = XrHead::OpenXr;
  XrReferenceSpace reference_space = XrReferenceSpace::Local;
};

struct DisplaySettings {
  Output output = Output::Auto;
  int width_px = 1280;        ///< window or full-screen size
  int height_px = 720;
  int x_px = 0;               ///< position of the window / HMD output in the X screen (extended mode)
  int y_px = 0;
  std::string x11_output;     ///< with Output::Fullscreen: the X output (RandR monitor) to cover; empty: x, y, size
  bool vsync = true;
  double max_fps = 0.0;       ///< frames per second at most (0: as fast as the output allows); a headless station
  OpenXrSettings openxr;
};

struct LensSettings {
  bool enabled = false;
  std::array<double, 3> k1 = {0.22, 0.24, 0.26};  ///< radial k1 per colour channel (R, G, B)
  std::array<double, 3> k2 = {0.24, 0.26, 0.28};  ///< radial k2 per colour channel (R, G, B)
};

struct HmdSettings {
  View view = View::Stereo;
  std::string layout = "side_by_side";
  int eye_width_px = 640;
  int eye_height_px = 720;
  double ipd_mm = 63.0;
  double fov_inner_deg = 40.0;  ///< per eye, toward the nose
  double fov_outer_deg = 50.0;  ///< per eye, toward the temple
  double fov_up_deg = 45.0;
  double fov_down_deg = 45.0;
  std::array<double, 3> head_to_eye_mm = {0.0, -80.0, -70.0};  ///< centre of the eyes in the tracker's frame
  double near_mm = 50.0;
  double far_mm = 5000.0;
  double prediction_max_ms = 50.0;  ///< bound on constant-velocity head prediction
  LensSettings lens;
  /// [hmd.display_calibration] (`lungar calibrate-display`): each eye's 3 x 4 projection, head sensor mm -> that
  /// eye's viewport pixels (origin top-left), row-major, left then right. Set, it replaces ipd_mm, the fields of
  /// view and head_to_eye_mm for the eyes' views (platform/output/hmd_views.h).
  std::optional<std::array<std::array<double, 12>, 2>> display_calibration;
};

/// Reads [display] (and [display.openxr]) over `d`; throws config::ConfigError naming the file, key and expectation.
void read_display_settings(config::TomlSection s, DisplaySettings& d);
/// Reads [hmd] (and [hmd.lens]) over `h`, the same way.
void read_hmd_settings(config::TomlSection s, HmdSettings& h);

}  // namespace lungar::platform
