/// @file settings.h
/// @brief lungar's typed settings tree: every knob of the runtime, with its built-in default.
///
/// The values here are the defaults; `config/default.toml` documents each key and its unit, and
/// `load_settings()` (settings_load.h) overlays a TOML file on them with validation.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/base/enum_names.h"

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
enum class TrackerSource { Mock, Hid, Replay, Igtl };
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
  StereoStrategy stereo_strategy = StereoStrategy::PerEye;  // measured faster (docs/measurements.md, scripts/bench)
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
  double read_timeout_ms = 10.0; ///< hid_read_timeout's wait, so the thread notices stop and staleness
  /// Feature reports sent in order (hid_send_feature_report) each time the device is opened, report id first:
  /// for trackers that stream nothing until told to. Parsed from hex text ("0x02 0x01") by the loader.
  std::vector<std::vector<std::uint8_t>> init_feature_reports;
};

/// An OpenIGTLink server (PlusServer, 3D Slicer's OpenIGTLinkIF) streaming TRANSFORM, TDATA or QTDATA messages.
struct IgtlSettings {
  std::string host = "127.0.0.1";
  int port = 18944;                ///< OpenIGTLink's registered port, PlusServer's and Slicer's default
  /// The device (or tool) name that carries each role, PLUS's naming; "" = the role is not fed.
  std::string head = "HeadToTracker";
  std::string patient = "PatientToTracker";
  std::string stylus = "StylusTipToTracker";
  double scale = 1.0;              ///< mm per unit of the received positions (PLUS and Slicer send mm)
  double rigid_tolerance = 1e-3;   ///< a rotation part whose |R^T R - I| entries exceed this is not rigid: dropped
  double connect_timeout_ms = 1000.0;
};

/// How one number is stored in a report. None (position only): the report carries no position (an
/// orientation-only sensor such as an HMD's IMU); each role then uses its fixed_position_mm.
enum class FieldType { I16, I32, F32, Fixed16, Fixed32, None };
enum class Endian { Little, Big };
/// How a sensor's orientation is sent: a quaternion, or three Euler (Tait-Bryan) angles.
enum class OrientationKind { Quaternion, Euler };

/// One sensor inside a report; the role it feeds is the key it sits under ([trackers.head], ...).
struct SensorSettings {
  bool enabled = false;
  int station = 0;  ///< value of the station byte that selects this sensor (station mode only)
  int offset = 0;   ///< byte offset of this sensor's block (position, orientation) in the report
  /// With position_type = "none": the position this role reports, in the tracker's axes (before axis_remap), mm.
  std::array<double, 3> fixed_position_mm = {0.0, 0.0, 0.0};
};

/// The byte layout of one HID input report. Offsets are bytes from the start of what hid_read returns
/// (the report id byte included when report_id >= 0); field offsets are relative to the sensor block.
struct ReportSettings {
  int report_id = 1;       ///< first byte of every report; -1: the device does not number its reports
  int length = 32;         ///< bytes per report, the id byte included
  Endian endian = Endian::Little;
  int station_offset = 1;  ///< byte that names the sensor; -1: every sensor at its fixed offset in each report
  int time_offset = 2;     ///< device timestamp; -1: none (arrival time stands in)
  int time_bits = 32;      ///< unsigned 16 or 32 bits, wraps around
  double time_tick_us = 1.0;  ///< microseconds per timestamp tick
  int position_offset = 0;
  FieldType position_type = FieldType::I32;
  int position_frac_bits = 0;    ///< fixed-point types: fractional bits
  double position_scale = 0.01;  ///< mm per unit (after the fixed-point division)
  std::string position_components = "x,y,z";  ///< what the device sends, in order, with its signs
  OrientationKind orientation = OrientationKind::Quaternion;
  int orientation_offset = 12;
  FieldType orientation_type = FieldType::Fixed16;
  int orientation_frac_bits = 14;
  double orientation_scale = 1.0;  ///< quaternion units, or degrees for Euler angles, per unit
  std::string orientation_components = "w,x,y,z";  ///< quaternion components or Euler axes, in sent order
  std::string euler_sequence = "zyx";  ///< intrinsic Tait-Bryan order: "zyx" is R = Rz(a) Ry(b) Rx(c)
};

struct TrackerSettings {
  TrackerSource source = TrackerSource::Mock;
  std::string mock_trajectory = "upright_to_supine";  ///< static | upright_to_supine | head_orbit
  double mock_rate_hz = 62.5;
  double mock_noise_mm = 0.0;       ///< Gaussian position noise of the mock, mm (1 sigma)
  double mock_dropout = 0.0;        ///< probability that the mock drops a report
  std::string replay_file;
  bool replay_realtime = true;
  bool replay_loop = false;         ///< start the log again at its end
  double stale_ms = 100.0;        ///< a pose older than this is marked stale
  double reopen_backoff_ms = 250.0;
  double quat_norm_tolerance = 0.05;  ///< a decoded quaternion's |norm - 1| above this is malformed
  std::array<double, 3> workspace_min_mm = {-3000.0, -3000.0, -3000.0};  ///< world frame
  std::array<double, 3> workspace_max_mm = {3000.0, 3000.0, 3000.0};
  std::string axis_remap = "x,y,z";  ///< world axes in terms of the tracker's: "x,-z,y" is world y = -tracker z
  std::array<double, 3> world_offset_mm = {0.0, 0.0, 0.0};  ///< tracker origin in the world, mm
  HidSettings hid;
  IgtlSettings igtl;
  ReportSettings report;
  SensorSettings head{true, 1, 6, {}};
  SensorSettings patient{true, 2, 6, {}};
  SensorSettings stylus{false, 3, 6, {}};
};

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

/// One entry of a component list such as "w,-x,-y,-z": the index of its letter in the alphabet given to
/// parse_signed_axes() and its sign (+1 or -1).
struct SignedAxis {
  int index = 0;
  int sign = 1;
};
/// Parses a comma-separated permutation of `letters` ("x,-z,y" over "xyz"), each letter once, optionally
/// preceded by '-'; nullopt when the text is not such a permutation.
std::optional<std::vector<SignedAxis>> parse_signed_axes(std::string_view text, std::string_view letters);

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
inline constexpr EnumNames<TrackerSource, 4> kTrackerSourceNames{{{{TrackerSource::Mock, "mock"},
                                                                   {TrackerSource::Hid, "hid"},
                                                                   {TrackerSource::Replay, "replay"},
                                                                   {TrackerSource::Igtl, "igtl"}}}};
inline constexpr EnumNames<OrientationMode, 2> kOrientationModeNames{
    {{{OrientationMode::Exact, "exact"}, {OrientationMode::PaperInterp, "paper_interp"}}}};
inline constexpr EnumNames<FieldType, 6> kFieldTypeNames{{{{FieldType::I16, "i16"},
                                                           {FieldType::I32, "i32"},
                                                           {FieldType::F32, "f32"},
                                                           {FieldType::Fixed16, "fixed16"},
                                                           {FieldType::Fixed32, "fixed32"},
                                                           {FieldType::None, "none"}}}};
/// The types an orientation may have: every field type but "none".
inline constexpr EnumNames<FieldType, 5> kOrientationFieldTypeNames{{{{FieldType::I16, "i16"},
                                                                      {FieldType::I32, "i32"},
                                                                      {FieldType::F32, "f32"},
                                                                      {FieldType::Fixed16, "fixed16"},
                                                                      {FieldType::Fixed32, "fixed32"}}}};
inline constexpr EnumNames<Endian, 2> kEndianNames{{{{Endian::Little, "little"}, {Endian::Big, "big"}}}};
inline constexpr EnumNames<OrientationKind, 2> kOrientationKindNames{
    {{{OrientationKind::Quaternion, "quaternion"}, {OrientationKind::Euler, "euler"}}}};

inline const char* to_string(Output v) { return kOutputNames.name(v); }
inline const char* to_string(XrHead v) { return kXrHeadNames.name(v); }
inline const char* to_string(XrSpace v) { return kXrSpaceNames.name(v); }
inline const char* to_string(View v) { return kViewNames.name(v); }
inline const char* to_string(RenderMode v) { return kRenderModeNames.name(v); }
inline const char* to_string(Deform v) { return kDeformNames.name(v); }
inline const char* to_string(StereoStrategy v) { return kStereoStrategyNames.name(v); }
inline const char* to_string(TrackerSource v) { return kTrackerSourceNames.name(v); }
inline const char* to_string(OrientationMode v) { return kOrientationModeNames.name(v); }
inline const char* to_string(FieldType v) { return kFieldTypeNames.name(v); }
inline const char* to_string(Endian v) { return kEndianNames.name(v); }
inline const char* to_string(OrientationKind v) { return kOrientationKindNames.name(v); }
inline const char* to_string(SyncRole v) { return kSyncRoleNames.name(v); }

}  // namespace lungar::config
