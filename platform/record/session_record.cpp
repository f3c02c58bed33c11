/// @file session_record.cpp
/// @brief The record's line format, its header and timeline as JSON, and the reader that stops at the first line that
///        is not whole.
#include "platform/record/session_record.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include "config/base/crc32.h"

namespace lungar::platform::record {

namespace {

/// Where a field is read: the file and line, for the one error line.
struct Where {
  const std::string& path;
  std::size_t line;
  std::string within;  ///< the fields' parent ("events[2]."), empty at the top
  Error bad(const std::string& field, const std::string& expected) const {
    return fail(path + ":" + std::to_string(line) + ": field '" + within + field + "': expected " + expected);
  }
};

Status read_number(const nlohmann::json& j, const char* key, const Where& w, double& out) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return w.bad(key, "a number");
  out = it->get<double>();
  return ok();
}

Status read_int(const nlohmann::json& j, const char* key, const Where& w, std::int64_t& out) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number_integer()) return w.bad(key, "an integer");
  out = it->get<std::int64_t>();
  return ok();
}

Status read_string(const nlohmann::json& j, const char* key, const Where& w, std::string& out) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_string()) return w.bad(key, "a string");
  out = it->get<std::string>();
  return ok();
}

Status read_strings(const nlohmann::json& j, const char* key, const Where& w, std::vector<std::string>& out) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array()) return w.bad(key, "an array of strings");
  out.clear();
  for (const auto& item : *it) {
    if (!item.is_string()) return w.bad(key, "an array of strings");
    out.push_back(item.get<std::string>());
  }
  return ok();
}

/// N numbers (null allowed when `nulls`, read as NaN).
template <std::size_t N>
Status read_numbers(const nlohmann::json& j, const char* key, const Where& w, std::array<double, N>& out,
                    bool nulls = false) {
  const auto it = j.find(key);
  const std::string expected = std::to_string(N) + (nulls ? " numbers (or nulls)" : " numbers");
  if (it == j.end() || !it->is_array() || it->size() != N) return w.bad(key, "an array of " + expected);
  for (std::size_t k = 0; k < N; ++k) {
    const auto& item = (*it)[k];
    if (!(item.is_number() || (nulls && item.is_null()))) return w.bad(key, "an array of " + expected);
    out[k] = item.is_null() ? std::numeric_limits<double>::quiet_NaN() : item.get<double>();
  }
  return ok();
}

std::optional<sim::BreathPhase> phase_named(const std::string& name) {
  for (sim::BreathPhase p : {sim::BreathPhase::Inspiration, sim::BreathPhase::Expiration, sim::BreathPhase::Hold,
                             sim::BreathPhase::Apnoea}) {
    if (name == sim::to_string(p)) return p;
  }
  return std::nullopt;
}

Status read_header(const nlohmann::json& j, const Where& w, SessionHeader& h) {
  const auto format = j.find("format");
  if (format == j.end() || !format->is_string() || *format != kSessionFormat)
    return fail(w.path + ":1: not a lungar session record (field 'format': expected \"" + kSessionFormat + "\")");
  const auto version = j.find("version");
  if (version == j.end() || !version->is_number_integer())
    return w.bad("version", "an integer (this lungar reads version " + std::to_string(kSessionVersion) + ")");
  if (*version != kSessionVersion)
    return w.bad("version", std::to_string(kSessionVersion) + " (the version this lungar reads), got " +
                                version->dump() + ": replay it with the lungar that recorded it");
  h.version = kSessionVersion;
  std::int64_t nodes = 0;
  const auto asset = j.find("asset");
  if (asset == j.end() || !asset->is_object()) return w.bad("asset", "an object (path, name, procedural, nodes)");
  const auto procedural = asset->find("procedural");
  if (procedural == asset->end() || !procedural->is_boolean()) return w.bad("asset.procedural", "true or false");
  h.procedural = procedural->get<bool>();
  const Where in_asset{w.path, w.line, "asset."}, in_registration{w.path, w.line, "registration."};
  const auto registration = j.find("registration");
  if (registration == j.end() || !registration->is_object())
    return w.bad("registration", "an object (translation_mm, rotation_wxyz)");
  for (Status s : {read_string(j, "station", w, h.station), read_string(j, "role", w, h.role),
                   read_string(j, "classroom", w, h.classroom), read_string(j, "started_utc", w, h.started_utc),
                   read_number(j, "started_unix_s", w, h.started_unix_s), read_string(j, "lungar", w, h.lungar_version),
                   read_string(j, "scenario", w, h.scenario), read_string(*asset, "path", in_asset, h.asset_path),
                   read_string(*asset, "name", in_asset, h.asset_name), read_int(*asset, "nodes", in_asset, nodes),
                   read_strings(j, "lungs", w, h.lungs), read_strings(j, "pathologies", w, h.pathologies),
                   read_strings(j, "lesions", w, h.lesions),
                   read_numbers(*registration, "translation_mm", in_registration, h.registration_translation_mm),
                   read_numbers(*registration, "rotation_wxyz", in_registration, h.registration_rotation_wxyz),
                   read_string(j, "orientation_mode", w, h.orientation_mode)}) {
    if (!s) return s.with_context("");
  }
  if (nodes <= 0) return w.bad("asset.nodes", "the asset's vertex count, above 0");
  h.nodes = static_cast<std::uint64_t>(nodes);
  const auto& q = h.registration_rotation_wxyz;
  if (std::abs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1.0) > 1e-3)
    return w.bad("registration.rotation_wxyz", "a unit quaternion");
  return ok();
}

/// `j` a frame line; `previous` the frame before (its pathologies stand when the line gives none).
Status read_frame(const nlohmann::json& j, const Where& w, const RecordedFrame* previous, RecordedFrame& f) {
  std::string phase;
  std::int64_t breath = 0, flags = 0;
  std::array<double, 3> patient_mm{}, origin{};
  std::array<double, 4> patient_q{}, lung_q{};
  for (Status s : {read_int(j, "i", w, f.index), read_number(j, "s", w, f.s), read_number(j, "t_s", w, f.breath.t_s),
                   read_number(j, "dv_ml", w, f.breath.dv_ml), read_number(j, "v_ml", w, f.breath.v_ml),
                   read_number(j, "v_frc_ml", w, f.breath.v_frc_ml), read_number(j, "p_cmh2o", w, f.breath.p_cmh2o),
                   read_number(j, "p_applied_cmh2o", w, f.breath.p_applied_cmh2o), read_string(j, "phase", w, phase),
                   read_int(j, "breath", w, breath), read_numbers(j, "lung_dv_ml", w, f.lung_dv_ml, true),
                   read_numbers(j, "source_lung_dv_ml", w, f.breath.lung_dv_ml, true),
                   read_numbers(j, "patient_mm", w, patient_mm), read_numbers(j, "patient_wxyz", w, patient_q),
                   read_int(j, "patient_flags", w, flags), read_numbers(j, "lung_origin_mm", w, origin),
                   read_numbers(j, "lung_in_world_wxyz", w, lung_q)}) {
    if (!s) return s.with_context("");
  }
  const auto p = phase_named(phase);
  if (!p) return w.bad("phase", "inspiration, expiration, hold or apnoea");
  f.breath.phase = *p;
  f.breath.breath = breath;
  f.patient.role = drivers::Role::Patient;
  f.patient.flags = static_cast<std::uint32_t>(flags);
  f.patient.position_mm = patient_mm;
  f.patient.orientation_wxyz = patient_q;
  f.lung_origin_mm = Eigen::Vector3d(origin[0], origin[1], origin[2]);
  f.lung_in_world = Eigen::Quaterniond(lung_q[0], lung_q[1], lung_q[2], lung_q[3]);
  if (const auto it = j.find("pathologies"); it != j.end()) {
    if (!it->is_string()) return w.bad("pathologies", "a string");
    f.pathologies = it->get<std::string>();
  } else if (previous != nullptr) {
    f.pathologies = previous->pathologies;
  }
  return ok();
}

Status read_timeline(const nlohmann::json& j, const Where& w, RecordedTimeline& t) {
  t.line = w.line;
  if (Status s = read_number(j, "s", w, t.s); !s) return s;
  if (Status s = read_strings(j, "start", w, t.timeline.start); !s) return s;
  const auto events = j.find("events");
  if (events == j.end() || !events->is_array()) return w.bad("events", "an array of pathology events");
  for (std::size_t k = 0; k < events->size(); ++k) {
    const auto& e = (*events)[k];
    const std::string where = "events[" + std::to_string(k) + "]";
    if (!e.is_object()) return w.bad(where, "an object (at_s, over_s, add, remove)");
    sim::PathologyEvent event;
    const Where inner{w.path, w.line, where + "."};
    for (Status s : {read_number(e, "at_s", inner, event.at_s), read_number(e, "over_s", inner, event.over_s),
                     read_string(e, "add", inner, event.add), read_string(e, "remove", inner, event.remove)}) {
      if (!s) return s;
    }
    t.timeline.events.push_back(std::move(event));
  }
  return ok();
}

/// A whole line after the header, into the record.
Status read_body_line(const nlohmann::json& j, const Where& w, SessionRecord& r) {
  std::string type;
  if (Status s = read_string(j, "type", w, type); !s) return s;
  if (type == "frame") {
    RecordedFrame f;
    if (Status s = read_frame(j, w, r.frames.empty() ? nullptr : &r.frames.back(), f); !s) return s;
    r.frames.push_back(std::move(f));
  } else if (type == "timeline") {
    RecordedTimeline t;
    if (Status s = read_timeline(j, w, t); !s) return s;
    r.timelines.push_back(std::move(t));
  } else if (type == "event") {
    RecordedEvent e;
    for (Status s : {read_number(j, "s", w, e.s), read_number(j, "t_s", w, e.t_s), read_string(j, "kind", w, e.kind),
                     read_string(j, "user", w, e.user), read_string(j, "text", w, e.text)}) {
      if (!s) return s;
    }
    r.events.push_back(std::move(e));
  } else if (type == "stations") {
    RecordedStations st;
    if (Status s = read_number(j, "s", w, st.s); !s) return s;
    const auto it = j.find("stations");
    if (it == j.end()) return w.bad("stations", "each station's status");
    st.stations = *it;
    r.stations.push_back(std::move(st));
  } else if (type == "end") {
    std::int64_t dropped = 0;
    if (Status s = read_int(j, "dropped_frames", w, dropped); !s) return s;
    r.dropped_frames = static_cast<std::uint64_t>(std::max<std::int64_t>(dropped, 0));
    r.ended = true;
  } else {
    return w.bad("type", "frame, timeline, event, stations or end, got \"" + type + "\"");
  }
  return ok();
}

/// The JSON text of a whole line whose CRC matches; none when the line is corrupt.
std::optional<std::string_view> checked_json(std::string_view line) {
  if (line.size() < 10 || line[8] != ' ') return std::nullopt;
  std::uint32_t crc = 0;
  for (std::size_t k = 0; k < 8; ++k) {
    const char c = line[k];
    const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (digit < 0) return std::nullopt;
    crc = (crc << 4) | static_cast<std::uint32_t>(digit);
  }
  const std::string_view json = line.substr(9);
  if (crc32(json.data(), json.size()) != crc) return std::nullopt;
  return json;
}

}  // namespace

std::string session_line(std::string_view json) {
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x ", crc32(json.data(), json.size()));
  std::string line;
  line.reserve(json.size() + 10);
  line.append(crc).append(json).push_back('\n');
  return line;
}

nlohmann::ordered_json header_json(const SessionHeader& h) {
  nlohmann::ordered_json j;
  j["type"] = "header";
  j["format"] = kSessionFormat;
  j["version"] = h.version;
  j["station"] = h.station;
  j["role"] = h.role;
  j["classroom"] = h.classroom;
  j["started_utc"] = h.started_utc;
  j["started_unix_s"] = h.started_unix_s;
  j["lungar"] = h.lungar_version;
  j["scenario"] = h.scenario;
  j["asset"] = {{"path", h.asset_path}, {"name", h.asset_name}, {"procedural", h.procedural}, {"nodes", h.nodes}};
  j["lungs"] = h.lungs;
  j["pathologies"] = h.pathologies;
  j["lesions"] = h.lesions;
  j["registration"] = {{"translation_mm", h.registration_translation_mm},
                       {"rotation_wxyz", h.registration_rotation_wxyz}};
  j["orientation_mode"] = h.orientation_mode;
  return j;
}

nlohmann::ordered_json timeline_json(double s, const sim::PathologyTimeline& timeline) {
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const sim::PathologyEvent& e : timeline.events)
    events.push_back({{"at_s", e.at_s}, {"over_s", e.over_s}, {"add", e.add}, {"remove", e.remove}});
  nlohmann::ordered_json j;
  j["type"] = "timeline";
  j["s"] = s;
  j["start"] = timeline.start;
  j["events"] = events;
  return j;
}

Result<SessionRecord> read_session_record(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path + ": cannot read the session record: " + std::strerror(errno));
  std::ostringstream text_stream;
  text_stream << in.rdbuf();
  const std::string text = text_stream.str();
  SessionRecord r;
  r.path = path;
  if (text.empty()) return fail(path + ": empty: not a lungar session record (no header line)");
  std::size_t at = 0;
  for (std::size_t line = 1; at < text.size(); ++line) {
    const std::size_t end = text.find('\n', at);
    const Where w{path, line, ""};
    if (end == std::string::npos) {  // a kill mid-write: everything before it stands
      if (line == 1) return fail(path + ":1: the header line is torn (no newline at its end): not a whole record");
      r.cut = "line " + std::to_string(line) + ": torn (no newline at its end: the recording stopped mid-line)";
      break;
    }
    const std::string_view whole(text.data() + at, end - at);
    at = end + 1;
    const auto json_text = checked_json(whole);
    if (!json_text) {
      if (line == 1)
        return fail(path + ":1: not a lungar session record (expected a first line 'CRC32HEX {\"format\": \"" +
                    kSessionFormat + "\", ...}' whose CRC matches)");
      r.cut = "line " + std::to_string(line) + ": corrupt (its CRC does not match)";
      break;
    }
    const nlohmann::json j = nlohmann::json::parse(*json_text, nullptr, false);
    if (!j.is_object()) {
      if (line == 1) return fail(path + ":1: not a lungar session record (its first line is not a JSON object)");
      return fail(path + ":" + std::to_string(line) + ": expected a JSON object (the CRC matches: a writer's fault)");
    }
    ++r.lines;
    if (Status s = line == 1 ? read_header(j, w, r.header) : read_body_line(j, w, r); !s) return Error{s.error()};
    if (r.ended) break;
  }
  return r;
}

}  // namespace lungar::platform::record
