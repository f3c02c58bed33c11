/// @file session_record.h
/// @brief A class's session record as read back: the header (who recorded, when, and what a replay needs to rebuild
///        the scene), every frame's breath and poses, the pathology timeline each time it changed, the events and
///        console actions with who made them, and each station's status over time (docs/design.md, "The session
///        record"). session_recorder.h writes it; `lungar replay` plays it back.
///
/// The file is one line per record, `CRC32HEX JSON\n` (the CRC of the JSON text): a line is whole when it ends in a
/// newline and its CRC matches. A station killed mid-write leaves a torn last line, which the reader cuts off and
/// says, reading everything before it.
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "config/base/result.h"
#include "drivers/pose/pose_sample.h"
#include "sim/breathing/driver.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::platform::record {

/// The header's `format`: what says a file is a session record.
inline constexpr const char* kSessionFormat = "lungar-session";
/// The version this lungar writes and reads; a record of another is refused, naming both.
inline constexpr int kSessionVersion = 1;
/// A record's file name ends so (`lungar --session-record DIR` names it DIR/<UTC time>-<station>.lungarsession).
inline constexpr const char* kSessionExtension = ".lungarsession";

/// The first line.
struct SessionHeader {
  int version = kSessionVersion;
  std::string station;         ///< the recording station's name
  std::string role;            ///< its classroom role: off, instructor or trainee
  std::string classroom;       ///< the classroom's name (empty outside one)
  std::string started_utc;     ///< the session's wall-clock start, "2026-11-29T19:12:16Z"
  double started_unix_s = 0;   ///< the same in seconds since 1970 (UTC), to the microsecond
  std::string lungar_version;  ///< the lungar that recorded it
  std::string scenario;        ///< the scenario file run (empty: none), for a reader
  // What a replay rebuilds the scene from.
  std::string asset_path;                ///< [sim] asset as run; empty: the demo's lungs (`procedural` says which pair)
  std::string asset_name;                ///< the stats JSON's name of the asset drawn
  bool procedural = false;               ///< the demo's procedural pair (--procedural)
  std::uint64_t nodes = 0;               ///< the asset's vertex count: a replay checks it draws the same lungs
  std::vector<std::string> lungs;        ///< the lungs' names in the asset's order (a frame's lung_dv_ml)
  std::vector<std::string> pathologies;  ///< applied when the asset was loaded (the settings' and the scenario's)
  std::vector<std::string> lesions;      ///< [sim] lesion specs drawn
  std::array<double, 3> registration_translation_mm = {0, 0, 0};  ///< lung model -> patient tracker
  std::array<double, 4> registration_rotation_wxyz = {1, 0, 0, 0};
  std::string orientation_mode = "exact";  ///< [sim] orientation_mode (sim::kForceModeNames)
};

/// One frame as the runtime drew it (platform/runtime/frame_listener.h's FrameState).
struct RecordedFrame {
  std::int64_t index = 0;  ///< the frame's number in the session, from 0
  double s = 0;            ///< session time: seconds since the session started
  /// The breath: breathing time t_s, P, V, dV, phase, breath index, and the source's own per-lung dV (NaN: none).
  sim::BreathingSample breath;
  /// Each lung's dV as drawn, in the header's `lungs` order (NaN past the asset's lungs).
  std::array<double, 2> lung_dv_ml{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  drivers::PoseSample patient;  ///< the patient pose the frame used (world, mm): position, orientation, flags
  Eigen::Vector3d lung_origin_mm = Eigen::Vector3d::Zero();  ///< the lung frame's origin in the world
  Eigen::Quaterniond lung_in_world = Eigen::Quaterniond::Identity();
  /// The pathologies the lungs' course showed ("pneumothorax:right:30:tension (coming)"); empty: no course.
  std::string pathologies;
};

/// The pathology timeline as it stood from session time `s` on.
struct RecordedTimeline {
  double s = 0;
  sim::PathologyTimeline timeline;
  std::size_t line = 0;  ///< its line in the file (from 1), for an error about it
};

/// An event of the class or a console action, and who made it.
struct RecordedEvent {
  double s = 0;    ///< session time of the note
  double t_s = 0;  ///< breathing time it is about
  std::string kind, user, text;
};

/// Every station's status at session time `s`, as the console gave it.
struct RecordedStations {
  double s = 0;
  nlohmann::json stations;
};

struct SessionRecord {
  std::string path;
  SessionHeader header;
  std::vector<RecordedFrame> frames;        ///< in the order drawn
  std::vector<RecordedTimeline> timelines;  ///< in the order noted
  std::vector<RecordedEvent> events;
  std::vector<RecordedStations> stations;
  bool ended = false;                ///< the recorder closed it (its end line was read)
  std::uint64_t dropped_frames = 0;  ///< frames the recorder could not keep up with (said by the end line)
  /// Empty when every line was whole; else where and why reading stopped ("line 812: torn (no newline at the end)").
  std::string cut;
  std::size_t lines = 0;  ///< whole lines read
};

/// `CRC32HEX JSON\n` for one record's JSON text (one line: no newline in it).
std::string session_line(std::string_view json);

/// The header as its line's JSON object.
nlohmann::ordered_json header_json(const SessionHeader& header);
/// The timeline as a `timeline` line's JSON object, noted at session time `s`.
nlohmann::ordered_json timeline_json(double s, const sim::PathologyTimeline& timeline);

/// Reads every whole line with a good CRC up to the first torn or corrupt one, which is said in `cut` (a killed
/// station leaves a torn last line: not an error). An error (one line: the file, the line, the field and what was
/// expected) for a file that is not a session record, another version, a bad header, or a whole line whose field
/// is wrong.
Result<SessionRecord> read_session_record(const std::string& path);

}  // namespace lungar::platform::record
