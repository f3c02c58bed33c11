/// @file settings.h
/// @brief lungar's typed settings tree: every knob of the runtime, with its built-in default.
///
/// The values here are the defaults; `config/default.toml` documents each key and its unit, and
/// `load_settings()` (settings_load.h) overlays a TOML file on them with validation.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace lungar::config {

/// Where frames go.
enum class Output { Auto, Window, Fullscreen, Headless };
enum class View { Mono, Stereo };
enum class RenderMode { Points, Mesh };
/// Where the deformation is evaluated: the vertex shader (eq. 7), or the CPU by eq. (7) or eq. (1).
enum class Deform { Gpu, Cpu7, Cpu1 };
/// Stereo strategy: deform in each eye's draw (the paper), or once into a buffer by transform feedback.
enum class StereoStrategy { PerEye, DeformOnce };
enum class TrackerSource { Mock, Hid, Replay };
/// Orientation -> force SH: exact linear combination of baked vectors, or the paper's eq. (8)-(9).
enum class OrientationMode { Exact, PaperInterp };

struct DisplaySettings {
  Output output = Output::Auto;
  int width_px = 1280;        ///< window or full-screen size
  int height_px = 720;
  int x_px = 0;               ///< position of the window / HMD output in the X screen (extended mode)
  int y_px = 0;
  std::string x11_output;     ///< X output name for full-screen (empty: the window's screen)
  bool vsync = true;
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
  StereoStrategy stereo_strategy = StereoStrategy::DeformOnce;
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

struct HidSettings {
  std::uint16_t vendor_id = 0;   ///< 0: any
  std::uint16_t product_id = 0;  ///< 0: any
  std::string serial;
  std::string path;              ///< hidraw path; wins over ids when set
};

struct TrackerSettings {
  TrackerSource source = TrackerSource::Mock;
  std::string mock_trajectory = "upright_to_supine";  ///< static | upright_to_supine | head_orbit
  double mock_rate_hz = 62.5;
  std::string replay_file;
  bool replay_realtime = true;
  double stale_ms = 100.0;        ///< a pose older than this is marked stale
  double reopen_backoff_ms = 250.0;
  HidSettings hid;
};

struct RegistrationSettings {
  std::array<double, 3> translation_mm = {0.0, 0.0, 0.0};        ///< lung model -> patient tracker
  std::array<double, 4> rotation_wxyz = {1.0, 0.0, 0.0, 0.0};    ///< unit quaternion, model -> tracker
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
  std::string source = "<defaults>";
};

const char* to_string(Output);
const char* to_string(View);
const char* to_string(RenderMode);
const char* to_string(Deform);
const char* to_string(StereoStrategy);
const char* to_string(TrackerSource);
const char* to_string(OrientationMode);

}  // namespace lungar::config
