/// @file session_recording.cpp
/// @brief The record's path and header from the settings, and the recorder among the frame's listeners.
#include "platform/app/session_recording.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include "config/base/clock.h"
#include "lungar/version.h"
#include "platform/app/log.h"
#include "sim/force/force_sh.h"

namespace lungar::platform {

namespace {

/// This station's name for the record: its classroom name, else the host's.
std::string station_name(const Settings& s) {
  if (!s.sync.station.empty()) return s.sync.station;
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0 || host[0] == '\0') return "lungar";
  return host;
}

/// `name` with only what a file name may safely hold (letters, digits, '-', '_', '.'; others '_').
std::string file_safe(std::string name) {
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  }
  return name;
}

record::SessionHeader header_of(const Settings& s, const RuntimeOptions& o, const LungScene& scene,
                                const std::string& station) {
  record::SessionHeader h;
  h.station = station;
  h.role = classroom::kSyncRoleNames.name(s.sync.role);
  h.classroom = s.sync.role == classroom::SyncRole::Off ? "" : s.sync.classroom;
  h.started_utc = utc_timestamp();
  h.started_unix_s = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  h.lungar_version = LUNGAR_VERSION;
  h.scenario = s.breathing.scenario;
  h.asset_path = s.sim.asset;
  h.asset_name = scene.name();
  h.procedural = o.procedural;
  h.nodes = scene.asset().vertex_count();
  for (const sim::BakedLung& lung : scene.asset().lungs) h.lungs.push_back(lung.name);
  h.pathologies = s.sim.pathologies;
  h.lesions = s.sim.lesions;
  h.registration_translation_mm = s.registration.translation_mm;
  h.registration_rotation_wxyz = s.registration.rotation_wxyz;
  h.orientation_mode = sim::to_string(s.sim.orientation_mode);
  return h;
}

}  // namespace

std::string session_record_path(const std::string& given, const std::string& station) {
  std::error_code ec;
  if (!std::filesystem::is_directory(given, ec)) return given;
  std::string stamp = utc_timestamp();
  std::replace(stamp.begin(), stamp.end(), ':', '-');  // no colons: they trouble scp and other tools
  return (std::filesystem::path(given) / (stamp + "-" + file_safe(station) + record::kSessionExtension)).string();
}

Status check_session_record_path(const std::string& given) {
  if (given.empty()) return ok();
  const std::string where = "--session-record: " + given + ": ";
  std::error_code ec;
  if (std::filesystem::is_directory(given, ec)) {
    if (::access(given.c_str(), W_OK) != 0)
      return fail(where + "cannot write into this folder: " + std::strerror(errno));
    return ok();
  }
  if (std::filesystem::exists(given, ec))
    return fail(where + "exists already (a record is never overwritten): give a new file, or a folder");
  const std::filesystem::path parent = std::filesystem::path(given).parent_path();
  const std::string folder = parent.empty() ? "." : parent.string();
  if (!std::filesystem::is_directory(folder, ec)) return fail(where + "expected a file in an existing folder");
  if (::access(folder.c_str(), W_OK) != 0)
    return fail(where + "cannot write into " + folder + ": " + std::strerror(errno));
  return ok();
}

Result<std::shared_ptr<record::SessionRecorder>> start_session_recording(const Settings& s, const RuntimeOptions& o,
                                                                         const sim::PathologyTimeline& timeline,
                                                                         std::int64_t t0, RuntimeParts& parts) {
  if (o.session_record_path.empty()) return std::shared_ptr<record::SessionRecorder>();
  const std::string station = station_name(s);
  const std::string path = session_record_path(o.session_record_path, station);
  auto made = record::SessionRecorder::create(path, header_of(s, o, *parts.scene, station), t0, parts.course,
                                              [](const std::string& line) { log_line(line); });
  if (!made) return made.with_context("--session-record: ");
  std::shared_ptr<record::SessionRecorder> recorder = made.take();
  recorder->note_timeline(timeline);
  parts.listeners.push_back(recorder);
  log_line("session record: " + path);
  return recorder;
}

bool finish_session_recording(const std::shared_ptr<record::SessionRecorder>& recorder) {
  if (!recorder) return true;
  const Status closed = recorder->close();
  if (!closed) return false;  // the recorder said it when the write failed
  const std::uint64_t dropped = recorder->dropped_frames();
  log_line("session record: " + recorder->path() + " closed" +
           (dropped > 0 ? " (" + std::to_string(dropped) + " frames dropped: the disk fell behind)" : ""));
  return true;
}

}  // namespace lungar::platform
