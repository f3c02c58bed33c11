/// @file ards.cpp
/// @brief `ards:SEVERITY` (0 to 1): the acute respiratory distress syndrome's heavy, wet lung collapses where it
///        lies lowest, and which part that is follows the posture.
///
/// Supine the dorsal lung stops ventilating and the breath moves ventral, prone the dorsal lung recruits. Not a
/// change of the asset's response but of the applied force, evaluated per posture (sim/force/dependent_collapse.h):
/// a pattern that is not linear in position, carried by the SH. Applied after the others, whatever the order given
/// (its pattern is fitted to the response and geometry they leave), and only from the start of a run: the fit is
/// made at load. It costs a projection of its pattern per change of posture (docs/design.md, "Pathologies").
#include <algorithm>

#include "sim/force/dependent_collapse.h"
#include "sim/pathology/lung_changes.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim::pathology {
namespace {

class Ards final : public Pathology {
 public:
  Ards(const PathologyModel& m, std::string_view spec, double severity) : Pathology(m, spec, ""), severity_(severity) {}

  /// Every lung takes the collapsed pattern's force, its healthy volumes kept for its weight in the split.
  Status apply(BakedAsset& a, PatientState& patient) const override {
    if (std::any_of(patient.lungs.begin(), patient.lungs.end(),
                    [](const LungState& l) { return l.collapse != nullptr; }))
      return bad(spec(), "ARDS is given twice; give one severity");
    Result<std::shared_ptr<const DependentCollapse>> pattern = DependentCollapse::build(a, severity_);
    if (!pattern) return bad(spec(), pattern.error());
    for (std::size_t l = 0; l < a.lungs.size(); ++l) {
      LungState& lung = patient.lungs[l];
      keep_healthy_volumes(a.lungs[l], lung);
      lung.collapse = *pattern;
      lung.collapse_index = l;
    }
    return {};
  }

 private:
  double severity_;
};

class ArdsModel final : public PathologyModel {
 public:
  ArdsModel()
      : PathologyModel(
            {.name = "ards",
             .syntax = "ards:SEVERITY",
             .fields = "SEVERITY 0 to 1",
             .summary =
                 "the heavy, wet lung collapses where it lies lowest, following the posture: supine the breath moves "
                 "ventral, prone the dorsal lung recruits",
             .once = "one ARDS (it is given twice: give its severity once)"}) {}
  bool may_change_in_a_run() const override { return false; }
  bool applied_last() const override { return true; }
  Result<std::unique_ptr<Pathology>> parse(std::string_view spec, std::span<const std::string_view> f) const override {
    if (f.size() != 2) return bad(spec, "expected ards:SEVERITY");
    Result<double> severity = parse_number(spec, f[1], 0.0, 1.0, "SEVERITY: expected a number from 0 to 1");
    if (!severity) return severity.with_context("");
    return std::unique_ptr<Pathology>(std::make_unique<Ards>(*this, spec, *severity));
  }
};

}  // namespace

const PathologyModel& ards_pathology() {
  static const ArdsModel model;
  return model;
}

}  // namespace lungar::sim::pathology
