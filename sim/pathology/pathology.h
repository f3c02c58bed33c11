/// @file pathology.h
/// @brief The diseases a trainer switches on, as plug-ins: each kind is a PathologyModel in a file of its own under
///        sim/pathology/ (pneumothorax.cpp, consolidation.cpp, emphysema.cpp, ards.cpp, ...), listed once in
///        pathology_list.h. A spec ("pneumothorax:right:30") parses into a Pathology that changes a baked asset
///        when it is loaded: the runtime, `lungar-bake export` and the CPU paths all draw the changed asset, so they
///        agree. The help texts, the settings' check and the docs' table come from the same list.
///
/// Adding one: a file sim/pathology/NAME.cpp defining `const PathologyModel& pathology::NAME_pathology()` (its spec's
/// parser, its change of the asset, what it says of itself), and the line `LUNGAR_PATHOLOGY(NAME)` in pathology_list.h.
/// The shared lung operations (scaling about the hilum, resumming the swept volumes, spec fields) are in
/// lung_changes.h. docs/design.md ("Pathologies") has the models' physiology; docs/pathologies.md the table.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

class PathologyModel;

/// One pathology as the trainer gave it: a parsed spec, ready to change an asset.
class Pathology {
 public:
  Pathology(const PathologyModel& model, std::string_view spec, std::string side)
      : model_(&model), spec_(spec), side_(std::move(side)) {}
  virtual ~Pathology() = default;

  const PathologyModel& model() const { return *model_; }
  /// As the user wrote it.
  const std::string& spec() const { return spec_; }
  /// The lung's name in the asset ("left", "right"), or "" for every lung.
  const std::string& side() const { return side_; }

  /// Whether `other`, of the same model, changes what this one changes, so that applying both would compound it
  /// (two pneumothoraces of one lung collapse it twice). By default: the same lung, or either of them every lung's.
  virtual bool overlaps(const Pathology& other) const {
    return side_.empty() || other.side_.empty() || side_ == other.side_;
  }
  /// Changes the patient at load: `asset`, its shape and per-vertex response (the asset is not written after
  /// load), and `patient`, what the patient is now (a lung's weight in the split, the force it takes per posture).
  /// On an error the caller drops both (apply_pathologies works on copies).
  virtual Status apply(BakedAsset& asset, PatientState& patient) const = 0;

 private:
  const PathologyModel* model_;
  std::string spec_;
  std::string side_;
};

/// What a kind of pathology says of itself: its name and spec for the help texts and errors, a line for the docs.
struct PathologyText {
  std::string_view name;     ///< the spec's first field, e.g. "pneumothorax"
  std::string_view syntax;   ///< the spec's form, e.g. "pneumothorax:SIDE:PERCENT[:tension]"
  std::string_view fields;   ///< what its fields take, "; " between them: "SIDE left or right; PERCENT 1 to 90"
  std::string_view summary;  ///< one line for the docs' table: what it models
  std::string_view once;     ///< what is expected instead of a second one that overlaps (check_pathologies' error)
};

/// One kind of pathology: what it is called, how its spec reads, and what it does.
class PathologyModel {
 public:
  explicit PathologyModel(const PathologyText& text) : text_(text) {}
  virtual ~PathologyModel() = default;
  std::string_view name() const { return text_.name; }
  std::string_view syntax() const { return text_.syntax; }
  std::string_view fields() const { return text_.fields; }
  std::string_view summary() const { return text_.summary; }
  std::string_view once() const { return text_.once; }
  /// Parses `spec`, whose `fields[0]` is name(); the error is one line naming the spec and the field.
  virtual Result<std::unique_ptr<Pathology>> parse(std::string_view spec,
                                                   std::span<const std::string_view> fields) const = 0;
  /// Whether it may come or go while a run goes on (false: only from the start).
  virtual bool may_change_in_a_run() const { return true; }
  /// Whether it is applied after every other, whatever the order given (its fit depends on what they leave).
  virtual bool applied_last() const { return false; }
  /// The breathing preset the patient breathes with when the breathing is at its default ("" for none).
  virtual std::string_view breathing_preset() const { return ""; }

 private:
  PathologyText text_;
};

/// Every pathology lungar knows, in pathology_list.h's order.
std::span<const PathologyModel* const> pathology_models();

/// "pneumothorax:SIDE:PERCENT[:tension], consolidation:SIDE:REGION, ... (SIDE left or right, ...)": the help
/// texts' list, from the models.
std::string pathology_syntaxes();

/// The docs' table (markdown, a row a model): docs/pathologies.md holds it, and a test keeps the two the same.
std::string pathology_table();

/// "pneumothorax:right:30", "consolidation:left:upper", "emphysema:0.5", "ards:0.6" -> a Pathology, or one line
/// saying what was expected.
Result<std::shared_ptr<const Pathology>> parse_pathology(std::string_view spec);

/// Every spec parses and none overlaps one before it of the same model; the error names both specs and what was
/// expected.
Status check_pathologies(const std::vector<std::string>& specs);

/// Parses and applies each spec in order (those applied_last() last) to `asset` and `patient` (one state per lung
/// of the asset; the lungs' shape figures in it follow the asset's after each); the error names the spec (a
/// repeated one, check_pathologies, too). All or nothing: on an error both are unchanged.
Status apply_pathologies(BakedAsset& asset, PatientState& patient, const std::vector<std::string>& specs);

/// The breathing a pathology asks for: the first of `specs` whose model has a preset (an emphysema: "emphysema"),
/// and that spec; both "" when none has.
struct BreathingHint {
  std::string spec, preset;
};
BreathingHint breathing_of(const std::vector<std::string>& specs);

}  // namespace lungar::sim
