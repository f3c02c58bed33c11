/// @file lung_changes.h
/// @brief What the pathology plug-ins (sim/pathology/<name>.cpp) do to a baked lung, and how they read their specs:
///        shared so that each plug-in is only its model.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim::pathology {

/// The point or vector at `p` (three floats of an asset's array).
inline Eigen::Vector3d vec3(const float* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

/// "pathology 'SPEC': WHY", the one line every pathology error is.
Error bad(std::string_view spec, const std::string& why);

/// A spec's fields: "pneumothorax:right:30" -> {"pneumothorax", "right", "30"}.
std::vector<std::string_view> split_spec(std::string_view spec);

/// A model's fields() text, split at its "; ".
std::vector<std::string_view> split_fields(std::string_view fields);

/// A side field: "left" or "right", else the error.
Result<std::string> parse_side(std::string_view spec, std::string_view field);

/// A number field from `lo` to `hi` (inclusive), else the error naming `what` (e.g. "PERCENT: expected a number
/// from 1 to 90 (the share of the lung's volume lost)").
Result<double> parse_number(std::string_view spec, std::string_view field, double lo, double hi,
                            const std::string& what);

/// The index of the lung called `name`, or a.lungs.size().
std::size_t find_lung(const BakedAsset& a, const std::string& name);

/// The index of the lung called `side`, or the error naming the spec ("the asset has no lung named ...").
Result<std::size_t> lung_of(const BakedAsset& a, const std::string& side, std::string_view spec);

/// The lung's first-order swept volume for the unnormalised force SH `f`, mm^3 (unscaled): sum over its vertices
/// of A_I (e_I . n_I) sum_lm T^I_lm f_lm, the sum BakedLung's volume_const and volume_grad are made of.
double swept(const BakedAsset& a, const BakedLung& lung, const std::vector<float>& f);

/// The lung's extent along lung-frame axis `axis` (0 x, 1 y, 2 z: +z superior).
std::pair<double, double> extent(const BakedAsset& a, const BakedLung& lung, int axis);

/// The pair's volume-weighted mean x: the body's midline as the lungs give it.
double midline_x(const BakedAsset& a);

/// Before a change of the lung's response: its swept volumes as they were (`lung`'s), kept in its state `now` for
/// its weight in the split (breath_share.h), unless an earlier pathology kept them already.
void keep_healthy_volumes(const BakedLung& lung, LungState& now);

/// After the lung's response or surface changed: its swept volumes summed again from the arrays, the bake's
/// per-lung factor to the enclosed volume (about 1.03) kept; `before` is the first-order sum from before the
/// change (nothing is done when it is not positive).
void resum_swept_volumes(const BakedAsset& a, BakedLung& lung, double before);

/// The hilum: the area-weighted centre of the lung's medial face (normals within 60 degrees of the midline) in
/// the middle third of its height, where the bronchus and vessels enter; the lung's centre when it has none.
Eigen::Vector3d hilum(const BakedAsset& a, std::size_t l);

/// Scales lung l about its hilum to `volume_factor` of its volume, keeping its shape. The first-order swept
/// volumes scale with the area (s^2): the per-vertex response T is kept, so a unit of force moves the same
/// millimetres over a smaller (or larger) surface. The healthy volumes a pathology kept in `patient` scale too.
void scale_about_hilum(BakedAsset& a, PatientState& patient, std::size_t l, double volume_factor);

/// Scales lung l along lung-frame axis `axis` (0 x, 1 y, 2 z) by k about the plane at `about`: its positions,
/// centre, areas and normals (a surface element under u -> k u: its area times sqrt(n_u^2 + k^2 (1 - n_u^2)), its
/// normal along (n_u, k n_v, k n_w)), its rest volume (times k) and its swept volumes (summed again); its response
/// per unit of force is its own.
void scale_along_axis(BakedAsset& a, std::size_t l, int axis, double about, double k);

/// Scales the response of lung l's vertex i (its transfer row, linear basis and off-axis part) by `m`.
void scale_response(BakedAsset& a, std::size_t i, float m);

}  // namespace lungar::sim::pathology
