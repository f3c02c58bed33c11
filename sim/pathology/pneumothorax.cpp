/// @file pneumothorax.cpp
/// @brief `pneumothorax:SIDE:PERCENT[:tension]`: air in the pleural space lets the lung on SIDE collapse towards its
///        hilum.
///
/// It keeps its shape and shrinks about the hilum until it has lost PERCENT of its volume, which is what Light's
/// index measures from a chest film (%PTX = 100 (1 - L^3 / H^3), L the lung's and H the hemithorax's diameter: a
/// shape-keeping collapse). The collapsed lung takes kCollapsedLungBreathWeight of its healthy weight in the split
/// of each breath (sim/force/breath_share.h), under a tenth of the tidal volume: the other lung takes the rest.
/// `:tension`: the air cannot leave, the pressure pushes the mediastinum over, and the collapsed lung with it moves
/// kTensionShiftMm to the other side, pressing the other lung that far from its medial face (the tracheal deviation
/// and mediastinal shift of a tension pneumothorax on the chest film).
#include <cmath>

#include "sim/motion/surface_regions.h"
#include "sim/pathology/lung_changes.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim::pathology {
namespace {

/// A collapsed lung's weight in the split of the breath, as a fraction of its healthy one: with the CT demo's
/// 53 % right lung, 5 % of its weight is 6 % of the breath supine and 8 % lying on it.
constexpr double kCollapsedLungBreathWeight = 0.05;
/// A tension pneumothorax's mediastinal shift: a shift of 1 to 3 cm on the chest film is the usual sign.
constexpr double kTensionShiftMm = 20.0;
/// Sizes accepted, percent of the lung's volume.
constexpr double kMinPercent = 1.0, kMaxPercent = 90.0;

/// Tension: the collapsed lung l and the mediastinum move kTensionShiftMm towards the other side, and every other
/// lung is pressed that far from its medial side: scaled along x about its lateral extreme, so that its medial face
/// moves by the shift and its lateral face (on the ribs) stays. Its areas, normals, rest volume and swept volumes
/// follow the scaling; its response per unit of force is its own.
void push_mediastinum(BakedAsset& a, std::size_t l) {
  const double mid = midline_x(a);
  const Eigen::Vector3d towards_other = medial_direction(a.lungs[l].name, a.lungs[l].centre[0], mid);
  const Eigen::Vector3d shift = kTensionShiftMm * towards_other;
  BakedLung& pushed = a.lungs[l];
  for (std::size_t i = pushed.first_vertex; i < std::size_t{pushed.first_vertex} + pushed.vertex_count; ++i)
    for (int k = 0; k < 3; ++k) a.positions[3 * i + k] = static_cast<float>(a.positions[3 * i + k] + shift[k]);
  for (int k = 0; k < 3; ++k) pushed.centre[k] = static_cast<float>(pushed.centre[k] + shift[k]);
  for (std::size_t o = 0; o < a.lungs.size(); ++o) {
    if (o == l) continue;
    BakedLung& lung = a.lungs[o];
    const auto [lo, hi] = extent(a, lung, 0);
    if (!(hi - lo > 2 * kTensionShiftMm)) continue;
    // Its lateral extreme is the one away from the pushed lung.
    scale_along_axis(a, o, 0, towards_other.x() > 0 ? hi : lo, 1.0 - kTensionShiftMm / (hi - lo));
  }
}

class Pneumothorax final : public Pathology {
 public:
  Pneumothorax(const PathologyModel& m, std::string_view spec, std::string side, double percent, bool tension)
      : Pathology(m, spec, std::move(side)), percent_(percent), tension_(tension) {}

  Status apply(BakedAsset& a, PatientState& patient) const override {
    Result<std::size_t> l = lung_of(a, side(), spec());
    if (!l) return l.with_context("");
    scale_about_hilum(a, patient, *l, 1.0 - percent_ / 100.0);
    patient.lungs[*l].breath_weight *= kCollapsedLungBreathWeight;
    if (tension_) push_mediastinum(a, *l);
    return {};
  }

 private:
  double percent_;
  bool tension_;
};

class PneumothoraxModel final : public PathologyModel {
 public:
  PneumothoraxModel()
      : PathologyModel(
            {.name = "pneumothorax",
             .syntax = "pneumothorax:SIDE:PERCENT[:tension]",
             .fields = "SIDE left or right; PERCENT 1 to 90",
             .summary = "air in the pleural space: the lung shrinks about its hilum by PERCENT of its volume and "
                        "takes 5 % of its share of each breath; `:tension` pushes the mediastinum and the other lung "
                        "20 mm over",
             .once = "one pneumothorax a lung (give its size once; a second one would collapse the lung again)"}) {}
  Result<std::unique_ptr<Pathology>> parse(std::string_view spec, std::span<const std::string_view> f) const override {
    const bool tension = f.size() == 4;
    if (tension && f[3] != "tension")
      return bad(spec, "expected pneumothorax:SIDE:PERCENT or pneumothorax:SIDE:PERCENT:tension");
    if (f.size() != 3 && !tension)
      return bad(spec, "expected " + std::string(syntax()) + " (SIDE left or right, PERCENT 1 to 90)");
    Result<std::string> side = parse_side(spec, f[1]);
    if (!side) return side.with_context("");
    Result<double> percent =
        parse_number(spec, f[2], kMinPercent, kMaxPercent,
                     "PERCENT: expected a number from 1 to 90 (the share of the lung's volume lost)");
    if (!percent) return percent.with_context("");
    return std::unique_ptr<Pathology>(std::make_unique<Pneumothorax>(*this, spec, side.take(), *percent, tension));
  }
};

}  // namespace

const PathologyModel& pneumothorax_pathology() {
  static const PneumothoraxModel model;
  return model;
}

}  // namespace lungar::sim::pathology
