/// @file consolidation.cpp
/// @brief `consolidation:SIDE:REGION` (upper, middle or lower third of the lung's height): the region fills with
///        fluid or cells, stops ventilating and stiffens.
///
/// Its surface moves kConsolidatedResponse of its healthy motion (each vertex's transfer row, T^I_lm, its linear
/// basis and its off-axis part scaled), with a ramp of kRamp of the height outside the region so that the surface
/// does not tear. The lung's weight in the split falls by the share of its swept volume it lost in the posture
/// (V(g) / V_healthy(g)): the tidal volume stays what the breathing delivers, so the part of it the region no
/// longer takes spreads over everything that still ventilates, in both lungs, in proportion.
#include <algorithm>

#include "config/base/enum_names.h"
#include "sim/pathology/lung_changes.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim::pathology {
namespace {

/// How much of its healthy motion a consolidated region's surface keeps.
constexpr double kConsolidatedResponse = 0.1;
/// The ramp from consolidated to healthy outside the region, as a fraction of the lung's height.
constexpr double kRamp = 0.05;

enum class Third { Lower, Middle, Upper };
constexpr EnumNames<Third, 3> kThirdNames{
    {{{Third::Upper, "upper"}, {Third::Middle, "middle"}, {Third::Lower, "lower"}}}};

/// 1 - how much of the region's weight a vertex at height z carries: 1 inside the third, 0 beyond the ramp.
double region_weight(double z, double lo, double hi, Third third) {
  const double h = hi - lo, ramp = kRamp * h;
  const int index = static_cast<int>(third);
  const double bottom = lo + index * h / 3, top = lo + (index + 1) * h / 3;
  const double outside = std::max({0.0, bottom - z, z - top});  // distance beyond the third, mm
  return ramp > 0 ? std::clamp(1.0 - outside / ramp, 0.0, 1.0) : (outside > 0 ? 0.0 : 1.0);
}

class Consolidation final : public Pathology {
 public:
  Consolidation(const PathologyModel& m, std::string_view spec, std::string side, Third third)
      : Pathology(m, spec, std::move(side)), third_(third) {}

  bool overlaps(const Pathology& other) const override {
    return side() == other.side() && third_ == static_cast<const Consolidation&>(other).third_;
  }

  /// Scales the response of the region's vertices and the lung's swept volumes with it, keeping the healthy ones
  /// for its weight in the split (breath_share.h); an error when its swept volume is not positive.
  Status apply(BakedAsset& a, PatientState& patient) const override {
    Result<std::size_t> l = lung_of(a, side(), spec());
    if (!l) return l.with_context("");
    BakedLung& lung = a.lungs[*l];
    const double before = swept(a, lung, lung.force_const);
    if (!(before > 0)) return bad(spec(), "lung '" + lung.name + "' of the asset sweeps no volume to consolidate");
    const auto [lo, hi] = extent(a, lung, 2);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const double w = region_weight(a.positions[3 * i + 2], lo, hi, third_);
      if (w != 0) scale_response(a, i, static_cast<float>(1.0 - (1.0 - kConsolidatedResponse) * w));
    }
    keep_healthy_volumes(lung, patient.lungs[*l]);
    resum_swept_volumes(a, lung, before);
    return {};
  }

 private:
  Third third_;
};

class ConsolidationModel final : public PathologyModel {
 public:
  ConsolidationModel()
      : PathologyModel(
            {.name = "consolidation",
             .syntax = "consolidation:SIDE:REGION",
             .fields = "SIDE left or right; REGION upper, middle or lower",
             .summary = "a third of the lung's height fills and stiffens: its surface keeps a tenth of its motion (a "
                        "ramp of 5 % of the height outside it), and the breath it no longer takes goes to what still "
                        "ventilates",
             .once = "each third of a lung consolidated once"}) {}
  Result<std::unique_ptr<Pathology>> parse(std::string_view spec, std::span<const std::string_view> f) const override {
    if (f.size() != 3)
      return bad(spec, "expected " + std::string(syntax()) + " (SIDE left or right, REGION upper, middle or lower)");
    Result<std::string> side = parse_side(spec, f[1]);
    if (!side) return side.with_context("");
    const std::optional<Third> third = kThirdNames.parse(f[2]);
    if (!third) return bad(spec, "REGION: expected " + kThirdNames.expected());
    return std::unique_ptr<Pathology>(std::make_unique<Consolidation>(*this, spec, side.take(), *third));
  }
};

}  // namespace

const PathologyModel& consolidation_pathology() {
  static const ConsolidationModel model;
  return model;
}

}  // namespace lungar::sim::pathology
