/// @file scenario.h
/// @brief A breathing scenario as read from TOML: the state at t = 0 and timed events (breathing changes,
///        sighs, holds, apnoeas, ventilator, patient turns). Plain data; platform/scenario_adapter runs it.
///
/// The file format is documented in config/scenarios/teaching.toml.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "config/breathing_settings.h"

namespace lungar::config {

enum class ScenarioEventKind {
  Turn,         ///< the patient turns to a pose or rotation over over_s
  Change,       ///< new preset, rate, I:E or tidal volume
  Sigh,         ///< the next breath is deeper
  Hold,         ///< breath hold for duration_s
  Apnoea,       ///< no breathing for duration_s
  Ventilator,   ///< square pressure wave (pressure-controlled ventilation)
  Spontaneous,  ///< back to spontaneous breathing
  Pathology,    ///< a pathology comes (add) or goes (remove: a needle decompression) over over_s
};
inline constexpr EnumNames<ScenarioEventKind, 8> kScenarioEventKindNames{{{{ScenarioEventKind::Turn, "turn"},
                                                                          {ScenarioEventKind::Change, "change"},
                                                                          {ScenarioEventKind::Sigh, "sigh"},
                                                                          {ScenarioEventKind::Hold, "hold"},
                                                                          {ScenarioEventKind::Apnoea, "apnoea"},
                                                                          {ScenarioEventKind::Ventilator, "ventilator"},
                                                                          {ScenarioEventKind::Spontaneous, "spontaneous"},
                                                                          {ScenarioEventKind::Pathology, "pathology"}}}};
inline const char* to_string(ScenarioEventKind kind) { return kScenarioEventKindNames.name(kind); }

struct ScenarioEvent {
  ScenarioEventKind kind = ScenarioEventKind::Change;
  double at_s = 0;
  double over_s = -1;      ///< turn: its duration; others: the shortest transition (-1: automatic)
  double duration_s = 0;   ///< hold, apnoea
  // Breathing parameters (change, ventilator, spontaneous); empty: unchanged.
  std::optional<std::string> preset;
  std::optional<double> rate_bpm;
  std::optional<double> ie_ratio;
  std::optional<double> tidal_volume_ml;
  std::optional<double> peep_cmh2o;  ///< ventilator
  std::optional<double> tau_s;       ///< ventilator
  std::optional<double> volume_ml;   ///< sigh
  // Turn target: a pose name, or (pose empty) a unit quaternion w, x, y, z of the lung frame in the world.
  std::string pose;
  std::array<double, 4> rotation_wxyz = {1.0, 0.0, 0.0, 0.0};
  // Pathology: the spec that comes or goes (sim/pathology/pathology.h, checked where the asset is loaded).
  std::string pathology_add, pathology_remove;
  // Where it came from, for messages: "FILE:LINE: key 'event[2]...'".
  int index = 0;
  int line = 0;
};

struct Scenario {
  std::string source;       ///< the file
  std::string name;
  std::string description;
  double duration_s = 60.0;
  /// The patient's pathologies for the whole scenario (sim/pathology/pathology.h specs, checked where the asset is
  /// loaded), added to the settings' [sim] pathology: "a patient with ARDS, turned prone".
  std::vector<std::string> pathologies;
  BreathingSettings start;  ///< preset, rate, I:E and tidal volume at t = 0
  std::string start_pose = kPoseNames.name(Pose::Upright);
  std::array<double, 4> start_rotation_wxyz = {1.0, 0.0, 0.0, 0.0};  ///< used when start_pose is empty
  std::vector<ScenarioEvent> events;  ///< in time order (stable: file order among equal times)

  /// "FILE:LINE: key 'event[i].key'", the prefix of a message about one event.
  std::string where(const ScenarioEvent& e, const std::string& key) const;
};

}  // namespace lungar::config
