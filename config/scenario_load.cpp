/// @file scenario_load.cpp
/// @brief The schema of scenario TOML files: [start], then [[event]] tables whose keys depend on their kind.
#include "config/scenario_load.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "config/base/number_text.h"
#include "config/base/patient_names.h"
#include "config/toml_section.h"

namespace lungar::config {

namespace {

constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
constexpr double kMaxScenarioS = 86400.0;  // a day

std::optional<double> optional_number(TomlSection& s, std::string_view key, double lo, double hi,
                                      std::string_view unit) {
  double v = kUnset;
  s.number(key, v, lo, hi, unit);
  if (std::isnan(v)) return std::nullopt;
  return v;
}

/// A rotation_wxyz key, checked for unit norm; false when absent.
bool read_rotation(TomlSection& s, std::array<double, 4>& out) {
  std::array<double, 4> q = {kUnset, kUnset, kUnset, kUnset};
  s.numbers("rotation_wxyz", q, -1.0, 1.0, "");
  if (std::isnan(q[0])) return false;
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::abs(norm - 1.0) > 1e-3) {
    s.fail("rotation_wxyz",
           "expected a unit quaternion [w, x, y, z] (norm 1 within 1e-3), got norm " + number_text(norm));
  }
  out = q;
  return true;
}

void read_breathing_keys(TomlSection& s, ScenarioEvent& e) {
  std::string preset;
  s.choice("preset", preset, kPresetNames);
  if (!preset.empty()) e.preset = preset;
  e.rate_bpm = optional_number(s, "rate_bpm", 2.0, 60.0, "breaths/min");
  e.ie_ratio = optional_number(s, "ie_ratio", 0.1, 4.0, "(inspiration:expiration)");
  e.tidal_volume_ml = optional_number(s, "tidal_volume_ml", 50.0, 3000.0, "mL");
}

void read_start(TomlSection s, Scenario& sc) {
  s.choice("preset", sc.start.preset, kPresetNames);
  s.number("rate_bpm", sc.start.rate_bpm, 2.0, 60.0, "breaths/min");
  s.number("ie_ratio", sc.start.ie_ratio, 0.1, 4.0, "(inspiration:expiration)");
  s.number("tidal_volume_ml", sc.start.tidal_volume_ml, 50.0, 3000.0, "mL");
  std::string pose;
  s.choice("pose", pose, kPoseNames);
  if (read_rotation(s, sc.start_rotation_wxyz)) {
    if (!pose.empty()) s.fail("rotation_wxyz", "expected either pose or rotation_wxyz, got both");
    sc.start_pose.clear();
  } else if (!pose.empty()) {
    sc.start_pose = pose;
  }
  s.finish();
}

ScenarioEvent read_event(TomlSection s, const toml::table& t, int index) {
  ScenarioEvent e;
  e.index = index;
  e.line = static_cast<int>(t.source().begin.line);
  if (!t.contains("kind")) {
    s.fail("kind", "expected one of \"turn\" | \"change\" | \"sigh\" | \"hold\" | \"apnoea\" | \"ventilator\" | "
                   "\"spontaneous\" | \"pathology\", got nothing");
  }
  s.choice("kind", e.kind, kScenarioEventKindNames);
  double at = kUnset;
  s.number("at_s", at, 0.0, kMaxScenarioS, "s");
  if (std::isnan(at)) s.fail("at_s", "expected the event's time, a number in [0, 86400] s, got nothing");
  e.at_s = at;
  if (const toml::node* n = t.get("at_s")) e.line = static_cast<int>(n->source().begin.line);

  auto required = [&](std::string_view key, double lo, double hi, std::string_view unit, const char* what) {
    const std::optional<double> v = optional_number(s, key, lo, hi, unit);
    if (!v) {
      s.fail(key, std::string("expected ") + what + ", a number in [" + number_text(lo) + ", " + number_text(hi) +
                      "] " + std::string(unit) + ", got nothing");
    }
    return *v;
  };
  auto transition = [&]() { e.over_s = optional_number(s, "over_s", 0.0, 600.0, "s").value_or(-1.0); };

  switch (e.kind) {
    case ScenarioEventKind::Turn: {
      s.choice("to", e.pose, kPoseNames);
      const bool rotation = read_rotation(s, e.rotation_wxyz);
      if (rotation && !e.pose.empty()) s.fail("rotation_wxyz", "expected either to or rotation_wxyz, got both");
      if (!rotation && e.pose.empty()) {
        s.fail("to", "expected the pose to turn to (" + kPoseNames.expected() + ") or rotation_wxyz, got nothing");
      }
      e.over_s = required("over_s", 0.01, 600.0, "s", "the duration of the turn");
      break;
    }
    case ScenarioEventKind::Change:
      read_breathing_keys(s, e);
      transition();
      if (!e.preset && !e.rate_bpm && !e.ie_ratio && !e.tidal_volume_ml) {
        s.fail("kind", "expected at least one of preset, rate_bpm, ie_ratio, tidal_volume_ml with kind = "
                       "\"change\", got none");
      }
      break;
    case ScenarioEventKind::Sigh:
      e.volume_ml = optional_number(s, "volume_ml", 50.0, 3000.0, "mL");
      break;
    case ScenarioEventKind::Hold:
    case ScenarioEventKind::Apnoea:
      e.duration_s = required("duration_s", 0.1, 3600.0, "s", "how long it lasts");
      break;
    case ScenarioEventKind::Ventilator:
      read_breathing_keys(s, e);
      e.peep_cmh2o = optional_number(s, "peep_cmh2o", 0.0, 20.0, "cmH2O");
      e.tau_s = optional_number(s, "tau_s", 0.05, 5.0, "s");
      transition();
      break;
    case ScenarioEventKind::Spontaneous:
      read_breathing_keys(s, e);
      transition();
      break;
    case ScenarioEventKind::Pathology:
      s.text("add", e.pathology_add);
      s.text("remove", e.pathology_remove);
      if (e.pathology_add.empty() == e.pathology_remove.empty())
        s.fail("add", "expected one of add = SPEC (the pathology comes) or remove = SPEC (it goes: a needle "
                      "decompression), got " + std::string(e.pathology_add.empty() ? "neither" : "both"));
      e.over_s = required("over_s", 0.0, 600.0, "s", "how long the change takes");
      break;
  }
  s.finish();
  return e;
}

[[noreturn]] void fail_event(const Scenario& sc, const ScenarioEvent& e, const std::string& key,
                             const std::string& message) {
  throw ConfigError(sc.where(e, key) + ": " + message);
}

/// Time-line checks that need every event: within the duration, no overlapping turns, no overlapping holds or
/// apnoeas, no sigh while on the ventilator.
void check_timeline(const Scenario& sc) {
  const ScenarioEvent* last_turn = nullptr;
  const ScenarioEvent* last_pause = nullptr;  // hold or apnoea
  bool ventilated = false;
  for (const ScenarioEvent& e : sc.events) {
    if (e.at_s > sc.duration_s) {
      fail_event(sc, e, "at_s",
                 "expected a time within the scenario's duration_s (" + number_text(sc.duration_s) + " s), got " +
                     number_text(e.at_s) + " s");
    }
    if (e.kind == ScenarioEventKind::Turn) {
      if (last_turn && last_turn->at_s + last_turn->over_s > e.at_s) {
        fail_event(sc, e, "at_s",
                   "expected turns that do not overlap, got a turn at " + number_text(e.at_s) +
                       " s while the turn of event[" + std::to_string(last_turn->index) + "] (line " +
                       std::to_string(last_turn->line) + ") runs from " + number_text(last_turn->at_s) + " s to " +
                       number_text(last_turn->at_s + last_turn->over_s) + " s");
      }
      last_turn = &e;
    }
    if (e.kind == ScenarioEventKind::Hold || e.kind == ScenarioEventKind::Apnoea) {
      if (last_pause && last_pause->at_s + last_pause->duration_s > e.at_s) {
        fail_event(sc, e, "at_s",
                   std::string("expected holds and apnoeas that do not overlap, got a ") + to_string(e.kind) + " at " +
                       number_text(e.at_s) + " s while the " + to_string(last_pause->kind) + " of event[" +
                       std::to_string(last_pause->index) + "] (line " + std::to_string(last_pause->line) +
                       ") lasts from " + number_text(last_pause->at_s) + " s to " +
                       number_text(last_pause->at_s + last_pause->duration_s) + " s");
      }
      last_pause = &e;
    }
    if (e.kind == ScenarioEventKind::Ventilator) ventilated = true;
    if (e.kind == ScenarioEventKind::Spontaneous) ventilated = false;
    if (e.kind == ScenarioEventKind::Sigh && ventilated) {
      fail_event(sc, e, "kind", "expected a sigh during spontaneous breathing, got one while on the ventilator");
    }
  }
}

Result<Scenario> parse(const std::string& text, const std::string& name, const BreathingSettings& defaults) {
  auto parsed = parse_toml(text, name);
  if (!parsed) return parsed.with_context("");
  const toml::table& root = *parsed;
  Scenario sc;
  sc.source = name;
  sc.start = defaults;
  sc.start.scenario.clear();
  try {
    TomlSection top(&root, "", name);
    top.text("name", sc.name);
    top.text("description", sc.description);
    top.number("duration_s", sc.duration_s, 0.1, kMaxScenarioS, "s");
    top.texts("pathology", sc.pathologies);
    read_start(top.section("start"), sc);
    {
      // [[event]] is an array of tables, which TomlSection does not read; unknown top-level keys are looked for
      // in a copy without it.
      toml::table rest = root;
      rest.erase("event");
      TomlSection others(&rest, "", name);
      std::string ignored_text;
      double ignored_number = 0;
      std::vector<std::string> ignored_texts;
      others.text("name", ignored_text);
      others.texts("pathology", ignored_texts);
      others.text("description", ignored_text);
      others.number("duration_s", ignored_number, 0.1, kMaxScenarioS, "s");
      (void)others.section("start");
      others.finish();
    }
    if (const toml::node* events = root.get("event")) {
      const toml::array* list = events->as_array();
      if (!list || !list->is_array_of_tables()) {
        const TomlSection whole(&root, "", name);
        whole.fail("event", "expected [[event]] tables, got " + describe(*events));
      }
      for (std::size_t k = 0; k < list->size(); ++k) {
        const toml::table& t = *list->get(k)->as_table();
        sc.events.push_back(read_event(TomlSection(&t, "event[" + std::to_string(k) + "]", name), t,
                                       static_cast<int>(k)));
      }
    }
    if (sc.events.empty() && sc.pathologies.empty() && root.get("start") == nullptr) {
      // Nothing to run: the log would still say the scenario breathes and turns the patient.
      throw ConfigError(name +
                        ": expected a scenario: at least one [[event]], a [start] table or a pathology list, got "
                        "none (config/scenarios/teaching.toml shows each)");
    }
    std::stable_sort(sc.events.begin(), sc.events.end(),
                     [](const ScenarioEvent& a, const ScenarioEvent& b) { return a.at_s < b.at_s; });
    check_timeline(sc);
  } catch (const ConfigError& e) {
    return fail(e.what());
  }
  return sc;
}

}  // namespace


std::string Scenario::where(const ScenarioEvent& e, const std::string& key) const {
  std::string w = source;
  if (e.line > 0) w += ":" + std::to_string(e.line);
  return w + ": key 'event[" + std::to_string(e.index) + "]" + (key.empty() ? "" : "." + key) + "'";
}

Result<Scenario> load_scenario_from_string(const std::string& toml_text, const std::string& name,
                                         const BreathingSettings& defaults) {
  return parse(toml_text, name, defaults);
}

Result<Scenario> load_scenario(const std::string& path, const BreathingSettings& defaults) {
  auto text = read_toml_file(path, "scenario");
  if (!text) return text.with_context("");
  return parse(*text, path, defaults);
}

}  // namespace lungar::config
