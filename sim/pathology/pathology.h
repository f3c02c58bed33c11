/// @file pathology.h
/// @brief The diseases a trainer switches on, each a named model applied to a baked asset when it is loaded: the
///        runtime, `lungar-bake export` and the CPU paths all draw the changed asset, so they agree.
///
/// - `pneumothorax:SIDE:PERCENT`: air in the pleural space lets the lung on SIDE collapse towards its hilum. It
///   keeps its shape and shrinks about the hilum until it has lost PERCENT of its volume, which is what Light's
///   index measures from a chest film (%PTX = 100 (1 - L^3 / H^3), L the lung's and H the hemithorax's diameter:
///   a shape-keeping collapse). The collapsed lung takes kCollapsedLungBreathWeight of its healthy weight in the
///   split of each breath (sim/force/breath_share.h), under a tenth of the tidal volume: the other lung takes the
///   rest. `pneumothorax:SIDE:PERCENT:tension`: the air cannot leave, the pressure pushes the mediastinum over, and
///   the collapsed lung with it moves kTensionShiftMm to the other side, pressing the other lung that far from its
///   medial face (the tracheal deviation and mediastinal shift of a tension pneumothorax on the chest film).
/// - `consolidation:SIDE:REGION` (upper, middle or lower third of the lung's height): the region fills with fluid
///   or cells, stops ventilating and stiffens. Its surface moves kConsolidatedResponse of its healthy motion (each
///   vertex's transfer row, T^I_lm, its linear basis and its off-axis part scaled), with a ramp of
///   kConsolidationRamp of the height outside the region so that the surface does not tear. The lung's weight in
///   the split falls by the share of its swept volume it lost in the posture (V(g) / V_healthy(g)): the tidal
///   volume stays what the breathing delivers, so the part of it the region no longer takes spreads over
///   everything that still ventilates, in both lungs, in proportion.
///
/// - `emphysema:SEVERITY[:SIDE]` (SEVERITY 0 to 1; both lungs unless SIDE): destroyed alveolar walls trap air, so
///   the lung rests larger. It grows about its hilum, keeping its shape, to 1 + kEmphysemaFrcGain x SEVERITY of its
///   volume (severe COPD's functional residual capacity is 130-150 % of predicted). Its poor recoil, a slower and
///   longer expiration, is the breathing's: the runtime breathes with the `emphysema` preset (compliance 140
///   mL/cmH2O, resistance 10.5 cmH2O.s/L, tau 1.5 s against the normal 0.36 s) when the breathing is at its default.
/// - `ards:SEVERITY` (0 to 1): the acute respiratory distress syndrome's heavy, wet lung collapses where it lies
///   lowest, and which part that is follows the posture: supine the dorsal lung stops ventilating and the breath
///   moves ventral, prone the dorsal lung recruits. Not a change of the asset but of the applied force, evaluated
///   per posture (sim/force/dependent_collapse.h): a pattern that is not linear in position, carried by the SH.
///   Applied after the others, whatever the order given.
///
/// The first three are changes of the asset's per-vertex response and per-lung figures, made in milliseconds at
/// load: no second bake, no larger asset, no work in the frame; ARDS costs a projection of its pattern per change
/// of posture (docs/design.md, "Pathologies").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "config/base/enum_names.h"
#include "config/base/result.h"
#include "sim/asset/baked_asset.h"

namespace lungar::sim {

enum class PathologyKind { Pneumothorax, Consolidation, Emphysema, Ards };
enum class LungThird { Upper, Middle, Lower };

inline constexpr EnumNames<PathologyKind, 4> kPathologyKindNames{{{{PathologyKind::Pneumothorax, "pneumothorax"},
                                                                   {PathologyKind::Consolidation, "consolidation"},
                                                                   {PathologyKind::Emphysema, "emphysema"},
                                                                   {PathologyKind::Ards, "ards"}}}};
inline constexpr EnumNames<LungThird, 3> kLungThirdNames{
    {{{LungThird::Upper, "upper"}, {LungThird::Middle, "middle"}, {LungThird::Lower, "lower"}}}};

/// A collapsed lung's weight in the split of the breath, as a fraction of its healthy one: with the CT demo's
/// 53 % right lung, 5 % of its weight is 6 % of the breath supine and 8 % lying on it.
inline constexpr double kCollapsedLungBreathWeight = 0.05;
/// How much of its healthy motion a consolidated region's surface keeps.
inline constexpr double kConsolidatedResponse = 0.1;
/// The ramp from consolidated to healthy outside the region, as a fraction of the lung's height.
inline constexpr double kConsolidationRamp = 0.05;
/// Emphysema at severity 1 rests this much larger (a share of the healthy volume).
inline constexpr double kEmphysemaFrcGain = 0.4;
/// A tension pneumothorax's mediastinal shift: a shift of 1 to 3 cm on the chest film is the usual sign.
inline constexpr double kTensionShiftMm = 20.0;
/// Pneumothorax sizes accepted, percent of the lung's volume.
inline constexpr double kMinPneumothoraxPercent = 1.0, kMaxPneumothoraxPercent = 90.0;

struct Pathology {
  PathologyKind kind = PathologyKind::Pneumothorax;
  std::string side;                     ///< the lung's name in the asset: "left" or "right" ("" emphysema: both)
  double percent = 0;                   ///< pneumothorax: the volume lost, percent
  bool tension = false;                 ///< pneumothorax: the mediastinum pushed over
  LungThird region = LungThird::Lower;  ///< consolidation: which third of the height
  double severity = 0;                  ///< emphysema, ards: 0 to 1
  std::string spec;                     ///< as the user wrote it
};

/// "pneumothorax:right:30", "consolidation:left:upper", "emphysema:0.5", "ards:0.6" -> a Pathology, or one line
/// saying what was expected.
Result<Pathology> parse_pathology(std::string_view spec);

/// Whether `a` and `b` change the same thing, so that applying both would compound it (two pneumothoraces of a
/// lung collapse it twice): two pneumothoraces of one lung, two consolidations of one third of one lung, two
/// emphysemas of one lung (an emphysema without SIDE is both lungs'), two ARDS.
bool same_pathology(const Pathology& a, const Pathology& b);

/// Every spec parses and none is the same pathology as one before it (same_pathology); the error names both specs
/// and what was expected.
Status check_pathologies(const std::vector<std::string>& specs);

/// Applies `p` to `asset`; an error (asset untouched) when the asset has no lung on that side.
Status apply_pathology(BakedAsset& asset, const Pathology& p);

/// Whether any of `specs` is an emphysema (whose recoil is the breathing's: the runtime's preset).
bool has_emphysema(const std::vector<std::string>& specs);

/// Parses and applies each spec in order (ARDS last); the error names the spec (a repeated one, check_pathologies,
/// too). All or nothing: on an error `asset` is unchanged.
Status apply_pathologies(BakedAsset& asset, const std::vector<std::string>& specs);

}  // namespace lungar::sim
