/// @file surface_regions.h
/// @brief The four faces of a lung's surface that move differently in breathing, found from its geometry:
///        diaphragmatic (the base, on the diaphragm), costal (against the ribs), mediastinal (the medial face and
///        the hilum) and apical (the top, in the cupola of the pleura).
///
/// Each face has its own boundary condition in the sliding motion model (motion_model.h; docs/design.md, "Vector
/// displacement"). The rules, in the lung frame (LPS, +z superior), per vertex with outward normal n, height z
/// in the lung's extent [z_lo, z_hi] and medial direction m (towards the body's midline):
///   apical          z above z_hi - apex_fraction * height;
///   diaphragmatic   n_z below -diaphragm_normal_z and z below z_lo + diaphragm_fraction * height;
///   mediastinal     n.m above mediastinal_normal_dot (and neither of the above);
///   costal          the rest.
/// A CT label map with more labels than one per lung could name the faces directly; lungar's demo map holds one
/// label per lung, so geometry decides.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "config/base/enum_names.h"
#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

enum class SurfaceRegion : std::uint8_t { costal, diaphragmatic, mediastinal, apical };
inline constexpr int kSurfaceRegionCount = 4;
inline constexpr EnumNames<SurfaceRegion, kSurfaceRegionCount> kSurfaceRegionNames{
    {{{SurfaceRegion::costal, "costal"},
      {SurfaceRegion::diaphragmatic, "diaphragmatic"},
      {SurfaceRegion::mediastinal, "mediastinal"},
      {SurfaceRegion::apical, "apical"}}}};

/// Thresholds of the rules above. The defaults put the diaphragmatic face at about a fifth to a quarter of an
/// adult lung's surface, as its share of the pleura in anatomy atlases.
struct RegionRules {
  double apex_fraction = 0.12;          ///< the top 12 % of the height is the apex
  double diaphragm_fraction = 0.5;      ///< the diaphragm lies in the lower half
  double diaphragm_normal_z = 0.35;     ///< its normals point down by more than about 20 degrees
  double mediastinal_normal_dot = 0.5;  ///< faces turned within 60 degrees of the midline
};

/// The unit direction towards the body's midline for a lung named `name` ("right" lies at -x in LPS, so its
/// medial side is +x); for another name, from the side of its centre's x relative to `midline_x`.
Eigen::Vector3d medial_direction(const std::string& name, double centre_x, double midline_x);

/// Each vertex's face by the rules above.
std::vector<SurfaceRegion> classify_surface(const TriMesh& mesh, const std::vector<Eigen::Vector3d>& normals,
                                            const Eigen::Vector3d& medial, const RegionRules& rules = {});

}  // namespace lungar::sim
