/// @file wire.cpp
/// @brief Checked conversions between the classroom's IDL types and lungar's.
#include "drivers/classroom/wire.h"

#include "config/base/number_text.h"
#include "drivers/classroom/sync_types.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace lungar::classroom {

namespace {

/// Bits of ScenarioEvent::set: which optional fields of a change carry a value.
enum SetBit : std::uint32_t {
  kSetPreset = 1u << 0,
  kSetRate = 1u << 1,
  kSetIe = 1u << 2,
  kSetTidal = 1u << 3,
  kSetMode = 1u << 4,
  kSetTau = 1u << 5,
  kSetPeep = 1u << 6,
  kSetAll = (1u << 7) - 1,
};
constexpr std::uint8_t kPresetCount = 3;     // sim::Preset's values
constexpr std::uint8_t kModeCount = 2;       // sim::Mode's values
constexpr std::uint8_t kEventKindCount = 6;  // sim::EventKind's values

Status finite(const char* topic, const char* field, double v) {
  if (std::isfinite(v)) return ok();
  return fail(std::string(topic) + ": " + field + ": expected a finite number, got " + number_text(v));
}

/// BreathingParams and BreathingState carry the same fields by the same names (the enums as bytes on the wire),
/// so one copy serves both directions.
template <class From, class To>
void copy_params(const From& from, To& to) {
  to.preset = static_cast<decltype(to.preset)>(from.preset);
  to.mode = static_cast<decltype(to.mode)>(from.mode);
  to.rate_bpm = from.rate_bpm;
  to.ie_ratio = from.ie_ratio;
  to.tidal_volume_ml = from.tidal_volume_ml;
  to.ventilator_tau_s = from.ventilator_tau_s;
  to.peep_cmh2o = from.peep_cmh2o;
}

template <class T>
void set_if(std::uint32_t set, std::uint32_t bit, std::optional<T>& field, T value) {
  if (set & bit) field = value;
}

}  // namespace

Result<SharedPose> from_wire(const lungar_sync_PatientPose& s) {
  constexpr const char* kTopic = "lungar_patient_pose";
  SharedPose p;
  const std::array<double, 3> position{s.position_mm.x, s.position_mm.y, s.position_mm.z};
  const std::array<double, 4> orientation{s.orientation_wxyz.w, s.orientation_wxyz.x, s.orientation_wxyz.y,
                                          s.orientation_wxyz.z};
  double norm_sq = 0;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(position[i]) || std::abs(position[i]) > kMaxPositionMm) {
      return fail(std::string(kTopic) + ": position_mm[" + std::to_string(i) + "]: expected a finite number within " +
                  number_text(kMaxPositionMm) + " mm, got " + number_text(position[i]));
    }
    p.position_mm[i] = position[i];
  }
  for (int i = 0; i < 4; ++i) {
    if (Status f = finite(kTopic, "orientation_wxyz", orientation[i]); !f) return Error{f.error()};
    p.orientation_wxyz[i] = orientation[i];
    norm_sq += orientation[i] * orientation[i];
  }
  if (std::abs(std::sqrt(norm_sq) - 1.0) > kQuaternionNormTolerance) {
    return fail(std::string(kTopic) + ": orientation_wxyz: expected a unit quaternion (norm 1 +- " +
                number_text(kQuaternionNormTolerance) + "), got norm " + number_text(std::sqrt(norm_sq)));
  }
  if (s.measured_ns <= 0) return fail(std::string(kTopic) + ": measured_ns: expected a time after the epoch");
  p.measured_ns = s.measured_ns;
  return p;
}

void to_wire(const SharedPose& pose, std::uint64_t session, std::uint32_t seq, lungar_sync_PatientPose& out) {
  out.session = session;
  out.seq = seq;
  out.position_mm = {pose.position_mm[0], pose.position_mm[1], pose.position_mm[2]};
  out.orientation_wxyz = {pose.orientation_wxyz[0], pose.orientation_wxyz[1], pose.orientation_wxyz[2],
                          pose.orientation_wxyz[3]};
  out.measured_ns = pose.measured_ns;
}

Result<sim::BreathingParams> from_wire(const lungar_sync_BreathingState& s) {
  constexpr const char* kTopic = "lungar_breathing_state";
  if (s.preset >= kPresetCount) {
    return fail(std::string(kTopic) + ": preset: expected 0..2 (normal, emphysema, fibrosis), got " +
                std::to_string(s.preset));
  }
  if (s.mode >= kModeCount) {
    return fail(std::string(kTopic) + ": mode: expected 0 or 1 (spontaneous, ventilator), got " +
                std::to_string(s.mode));
  }
  if (s.time_base_ns <= 0) return fail(std::string(kTopic) + ": time_base_ns: expected a time after the epoch");
  sim::BreathingParams p;
  copy_params(s, p);
  if (Status e = sim::validate(p); !e) return e.with_context(std::string(kTopic) + ": ");
  return p;
}

void to_wire(const sim::BreathingParams& p, lungar_sync_BreathingState& out) { copy_params(p, out); }

Result<std::vector<sim::Event>> from_wire(const lungar_sync_ScenarioEvents& s) {
  std::vector<sim::Event> events;
  events.reserve(s.events._length);
  double previous = 0;
  for (std::uint32_t i = 0; i < s.events._length; ++i) {
    const lungar_sync_ScenarioEvent& w = s.events._buffer[i];
    const std::string where = "lungar_scenario_events: events[" + std::to_string(i) + "]";
    if (!std::isfinite(w.t_s) || w.t_s < previous) {
      return fail(where + ": t_s: expected a finite time not before the previous event's " + number_text(previous) +
                  " s, got " + number_text(w.t_s));
    }
    previous = w.t_s;
    if (w.kind >= kEventKindCount) return fail(where + ": kind: expected 0..5, got " + std::to_string(w.kind));
    if ((w.set & ~kSetAll) != 0) return fail(where + ": set: expected bits 0..6, got " + std::to_string(w.set));
    if ((w.set & kSetPreset) && w.preset >= kPresetCount) {
      return fail(where + ": preset: expected 0..2, got " + std::to_string(w.preset));
    }
    if ((w.set & kSetMode) && w.mode >= kModeCount) {
      return fail(where + ": mode: expected 0 or 1, got " + std::to_string(w.mode));
    }
    for (double v : {w.rate_bpm, w.ie_ratio, w.tidal_volume_ml, w.ventilator_tau_s, w.peep_cmh2o, w.sigh_volume_ml,
                     w.transition_s}) {
      if (!std::isfinite(v)) return fail(where + ": expected finite numbers, got " + number_text(v));
    }
    sim::Event e;
    e.t_s = w.t_s;
    e.kind = static_cast<sim::EventKind>(w.kind);
    e.sigh_volume_ml = w.sigh_volume_ml;
    e.transition_s = w.transition_s;
    set_if(w.set, kSetPreset, e.change.preset, static_cast<sim::Preset>(w.preset));
    set_if(w.set, kSetRate, e.change.rate_bpm, w.rate_bpm);
    set_if(w.set, kSetIe, e.change.ie_ratio, w.ie_ratio);
    set_if(w.set, kSetTidal, e.change.tidal_volume_ml, w.tidal_volume_ml);
    set_if(w.set, kSetMode, e.change.mode, static_cast<sim::Mode>(w.mode));
    set_if(w.set, kSetTau, e.change.ventilator_tau_s, w.ventilator_tau_s);
    set_if(w.set, kSetPeep, e.change.peep_cmh2o, w.peep_cmh2o);
    events.push_back(e);
  }
  return events;
}

Status to_wire(std::span<const sim::Event> events, std::vector<lungar_sync_ScenarioEvent>& storage,
               lungar_sync_ScenarioEvents& out) {
  if (events.size() > kMaxScenarioEvents) {
    return fail("sync: the scenario has " + std::to_string(events.size()) +
                " breathing events; a classroom carries at most " + std::to_string(kMaxScenarioEvents));
  }
  storage.assign(events.size(), lungar_sync_ScenarioEvent{});
  for (std::size_t i = 0; i < events.size(); ++i) {
    const sim::Event& e = events[i];
    lungar_sync_ScenarioEvent& w = storage[i];
    w.t_s = e.t_s;
    w.kind = static_cast<std::uint8_t>(e.kind);
    w.sigh_volume_ml = e.sigh_volume_ml;
    w.transition_s = e.transition_s;
    const sim::PatternChange& c = e.change;
    if (c.preset) w.set |= kSetPreset, w.preset = static_cast<std::uint8_t>(*c.preset);
    if (c.rate_bpm) w.set |= kSetRate, w.rate_bpm = *c.rate_bpm;
    if (c.ie_ratio) w.set |= kSetIe, w.ie_ratio = *c.ie_ratio;
    if (c.tidal_volume_ml) w.set |= kSetTidal, w.tidal_volume_ml = *c.tidal_volume_ml;
    if (c.mode) w.set |= kSetMode, w.mode = static_cast<std::uint8_t>(*c.mode);
    if (c.ventilator_tau_s) w.set |= kSetTau, w.ventilator_tau_s = *c.ventilator_tau_s;
    if (c.peep_cmh2o) w.set |= kSetPeep, w.peep_cmh2o = *c.peep_cmh2o;
  }
  out.events._buffer = storage.data();
  out.events._length = static_cast<std::uint32_t>(storage.size());
  out.events._maximum = static_cast<std::uint32_t>(storage.size());
  out.events._release = false;
  return ok();
}

namespace {

/// A bounded string of the sample as text; its bound is the array's size less the terminator, which Cyclone
/// checks on receipt (a string without one is not delivered).
template <std::size_t N>
std::string text_of(const char (&chars)[N]) {
  return std::string(chars, ::strnlen(chars, N));
}

template <std::size_t N>
Status copy_text(const std::string& text, const char* field, char (&out)[N]) {
  if (text.size() >= N) {
    return fail("sync: " + std::string(field) + " '" + text + "' is longer than a classroom carries (" +
                std::to_string(N - 1) + " characters)");
  }
  std::memcpy(out, text.c_str(), text.size() + 1);
  return ok();
}

}  // namespace

Result<sim::PathologyTimeline> pathologies_from_wire(const lungar_sync_ScenarioEvents& s) {
  sim::PathologyTimeline timeline;
  const std::string list = text_of(s.pathologies);
  for (std::size_t from = 0; from < list.size();) {
    const std::size_t comma = std::min(list.find(',', from), list.size());
    timeline.start.push_back(list.substr(from, comma - from));
    from = comma + 1;
  }
  for (std::uint32_t i = 0; i < s.pathology_events._length; ++i) {
    const lungar_sync_PathologyEvent& w = s.pathology_events._buffer[i];
    timeline.events.push_back({w.t_s, w.over_s, text_of(w.add), text_of(w.remove)});
  }
  if (Status c = sim::check_timeline(timeline); !c) return c.with_context("lungar_scenario_events: ");
  return timeline;
}

Status to_wire(const sim::PathologyTimeline& timeline, std::vector<lungar_sync_PathologyEvent>& storage,
               lungar_sync_ScenarioEvents& out) {
  if (timeline.events.size() > kMaxPathologyEvents) {
    return fail("sync: the scenario has " + std::to_string(timeline.events.size()) +
                " pathology events; a classroom carries at most " + std::to_string(kMaxPathologyEvents));
  }
  std::string list;
  for (const std::string& spec : timeline.start) list += (list.empty() ? "" : ",") + spec;
  if (Status c = copy_text(list, "the pathology list", out.pathologies); !c) return c;
  storage.assign(timeline.events.size(), lungar_sync_PathologyEvent{});
  for (std::size_t i = 0; i < timeline.events.size(); ++i) {
    const sim::PathologyEvent& e = timeline.events[i];
    storage[i].t_s = e.at_s;
    storage[i].over_s = e.over_s;
    if (Status c = copy_text(e.add, "the pathology", storage[i].add); !c) return c;
    if (Status c = copy_text(e.remove, "the pathology", storage[i].remove); !c) return c;
  }
  out.pathology_events._buffer = storage.data();
  out.pathology_events._length = static_cast<std::uint32_t>(storage.size());
  out.pathology_events._maximum = static_cast<std::uint32_t>(storage.size());
  out.pathology_events._release = false;
  return ok();
}

Result<std::optional<bool>> ventilation_map_from_wire(const lungar_sync_ScenarioEvents& s) {
  switch (s.ventilation_map) {
    case 0:
      return std::optional<bool>();
    case 1:
      return std::optional<bool>(false);
    case 2:
      return std::optional<bool>(true);
    default:
      return fail("lungar_scenario_events: ventilation_map: expected 0 (each station's own), 1 (off) or 2 (on), got " +
                  std::to_string(s.ventilation_map));
  }
}

void ventilation_map_to_wire(std::optional<bool> on, lungar_sync_ScenarioEvents& out) {
  out.ventilation_map = !on ? 0 : *on ? 2 : 1;
}

Status check(const lungar_sync_Heartbeat& s) {
  if (Status f = finite("lungar_heartbeat", "breath_t_s", s.breath_t_s); !f) return f;
  if (s.frame_ns <= 0) return fail("lungar_heartbeat: frame_ns: expected a time after the epoch");
  if (!s.followed) return ok();
  const auto plausible = [](const char* field, double v, bool nan_allowed) -> Status {
    if ((nan_allowed && std::isnan(v)) || (std::isfinite(v) && std::abs(v) <= kMaxSharedDvMl)) return ok();
    return fail(std::string("lungar_heartbeat: ") + field + ": expected a volume change within +-" +
                std::to_string(static_cast<int>(kMaxSharedDvMl)) + " mL" + (nan_allowed ? " or NaN" : "") + ", got " +
                std::to_string(v));
  };
  if (Status v = plausible("dv_ml", s.dv_ml, false); !v) return v;
  if (Status v = plausible("left_dv_ml", s.left_dv_ml, true); !v) return v;
  return plausible("right_dv_ml", s.right_dv_ml, true);
}

Status check(const lungar_sync_Station& s) {
  if (s.role != 1 && s.role != 2) {
    return fail("lungar_station: role: expected 1 (instructor) or 2 (trainee), got " + std::to_string(s.role));
  }
  if (s.name[0] == '\0') return fail("lungar_station: name: expected a station name, got an empty one");
  return ok();
}

Status check(const lungar_sync_StationStatus& s) {
  if (s.name[0] == '\0') return fail("lungar_station_status: name: expected a station name, got an empty one");
  if (s.state > static_cast<std::uint8_t>(SyncState::Lost))
    return fail("lungar_station_status: state: expected a sync state (0 to " +
                std::to_string(static_cast<int>(SyncState::Lost)) + "), got " + std::to_string(s.state));
  for (auto [name, v] :
       {std::pair{"breath_offset_ms", s.breath_offset_ms}, {"pose_age_ms", s.pose_age_ms}, {"fps", s.fps}}) {
    if (!std::isfinite(v) || v < 0)
      return fail(std::string("lungar_station_status: ") + name + ": expected a real number, not negative");
  }
  return ok();
}

}  // namespace lungar::classroom
