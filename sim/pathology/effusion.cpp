/// @file effusion.cpp
/// @brief `effusion:SIDE:ML`: a pleural effusion, ML of fluid in the pleural space of SIDE, compressing the lung from
///        below.
///
/// Fluid is heavier than lung and collects in the dependent part of the pleural space; on the erect chest film,
/// where effusions are judged, that is the base (the costophrenic angle blunts from about 200 mL, a fifth of the
/// hemithorax is about 1 L). The lung gives way to the fluid's volume where it lies: its base rises while its apex,
/// held by the pleura, stays; so the lung is pressed along its height about its apex to (V - ML) / V of its volume
/// (compressive atelectasis of the base). The compressed part stops ventilating: the lung's weight in the split of
/// each breath falls in proportion to what it lost, and the other lung takes the rest. A pressed lung is an affine
/// map of its loaded one, so an effusion can come and go during a run (drained by a thoracentesis). The asset's
/// posture is the erect one; the fluid's shift when the patient lies down is not modelled.
#include "sim/pathology/lung_changes.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim::pathology {
namespace {

/// Fluid volumes accepted, mL: from a small effusion to a massive one.
constexpr double kMinEffusionMl = 10.0, kMaxEffusionMl = 5000.0;
/// At most this share of the lung's volume can be pressed out: what is left must still be a lung.
constexpr double kMaxEffusionShare = 0.8;

class Effusion final : public Pathology {
 public:
  Effusion(const PathologyModel& m, std::string_view spec, std::string side, double ml)
      : Pathology(m, spec, std::move(side)), ml_(ml) {}

  Status apply(BakedAsset& a, PatientState& patient) const override {
    Result<std::size_t> l = lung_of(a, side(), spec());
    if (!l) return l.with_context("");
    BakedLung& lung = a.lungs[*l];
    const double share = ml_ / lung.rest_volume_ml;
    if (!(share <= kMaxEffusionShare))
      return bad(spec(), "ML: expected at most 80 % of the " + side() + " lung's " +
                             std::to_string(static_cast<long>(lung.rest_volume_ml)) + " mL");
    const double apex = extent(a, lung, 2).second;
    scale_along_axis(a, *l, 2, apex, 1.0 - share);
    patient.lungs[*l].breath_weight *= 1.0 - share;
    return {};
  }

 private:
  double ml_;
};

class EffusionModel final : public PathologyModel {
 public:
  EffusionModel()
      : PathologyModel({.name = "effusion",
                        .syntax = "effusion:SIDE:ML",
                        .fields = "SIDE left or right; ML 10 to 5000",
                        .summary = "pleural fluid pressing the lung from below: its base rises until it has lost ML "
                                   "(its apex stays), and it takes that much less of each breath",
                        .once = "one effusion a lung (give its volume once)"}) {}
  Result<std::unique_ptr<Pathology>> parse(std::string_view spec, std::span<const std::string_view> f) const override {
    if (f.size() != 3) return bad(spec, "expected effusion:SIDE:ML (SIDE left or right, ML 10 to 5000)");
    Result<std::string> side = parse_side(spec, f[1]);
    if (!side) return side.with_context("");
    Result<double> ml = parse_number(spec, f[2], kMinEffusionMl, kMaxEffusionMl,
                                     "ML: expected a number from 10 to 5000 (the fluid's volume, mL)");
    if (!ml) return ml.with_context("");
    return std::unique_ptr<Pathology>(std::make_unique<Effusion>(*this, spec, side.take(), *ml));
  }
};

}  // namespace

const PathologyModel& effusion_pathology() {
  static const EffusionModel model;
  return model;
}

}  // namespace lungar::sim::pathology
