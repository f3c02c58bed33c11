/// @file scene_lesions.cpp
/// @brief Parse, place, bake the rows, and say where each lesion is (scene_lesions.h).
#include "platform/app/scene_lesions.h"


#include "platform/app/log.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"

namespace lungar::platform {

Result<std::vector<sim::LesionRows>> scene_lesions(const std::vector<std::string>& specs,
                                                   const sim::BakedAsset& asset) {
  if (specs.empty() && asset.lesions.empty()) return std::vector<sim::LesionRows>{};
  std::vector<sim::Lesion> lesions;
  for (const sim::BakedLesion& b : asset.lesions) lesions.push_back(sim::lesion_of(b));
  for (const std::string& spec : specs) {
    Result<sim::Lesion> l = sim::parse_lesion(spec, "lesion");
    if (!l) return fail(l.error());
    lesions.push_back(l.take());
  }
  const sim::InteriorDisplacement field(asset);
  Result<std::vector<sim::PlacedLesion>> placed = sim::place_lesions(field, lesions, "lesion");
  if (!placed) return fail(placed.error());
  for (const sim::PlacedLesion& p : *placed) log_line(sim::describe_lesion(p, asset));
  return sim::lesion_rows(asset, field, *placed);
}

}  // namespace lungar::platform
