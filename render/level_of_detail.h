/// @file level_of_detail.h
/// @brief How many of a lung's points to draw for one eye: enough to cover its projected surface, no more.
///
/// The asset stores each lung's points so that every prefix is an even subsample of the surface; drawing the
/// first N points of the range covers the surface at a density of N / area. For square points of s pixels at a
/// scale of k pixels per mm, the surface is covered when N s^2 / k^2 exceeds the area by a safety factor, so the
/// work per eye follows the pixels the lung covers, not the model size.
#pragma once

#include <cstdint>

#include <glm/mat4x4.hpp>

#include "render/lung_drawable.h"

namespace lungar::render {

/// `coverage` is the factor by which the drawn points' total footprint exceeds the surface area they cover: 3 is
/// hole-free for sim's bake order (progressive Poisson disks, sim/mesh/lod_order.cpp) and for the R2 order of the
/// test assets; 2 leaves a few single-pixel holes where the surface faces the eye.
/// `model_view` maps the lung frame to the eye, `projection_y` is projection[1][1], `viewport_height_px` the
/// eye's height.
std::uint32_t lod_point_count(const LungRange& lung, const glm::mat4& model_view, float projection_y,
                              int viewport_height_px, float point_size_px, float coverage);

}  // namespace lungar::render
