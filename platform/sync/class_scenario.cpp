/// @file class_scenario.cpp
/// @brief A scenario's steps, the state they reach by a time, and the steps after it on class time.
#include "platform/sync/class_scenario.h"

#include <algorithm>
#include <cstdio>

#include "platform/runtime/pathology_course.h"

namespace lungar::platform::sync {

namespace {

/// "rate 28/min, 350 mL over 10 s" and the like: what a cue shows on the page.
std::string cue_text(const config::ScenarioEvent& e) {
  char line[200];
  std::string text;
  switch (e.kind) {
    case config::ScenarioEventKind::Turn:
      text = "to " + (e.pose.empty() ? std::string("a rotation") : e.pose);
      break;
    case config::ScenarioEventKind::Pathology:
      text = e.pathology_add.empty()      ? "remove " + e.pathology_remove
             : e.pathology_remove.empty() ? "add " + e.pathology_add
                                          : e.pathology_remove + " -> " + e.pathology_add;
      break;
    case config::ScenarioEventKind::Hold:
    case config::ScenarioEventKind::Apnoea:
      std::snprintf(line, sizeof line, "for %.1f s", e.duration_s);
      text = line;
      break;
    default:
      if (e.preset) text += *e.preset + " ";
      if (e.rate_bpm) text += std::to_string(static_cast<int>(*e.rate_bpm + 0.5)) + "/min ";
      if (e.tidal_volume_ml) text += std::to_string(static_cast<int>(*e.tidal_volume_ml + 0.5)) + " mL ";
      if (e.ie_ratio) {
        std::snprintf(line, sizeof line, "I:E %.2f ", *e.ie_ratio);
        text += line;
      }
      break;
  }
  if (e.over_s > 0) {
    std::snprintf(line, sizeof line, "%sover %.1f s", text.empty() || text.back() == ' ' ? "" : " ", e.over_s);
    text += line;
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

/// `params` with what `c` sets.
void apply(const sim::PatternChange& c, sim::BreathingParams& params) {
  if (c.preset) params.preset = *c.preset;
  if (c.rate_bpm) params.rate_bpm = *c.rate_bpm;
  if (c.ie_ratio) params.ie_ratio = *c.ie_ratio;
  if (c.tidal_volume_ml) params.tidal_volume_ml = *c.tidal_volume_ml;
  if (c.mode) params.mode = *c.mode;
  if (c.ventilator_tau_s) params.ventilator_tau_s = *c.ventilator_tau_s;
  if (c.peep_cmh2o) params.peep_cmh2o = *c.peep_cmh2o;
}

}  // namespace

Result<ClassScenario> ClassScenario::create(const config::Scenario& scenario, const sim::BreathingScript& script) {
  ClassScenario c;
  c.name_ = scenario.name.empty() ? scenario.source : scenario.name;
  c.file_ = scenario.source;
  c.description_ = scenario.description;
  c.duration_s_ = scenario.duration_s;
  c.start_ = script.start;
  c.breath_ = script.events;
  c.turns_ = script.orientation;
  c.lungs_ = timeline_of(scenario.pathologies, &scenario);
  if (Status s = sim::check_timeline(c.lungs_); !s) return fail(scenario.source + ": " + s.error());
  for (const config::ScenarioEvent& e : scenario.events)
    c.cues_.push_back({e.at_s, config::to_string(e.kind), cue_text(e)});
  return c;
}

ScenarioState ClassScenario::state_before(double t_s) const {
  ScenarioState state;
  state.params = start_;
  for (const sim::Event& e : breath_)
    if (e.t_s < t_s && e.kind == sim::EventKind::Change) apply(e.change, state.params);
  std::size_t begun = 0;
  while (begun < lungs_.events.size() && lungs_.events[begun].at_s < t_s) ++begun;
  state.pathologies = sim::present_after(lungs_, begun);
  state.orientation = turns_.at(t_s);
  return state;
}

ClassSteps ClassScenario::steps_from(double t_s, double offset_s) const {
  ClassSteps steps;
  bool holding = false, apnoea = false;  // at t_s, from the steps before it
  for (const sim::Event& e : breath_) {
    if (e.t_s < t_s) {
      if (e.kind == sim::EventKind::HoldStart || e.kind == sim::EventKind::HoldEnd)
        holding = e.kind == sim::EventKind::HoldStart;
      if (e.kind == sim::EventKind::ApnoeaStart || e.kind == sim::EventKind::ApnoeaEnd)
        apnoea = e.kind == sim::EventKind::ApnoeaStart;
      continue;
    }
    if (e.kind == sim::EventKind::HoldEnd && holding) {
      holding = false;
      continue;
    }
    if (e.kind == sim::EventKind::ApnoeaEnd && apnoea) {
      apnoea = false;
      continue;
    }
    sim::Event shifted = e;
    shifted.t_s += offset_s;
    steps.breath.push_back(shifted);
  }
  for (const sim::PathologyEvent& e : lungs_.events) {
    if (e.at_s < t_s) continue;
    sim::PathologyEvent shifted = e;
    shifted.at_s += offset_s;
    steps.lungs.push_back(shifted);
  }
  for (const sim::Turn& turn : turns_.turns()) {
    if (turn.t_s < t_s) continue;
    sim::Turn shifted = turn;
    shifted.t_s += offset_s;
    steps.turns.push_back(shifted);
  }
  return steps;
}

}  // namespace lungar::platform::sync
