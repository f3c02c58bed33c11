/// @file level_of_detail.cpp
/// @brief Draw count from the projected size.
#include "render/level_of_detail.h"

#include <algorithm>
#include <cmath>

namespace lungar::render {

std::uint32_t lod_point_count(const LungRange& lung, const glm::mat4& model_view, float projection_y,
                              int viewport_height_px, float point_size_px, float coverage) {
  const glm::vec4 centre = model_view * glm::vec4(lung.bound_centre, 1.f);
  const double depth = -centre.z;
  // The front half of the surface (the back half is culled) lies between depth - r and depth; use its middle.
  const double front_depth = depth - 0.5 * lung.bound_radius;
  if (front_depth <= 1e-3) return lung.vertex_count;  // the eye is inside or at the lung: draw everything
  const double px_per_mm = 0.5 * projection_y * viewport_height_px / front_depth;
  const double size = std::max(1.0, static_cast<double>(point_size_px));
  const double wanted = coverage * lung.surface_area_mm2 * px_per_mm * px_per_mm / (size * size);
  const double lowest = std::min<double>(lung.vertex_count, 64.0);  // a far lung keeps a recognisable shape
  return static_cast<std::uint32_t>(std::clamp(std::ceil(wanted), lowest, static_cast<double>(lung.vertex_count)));
}

}  // namespace lungar::render
