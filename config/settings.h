/// @file settings.h
/// @brief lungar's typed settings tree: every knob of the runtime, with its built-in default.
///
/// The values here are the defaults; `config/default.toml` documents each key and its unit, and
/// `load_settings()` (settings_load.h) overlays a TOML file on them with validation.
#pragma once

#include <array>
#include <string>

#include "config/base/enum_names.h"
#include "drivers/tracker/tracker_config.h"  // [trackers]: the drivers own the tracker's settings

namespace lungar::config {

/// Where frames go.
enum class Output { Auto, Window, Fullscreen, Headless, OpenXr };
/// With Output::OpenXr: whose head pose places the eyes (the runtime's tracking, or lungar's head tracker).
enum class XrHead { OpenXr, Tracker };
/// The OpenXR reference space the runtime's poses are located in.
enum class XrSpace { Local, Stage };
enum class View { Mono, Stereo };
enum class RenderMode { Points, Mesh };
/// Where the deformation is evaluated: the vertex shader (eq. 7), or the CPU by eq. (7) or eq. (1); or None,
/// the rest shape undeformed (what the deformation is compared with, and what the bench measures it against).
enum class Deform { Gpu, Cpu7, Cpu1, None };
/// Stereo strategy: deform in each eye's draw (the paper), or once into a buffer by transform feedback.
enum class StereoStrategy { PerEye, DeformOnce };
/// Orientation -> force SH: exact linear combination of baked vectors, or the paper's eq. (8)-(9).
enum class OrientationMode { Exact, PaperInterp };

/// [display.openxr]: the OpenXR output (an HMD through its OpenXR runtime).
struct OpenXrSettings {
  XrHead head = XrHead::OpenXr;
  XrSpace reference_space = XrSpace::Local;
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
};

struct RenderSettings {
  RenderMode mode = RenderMode::Points;
  double point_size_px = 5.0;
  bool overlay_rest = false;
  Deform deform = Deform::Gpu;
  StereoStrategy stereo_strategy = StereoStrategy::PerEye;  // measured faster on llvmpipe (README, bench)
  bool lod = true;
  bool half_float = false;
  bool hud = true;
  std::array<double, 3> color_left = {0.90, 0.45, 0.45};
  std::array<double, 3> color_right = {0.45, 0.60, 0.95};
  std::array<double, 3> background = {0.0, 0.0, 0.0};
};

struct BreathingSettings {
  std::string preset = "normal";  ///< normal | emphysema | fibrosis
  double rate_bpm = 12.0;
  double ie_ratio = 0.5;          ///< inspiration : expiration time, 1:2 = 0.5
  double tidal_volume_ml = 500.0;
  std::string scenario;           ///< optional scenario TOML (relative to the config file)
};

/// [trackers] is the drivers' (drivers/tracker/tracker_config.h, read and written by tracker_config_toml.h).
/// These names keep the code that still says config:: compiling until Settings leaves config/ for the
/// application layer.
using TrackerSettings = drivers::TrackerConfig;
using HidSettings = drivers::HidConfig;
using IgtlSettings = drivers::IgtlConfig;
using ReportSettings = drivers::ReportConfig;
using SensorSettings = drivers::SensorConfig;
using drivers::Endian;
using drivers::FieldType;
using drivers::OrientationKind;
using drivers::TrackerSource;
using drivers::kTrackerSourceNames;
using drivers::parse_signed_axes;
using drivers::SignedAxis;
using drivers::to_string;

struct RegistrationSettings {
  std::array<double, 3> translation_mm = {0.0, 0.0, 0.0};        ///< lung model -> patient tracker
  std::array<double, 4> rotation_wxyz = {1.0, 0.0, 0.0, 0.0};    ///< unit quaternion, model -> tracker
  /// The OpenXR reference space's pose in the tracker world (the runtime's tracking -> the trackers'), with
  /// display.openxr.head = "openxr". Default: LOCAL's origin (the head where the session started) at the default
  /// viewer's eyes, 0.8 m in front of the patient and looking at it, as the window output's default view.
  std::array<double, 3> xr_space_translation_mm = {0.0, -801.1, 1267.2};
  std::array<double, 4> xr_space_rotation_wxyz = {0.83485, 0.55048, 0.0, 0.0};
};

/// A classroom station's part (platform/sync): alone, the instructor, or a trainee.
enum class SyncRole { Off, Instructor, Trainee };
inline constexpr EnumNames<SyncRole, 3> kSyncRoleNames{
    {{{SyncRole::Off, "off"}, {SyncRole::Instructor, "instructor"}, {SyncRole::Trainee, "trainee"}}}};

/// [sync]: several stations sharing one patient and one breath over Cyclone DDS.
struct SyncSettings {
  SyncRole role = SyncRole::Off;
  std::string classroom = "classroom";  ///< the DDS partition: one name per classroom on a network
  int domain = 0;                       ///< the DDS domain id, [0, 232]
  std::string cyclonedds_xml;           ///< Cyclone XML; empty: the shipped config/cyclonedds/classroom-lan.xml
  std::string station;                  ///< this station's name; empty: host/pid
  double lost_after_ms = 250.0;         ///< a trainee is lost after this long without a word from the instructor
};

struct SimSettings {
  std::string asset;  ///< baked asset; empty: the cached procedural pair
  OrientationMode orientation_mode = OrientationMode::Exact;
};

/// The whole tree. `source` names the file it came from ("<defaults>" when none).
struct Settings {
  DisplaySettings display;
  HmdSettings hmd;
  RenderSettings render;
  BreathingSettings breathing;
  TrackerSettings trackers;
  RegistrationSettings registration;
  SimSettings sim;
  SyncSettings sync;
  std::string source = "<defaults>";
};

/// The names of each enumeration as TOML, the command line and logs spell them: one table each.
inline constexpr EnumNames<Output, 5> kOutputNames{{{{Output::Auto, "auto"},
                                                      {Output::Window, "window"},
                                                      {Output::Fullscreen, "fullscreen"},
                                                      {Output::Headless, "headless"},
                                                      {Output::OpenXr, "openxr"}}}};
inline constexpr EnumNames<XrHead, 2> kXrHeadNames{{{{XrHead::OpenXr, "openxr"}, {XrHead::Tracker, "tracker"}}}};
inline constexpr EnumNames<XrSpace, 2> kXrSpaceNames{{{{XrSpace::Local, "local"}, {XrSpace::Stage, "stage"}}}};
inline constexpr EnumNames<View, 2> kViewNames{{{{View::Mono, "mono"}, {View::Stereo, "stereo"}}}};
inline constexpr EnumNames<RenderMode, 2> kRenderModeNames{{{{RenderMode::Points, "points"}, {RenderMode::Mesh, "mesh"}}}};
inline constexpr EnumNames<Deform, 4> kDeformNames{
    {{{Deform::Gpu, "gpu"}, {Deform::Cpu7, "cpu7"}, {Deform::Cpu1, "cpu1"}, {Deform::None, "none"}}}};
inline constexpr EnumNames<StereoStrategy, 2> kStereoStrategyNames{
    {{{StereoStrategy::PerEye, "per_eye"}, {StereoStrategy::DeformOnce, "deform_once"}}}};
inline constexpr EnumNames<OrientationMode, 2> kOrientationModeNames{
    {{{OrientationMode::Exact, "exact"}, {OrientationMode::PaperInterp, "paper_interp"}}}};
inline const char* to_string(Output v) { return kOutputNames.name(v); }
inline const char* to_string(XrHead v) { return kXrHeadNames.name(v); }
inline const char* to_string(XrSpace v) { return kXrSpaceNames.name(v); }
inline const char* to_string(View v) { return kViewNames.name(v); }
inline const char* to_string(RenderMode v) { return kRenderModeNames.name(v); }
inline const char* to_string(Deform v) { return kDeformNames.name(v); }
inline const char* to_string(StereoStrategy v) { return kStereoStrategyNames.name(v); }
inline const char* to_string(OrientationMode v) { return kOrientationModeNames.name(v); }
inline const char* to_string(SyncRole v) { return kSyncRoleNames.name(v); }

}  // namespace lungar::config
