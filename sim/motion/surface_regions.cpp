/// @file surface_regions.cpp
/// @brief The rules of surface_regions.h, vertex by vertex.
#include "sim/motion/surface_regions.h"

#include <algorithm>

namespace lungar::sim {

Eigen::Vector3d medial_direction(const std::string& name, double centre_x, double midline_x) {
  if (name == "right") return Eigen::Vector3d::UnitX();
  if (name == "left") return -Eigen::Vector3d::UnitX();
  return Eigen::Vector3d(centre_x < midline_x ? 1.0 : -1.0, 0.0, 0.0);
}

std::vector<SurfaceRegion> classify_surface(const TriMesh& mesh, const std::vector<Eigen::Vector3d>& normals,
                                            const Eigen::Vector3d& medial, const RegionRules& rules) {
  double lo = 1e300, hi = -1e300;
  for (const Eigen::Vector3d& p : mesh.positions) {
    lo = std::min(lo, p.z());
    hi = std::max(hi, p.z());
  }
  const double height = hi - lo;
  const double apex_z = hi - rules.apex_fraction * height;
  const double diaphragm_z = lo + rules.diaphragm_fraction * height;
  std::vector<SurfaceRegion> out(mesh.positions.size(), SurfaceRegion::costal);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double z = mesh.positions[i].z();
    const Eigen::Vector3d& n = normals[i];
    if (z > apex_z) out[i] = SurfaceRegion::apical;
    else if (n.z() < -rules.diaphragm_normal_z && z < diaphragm_z) out[i] = SurfaceRegion::diaphragmatic;
    else if (n.dot(medial) > rules.mediastinal_normal_dot) out[i] = SurfaceRegion::mediastinal;
  }
  return out;
}

}  // namespace lungar::sim
