/// @file scene_lesions.cpp
/// @brief Parse, place, bake the rows, and say where each lesion is (scene_lesions.h).
#include "platform/app/scene_lesions.h"

#include <cstdio>

#include "platform/app/log.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"

namespace lungar::platform {

Result<std::vector<sim::LesionRows>> scene_lesions(const std::vector<std::string>& specs,
                                                   const sim::BakedAsset& asset) {
  if (specs.empty() && asset.lesions.empty()) return std::vector<sim::LesionRows>{};
  std::vector<sim::Lesion> lesions;
  for (const sim::BakedLesion& b : asset.lesions)
    lesions.push_back(
        {b.name, Eigen::Vector3d(b.centre_mm[0], b.centre_mm[1], b.centre_mm[2]), b.radius_mm, b.from_label});
  for (const std::string& spec : specs) {
    Result<sim::Lesion> l = sim::parse_lesion(spec, "lesion");
    if (!l) return fail(l.error());
    lesions.push_back(l.take());
  }
  const sim::InteriorDisplacement field(asset);
  Result<std::vector<sim::PlacedLesion>> placed = sim::place_lesions(field, lesions, "lesion");
  if (!placed) return fail(placed.error());
  for (const sim::PlacedLesion& p : *placed) {
    char line[200];
    std::snprintf(line, sizeof line, "lesion %s: %s lung, %.1f mm radius at (%.1f, %.1f, %.1f) mm (LPS)",
                  p.lesion.name.c_str(), asset.lungs[p.lung].name.c_str(), p.lesion.radius_mm, p.lesion.centre_mm.x(),
                  p.lesion.centre_mm.y(), p.lesion.centre_mm.z());
    log_line(line);
  }
  return sim::lesion_rows(asset, field, *placed);
}

}  // namespace lungar::platform
