/// @file lesion.h
/// @brief A lesion inside a lung (a tumour, a nodule): a ball placed by `--lesion NAME=x,y,z,radius_mm`, checked to lie
///        inside one lung, and moved by the interior field (interior_displacement.h) as the tissue around it moves.
///
/// Its displacement is its centre's. The interior field is harmonic inside each lung, and the mean of a harmonic
/// field over a ball equals its value at the centre (the mean value property), so the centre's displacement is the
/// whole lesion's mean displacement, exactly, for a ball inside the lung. Radiotherapy's tumour-motion figures (the
/// peak-to-peak excursion of the tumour's centre of mass over a breath; Seppenwoolde et al. 2002) are of that.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "config/base/result.h"
#include "sim/motion/interior_displacement.h"

namespace lungar::sim {

/// A ball in the lung frame (LPS, mm).
struct Lesion {
  std::string name;
  Eigen::Vector3d centre_mm = Eigen::Vector3d::Zero();
  double radius_mm = 0;
  /// Segmented (a label of the map the lungs came from): the lung's surface was made round its voxels, so only its
  /// centre is checked; the ball of its volume need not fit a tumour that lies against the pleura.
  bool from_label = false;
};

/// "NAME=x,y,z,radius_mm" -> a Lesion, or one line naming the spec and what was expected. NAME: 1 to 32 letters,
/// digits, '_' or '-'; the radius in (0, kMaxLesionRadiusMm]. `what` names where the spec came from in the error
/// ("--lesion", or the settings' "lesion").
Result<Lesion> parse_lesion(const std::string& spec, std::string_view what = "--lesion");

/// A lesion placed in its lung.
struct PlacedLesion {
  Lesion lesion;
  std::size_t lung = 0;  ///< index into the asset's lungs
};

/// The lung that holds each lesion whole: its centre and 26 points of its surface (the cube's directions) inside
/// the same lung (the centre alone for one from a label). One line for the first that is not, naming it and where it
/// lies; two lesions with one name are refused too. `what` as for parse_lesion.
Result<std::vector<PlacedLesion>> place_lesions(const InteriorDisplacement& field, const std::vector<Lesion>& lesions,
                                                std::string_view what = "--lesion");

/// A lesion as the asset keeps it, and back (sim/asset/baked_asset.h, BakedLesion).
BakedLesion baked_lesion(const PlacedLesion& p);
Lesion lesion_of(const BakedLesion& b);

/// One line saying where a placed lesion is: "lesion tumour: right lung, 5.0 mm radius at (x, y, z) mm (LPS)",
/// with ", segmented" for one from a label (the bake's notes and the runtime's log).
std::string describe_lesion(const PlacedLesion& p, const BakedAsset& asset);

/// The lesions' centres as interior points, for InteriorDisplacement::displacement().
InteriorPoints lesion_centres(const std::vector<PlacedLesion>& lesions);

/// The largest distance between two of a lesion's positions over a breath: `displacements` holds one vector per
/// phase (mm). Returns the peak-to-peak excursion and, in `si_mm`, its cranio-caudal (z) part: the z range.
double peak_to_peak_mm(const std::vector<Eigen::Vector3d>& displacements, double& si_mm);

}  // namespace lungar::sim
