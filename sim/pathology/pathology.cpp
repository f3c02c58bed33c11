/// @file pathology.cpp
/// @brief The registry of pathology plug-ins (pathology_list.h) and what is done with any spec: parse it by its
///        first field, refuse a repeat, apply a list all or nothing.
#include "sim/pathology/pathology.h"

#include <algorithm>
#include <array>

#include "sim/pathology/lung_changes.h"

namespace lungar::sim {

namespace pathology {
#define LUNGAR_PATHOLOGY(name) const PathologyModel& name##_pathology();
#include "sim/pathology/pathology_list.h"
#undef LUNGAR_PATHOLOGY
}  // namespace pathology

std::span<const PathologyModel* const> pathology_models() {
  static const std::array models = {
#define LUNGAR_PATHOLOGY(name) &pathology::name##_pathology(),
#include "sim/pathology/pathology_list.h"
#undef LUNGAR_PATHOLOGY
  };
  return models;
}

std::string pathology_syntaxes() {
  std::string forms;
  std::vector<std::string_view> fields;  // each field once: SIDE is several models'
  const auto models = pathology_models();
  for (std::size_t k = 0; k < models.size(); ++k) {
    forms += (k == 0 ? "" : k + 1 == models.size() ? " or " : ", ") + std::string(models[k]->syntax());
    for (std::string_view f : pathology::split_fields(models[k]->fields()))
      if (std::find(fields.begin(), fields.end(), f) == fields.end()) fields.push_back(f);
  }
  std::string list;
  for (std::string_view f : fields) list += (list.empty() ? "" : ", ") + std::string(f);
  return list.empty() ? forms : forms + " (" + list + ")";
}

std::string pathology_table() {
  std::string t = "| pathology | spec | fields | what it models | may change in a run |\n|---|---|---|---|---|\n";
  for (const PathologyModel* m : pathology_models())
    t += "| " + std::string(m->name()) + " | `" + std::string(m->syntax()) + "` | " + std::string(m->fields()) + " | " +
         std::string(m->summary()) + " | " + (m->may_change_in_a_run() ? "yes" : "no: from the start") + " |\n";
  return t;
}

Result<std::shared_ptr<const Pathology>> parse_pathology(std::string_view spec) {
  const std::vector<std::string_view> fields = pathology::split_spec(spec);
  for (const PathologyModel* m : pathology_models()) {
    if (m->name() != fields[0]) continue;
    Result<std::unique_ptr<Pathology>> p = m->parse(spec, fields);
    if (!p) return p.with_context("");
    return std::shared_ptr<const Pathology>(p.take());
  }
  return pathology::bad(spec, "expected " + pathology_syntaxes());
}

namespace {

/// Every spec parsed, none overlapping one before it of the same model; the error names the spec (and the one it
/// repeats) and what was expected.
Result<std::vector<std::shared_ptr<const Pathology>>> parse_distinct(const std::vector<std::string>& specs) {
  std::vector<std::shared_ptr<const Pathology>> seen;
  for (const std::string& spec : specs) {
    Result<std::shared_ptr<const Pathology>> p = parse_pathology(spec);
    if (!p) return p.with_context("");
    for (const auto& before : seen)
      if (&before->model() == &(*p)->model() && before->overlaps(**p))
        return pathology::bad(spec, "repeats '" + before->spec() + "': expected " + std::string((*p)->model().once()));
    seen.push_back(p.take());
  }
  return seen;
}

}  // namespace

Status check_pathologies(const std::vector<std::string>& specs) {
  if (auto parsed = parse_distinct(specs); !parsed) return parsed.with_context("");
  return {};
}

Status apply_pathologies(BakedAsset& asset, PatientState& patient, const std::vector<std::string>& specs) {
  if (specs.empty()) return {};
  if (patient.lungs.size() != asset.lungs.size())
    return fail("pathologies: expected a patient state of the asset's " + std::to_string(asset.lungs.size()) +
                " lungs, got " + std::to_string(patient.lungs.size()));
  Result<std::vector<std::shared_ptr<const Pathology>>> parsed = parse_distinct(specs);
  if (!parsed) return parsed.with_context("");
  std::stable_partition(parsed->begin(), parsed->end(), [](const auto& p) { return !p->model().applied_last(); });
  BakedAsset changed = asset;
  PatientState now = patient;
  for (const auto& p : *parsed) {
    if (Status s = p->apply(changed, now); !s) return s;
    for (std::size_t l = 0; l < changed.lungs.size(); ++l) now.lungs[l].take_shape_of(changed.lungs[l]);
  }
  asset = std::move(changed);
  patient = std::move(now);
  return {};
}

BreathingHint breathing_of(const std::vector<std::string>& specs) {
  for (const std::string& spec : specs) {
    Result<std::shared_ptr<const Pathology>> p = parse_pathology(spec);
    if (p && !(*p)->model().breathing_preset().empty()) return {spec, std::string((*p)->model().breathing_preset())};
  }
  return {};
}

}  // namespace lungar::sim
