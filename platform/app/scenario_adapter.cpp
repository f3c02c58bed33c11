/// @file scenario_adapter.cpp
/// @brief config::Scenario (plain data from TOML) -> sim::BreathingDriver events and sim::OrientationTrack turns.
#include "platform/app/scenario_adapter.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "config/scenario_load.h"

namespace lungar::platform {

namespace {

Eigen::Quaterniond rotation(const std::string& pose, const std::array<double, 4>& wxyz) {
  if (!pose.empty()) {
    if (auto p = sim::pose_from_name(pose)) return sim::pose_rotation(*p);
  }
  return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized();
}

/// The breathing keys shared by change, ventilator and spontaneous.
Status fill_change(const config::ScenarioEvent& e, sim::PatternChange& c) {
  if (e.preset) {
    c.preset = sim::preset_from_name(*e.preset);
    if (!c.preset) return fail("preset: expected a known preset, got \"" + *e.preset + "\"");
  }
  c.rate_bpm = e.rate_bpm;
  c.ie_ratio = e.ie_ratio;
  c.tidal_volume_ml = e.tidal_volume_ml;
  return ok();
}

}  // namespace

Result<sim::BreathingParams> to_breathing_params(const config::BreathingSettings& b) {
  const auto preset = sim::preset_from_name(b.preset);
  if (!preset) return fail("preset: expected " + kPresetNames.expected() + ", got \"" + b.preset + "\"");
  sim::BreathingParams out;
  out.preset = *preset;
  out.rate_bpm = b.rate_bpm;
  out.ie_ratio = b.ie_ratio;
  out.tidal_volume_ml = b.tidal_volume_ml;
  return out;
}

Result<sim::BreathingScript> make_breathing_script(const config::Scenario& sc) {
  auto start = to_breathing_params(sc.start);
  if (!start) return start.with_context(sc.source + ": [start] ");
  auto driver = sim::BreathingDriver::create(*start);
  if (!driver) return driver.with_context(sc.source + ": [start]: ");

  // Each scenario event becomes one or two driver events (a hold and an apnoea also end) or a turn.
  std::vector<std::pair<sim::Event, const config::ScenarioEvent*>> events;
  std::vector<sim::Turn> turns;
  for (const config::ScenarioEvent& e : sc.events) {
    sim::PatternChange change;
    switch (e.kind) {
      case config::ScenarioEventKind::Turn:
        turns.push_back({e.at_s, e.over_s, rotation(e.pose, e.rotation_wxyz)});
        break;
      case config::ScenarioEventKind::Change:
      case config::ScenarioEventKind::Ventilator:
      case config::ScenarioEventKind::Spontaneous:
        if (Status err = fill_change(e, change); !err) return err.with_context(sc.where(e, "") + ": ");
        if (e.kind == config::ScenarioEventKind::Ventilator) {
          change.mode = sim::Mode::Ventilator;
          change.peep_cmh2o = e.peep_cmh2o;
          change.ventilator_tau_s = e.tau_s;
        } else if (e.kind == config::ScenarioEventKind::Spontaneous) {
          change.mode = sim::Mode::Spontaneous;
        }
        events.push_back({sim::Event::set(e.at_s, change, e.over_s), &e});
        break;
      case config::ScenarioEventKind::Sigh:
        events.push_back({sim::Event::sigh(e.at_s, e.volume_ml.value_or(0.0)), &e});
        break;
      case config::ScenarioEventKind::Hold:
        events.push_back({sim::Event::of(e.at_s, sim::EventKind::HoldStart), &e});
        events.push_back({sim::Event::of(e.at_s + e.duration_s, sim::EventKind::HoldEnd), &e});
        break;
      case config::ScenarioEventKind::Apnoea:
        events.push_back({sim::Event::of(e.at_s, sim::EventKind::ApnoeaStart), &e});
        events.push_back({sim::Event::of(e.at_s + e.duration_s, sim::EventKind::ApnoeaEnd), &e});
        break;
      case config::ScenarioEventKind::Pathology:  // the lungs', not the breathing's (platform/runtime/pathology_course.h)
        break;
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.first.t_s < b.first.t_s; });
  for (const auto& [event, source] : events) {
    if (Status err = driver->apply(event); !err) return err.with_context(sc.where(*source, "") + ": ");
  }
  auto track = sim::OrientationTrack::create(rotation(sc.start_pose, sc.start_rotation_wxyz), std::move(turns));
  if (!track) return track.with_context(sc.source + ": ");
  sim::BreathingScript script{driver.take(), track.take(), sc.duration_s, *start, {}};
  for (const auto& applied : events) script.events.push_back(applied.first);
  return script;
}

Result<sim::BreathingScript> load_breathing_script(const config::BreathingSettings& breathing, double duration_s) {
  if (!breathing.scenario.empty()) {
    auto loaded = config::load_scenario(breathing.scenario, breathing);
    if (!loaded) return loaded.with_context("");
    return make_breathing_script(*loaded);
  }
  config::Scenario steady;
  steady.source = "[breathing]";
  steady.name = "steady";
  steady.start = breathing;
  steady.duration_s = duration_s;
  return make_breathing_script(steady);
}

}  // namespace lungar::platform
