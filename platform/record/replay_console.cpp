/// @file replay_console.cpp
/// @brief The record at the replay's cursor as the console's live view; every control refused.
#include "platform/record/replay_console.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "platform/record/timeline_csv.h"

namespace lungar::platform::record {

namespace {

/// "pitch" and "roll" of a lung orientation, degrees, as the live class gives them (class_control.cpp): its long
/// axis (+z) from the vertical, and the side tilt.
std::pair<double, double> tilt_deg(const Eigen::Quaterniond& q) {
  const Eigen::Vector3d up = q * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d front = q * Eigen::Vector3d::UnitY();
  const double kDeg = 180.0 / M_PI;
  return {std::atan2(up.y(), up.z()) * kDeg, std::atan2(-front.x(), front.y()) * kDeg};
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

/// The first frame after session time `s`.
std::vector<RecordedFrame>::const_iterator frame_after(const std::vector<RecordedFrame>& f, double s) {
  return std::upper_bound(f.begin(), f.end(), s, [](double t, const RecordedFrame& x) { return t < x.s; });
}

/// A frame's pathologies label ("a, b (coming)", "none", "" without a course) as the present ones and those
/// coming or going; `loaded`: the header's, for a record whose lungs had no course.
void split_pathologies(const std::string& label, const std::vector<std::string>& loaded, nlohmann::json& present,
                       std::string& changing) {
  present = nlohmann::json::array();
  if (label.empty()) {
    for (const std::string& spec : loaded) present.push_back(spec);
    return;
  }
  if (label == "none") return;
  std::size_t from = 0;
  while (from <= label.size()) {
    const std::size_t comma = std::min(label.find(", ", from), label.size());
    const std::string item = label.substr(from, comma - from);
    from = comma + 2;
    if (item.empty()) continue;
    const bool coming = item.ends_with(" (coming)"), going = item.ends_with(" (going)");
    // One coming or going is present, as in the live view (one under way counts), and said as changing.
    if (coming || going) changing += (changing.empty() ? "" : ", ") + item;
    present.push_back(coming ? item.substr(0, item.size() - 9) : going ? item.substr(0, item.size() - 8) : item);
  }
}

}  // namespace

ReplayConsole::ReplayConsole(std::shared_ptr<const SessionPlayback> playback)
    : playback_(std::move(playback)), cursor_s_(playback_->first_s()) {
  const SessionRecord& r = playback_->record();
  file_ = std::filesystem::path(r.path).filename().string();
  events_ = nlohmann::json::array();
  for (const RecordedEvent& e : r.events)
    events_.push_back({{"t_s", e.s}, {"breath_s", e.t_s}, {"kind", e.kind}, {"user", e.user}, {"text", e.text}});
  timeline_csv_ = record::timeline_csv(r);
}

void ReplayConsole::on_frame(const FrameState& state) {
  const double s = std::clamp(playback_->session_s(state.now_ns), playback_->first_s(), playback_->last_s());
  cursor_s_.store(s, std::memory_order_relaxed);
}

nlohmann::json ReplayConsole::view_at(double s) const {
  const SessionRecord& r = playback_->record();
  const RecordedFrame& now = *playback_->around(s).before;
  nlohmann::json j;
  j["station"] = r.header.station;
  j["t_s"] = s;
  j["refused"] = refused_count();
  j["replay"] = {{"session_s", s}, {"duration_s", playback_->last_s()}, {"file", file_}};
  const sim::BreathPhase phase = now.breath.phase;
  j["breath"] = {{"state", phase == sim::BreathPhase::Hold     ? "paused"
                           : phase == sim::BreathPhase::Apnoea ? "apnoea"
                                                               : "breathing"},
                 {"phase", sim::to_string(phase)},
                 {"source", "replay"},
                 {"breath", now.breath.breath},
                 {"dv_ml", now.breath.dv_ml}};
  nlohmann::json samples = nlohmann::json::array();
  const auto end = frame_after(r.frames, s + SessionPlayback::kSnapS);
  for (auto f = frame_after(r.frames, s - kSamplesS); f != end; ++f)
    samples.push_back({f->s, f->breath.dv_ml, number_or_null(f->lung_dv_ml[0]), number_or_null(f->lung_dv_ml[1])});
  j["samples"] = std::move(samples);
  const Eigen::Quaterniond& q = now.lung_in_world;
  const auto [pitch, roll] = tilt_deg(q);
  j["orientation"] = {{"wxyz", {q.w(), q.x(), q.y(), q.z()}}, {"pitch_deg", pitch}, {"roll_deg", roll}};
  nlohmann::json present;
  std::string changing;
  split_pathologies(now.pathologies, r.header.pathologies, present, changing);
  j["pathologies"] = std::move(present);
  j["pathologies_changing"] = changing;
  nlohmann::json stations = nlohmann::json::array();
  for (const RecordedStations& st : r.stations)  // in the order noted: the last one at or before the cursor
    if (st.s <= s + SessionPlayback::kSnapS) stations = st.stations;
  j["stations"] = std::move(stations);
  j["events"] = events_;
  j["presets"] = nlohmann::json::array();
  j["pathology_forms"] = nlohmann::json::array();
  return j;
}

std::string ReplayConsole::snapshot_json() { return view_at(cursor_s()).dump(); }

console::ControlReply ReplayConsole::control(const console::ConsoleUser&, const nlohmann::json&) {
  return {409,
          {{"error", "a replay is read-only: it plays the record " + file_ +
                         "; the class is changed from a live instructor's console"}}};
}

std::string ReplayConsole::timeline_csv() { return timeline_csv_; }

void ReplayConsole::refused(int, const std::string&) { refused_.fetch_add(1, std::memory_order_relaxed); }

}  // namespace lungar::platform::record
