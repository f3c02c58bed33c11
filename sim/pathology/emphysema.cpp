/// @file emphysema.cpp
/// @brief `emphysema:SEVERITY[:SIDE]` (SEVERITY 0 to 1; both lungs unless SIDE): destroyed alveolar walls trap air,
///        so the lung rests larger.
///
/// It grows about its hilum, keeping its shape, to 1 + kFrcGain x SEVERITY of its volume (severe COPD's functional
/// residual capacity is 130-150 % of predicted). Its poor recoil, a slower and longer expiration, is the
/// breathing's: the runtime breathes with the `emphysema` preset (compliance 140 mL/cmH2O, resistance
/// 10.5 cmH2O.s/L, tau 1.5 s against the normal 0.36 s) when the breathing is at its default.
#include "sim/pathology/lung_changes.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim::pathology {
namespace {

/// At severity 1 the lung rests this much larger (a share of the healthy volume).
constexpr double kFrcGain = 0.4;

class Emphysema final : public Pathology {
 public:
  Emphysema(const PathologyModel& m, std::string_view spec, std::string side, double severity)
      : Pathology(m, spec, std::move(side)), severity_(severity) {}

  Status apply(BakedAsset& a, PatientState& patient) const override {
    if (!side().empty()) {
      Result<std::size_t> l = lung_of(a, side(), spec());
      if (!l) return l.with_context("");
      scale_about_hilum(a, patient, *l, 1.0 + kFrcGain * severity_);
      return {};
    }
    for (std::size_t l = 0; l < a.lungs.size(); ++l) scale_about_hilum(a, patient, l, 1.0 + kFrcGain * severity_);
    return {};
  }

 private:
  double severity_;
};

class EmphysemaModel final : public PathologyModel {
 public:
  EmphysemaModel()
      : PathologyModel({.name = "emphysema",
                        .syntax = "emphysema:SEVERITY[:SIDE]",
                        .fields = "SIDE left or right; SEVERITY 0 to 1",
                        .summary = "trapped air: the lung (both without SIDE) rests up to 40 % larger about its "
                                   "hilum, and breathes with the `emphysema` preset (tau 1.5 s) when the breathing "
                                   "is at its default",
                        .once = "one emphysema a lung (emphysema:SEVERITY without SIDE is both lungs')"}) {}
  std::string_view breathing_preset() const override { return "emphysema"; }
  Result<std::unique_ptr<Pathology>> parse(std::string_view spec, std::span<const std::string_view> f) const override {
    if (f.size() != 2 && f.size() != 3) return bad(spec, "expected emphysema:SEVERITY or emphysema:SEVERITY:SIDE");
    Result<double> severity = parse_number(spec, f[1], 0.0, 1.0, "SEVERITY: expected a number from 0 to 1");
    if (!severity) return severity.with_context("");
    std::string side;
    if (f.size() == 3) {
      Result<std::string> s = parse_side(spec, f[2]);
      if (!s) return s.with_context("");
      side = s.take();
    }
    return std::unique_ptr<Pathology>(std::make_unique<Emphysema>(*this, spec, std::move(side), *severity));
  }
};

}  // namespace

const PathologyModel& emphysema_pathology() {
  static const EmphysemaModel model;
  return model;
}

}  // namespace lungar::sim::pathology
