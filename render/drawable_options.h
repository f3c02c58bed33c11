/// @file drawable_options.h
/// @brief How a LungDrawable lays out a baked asset's coefficients on the GPU: which basis, attributes or a
/// texture, full or half floats. Apart from lung_drawable.h so that code which only chooses (the bench's options)
/// needs no more of the renderer.
#pragma once

#include "config/base/enum_names.h"

namespace lungar::render {

/// Which per-vertex coefficient field the shader dots with the force: the SH field of eq. (7) (L^2 values) or the
/// exact linear basis (4 values: tau0, tau_x, tau_y, tau_z; docs/design.md, The exact linear basis).
enum class Basis { SphericalHarmonics, Linear };
/// Where the coefficients live: vertex attributes (up to 36 coefficients), or a float texture read by gl_VertexID.
enum class CoeffStorage { Auto, Attributes, Texture };
inline constexpr EnumNames<CoeffStorage, 3> kCoeffStorageNames{
    {{{CoeffStorage::Auto, "auto"}, {CoeffStorage::Attributes, "attributes"}, {CoeffStorage::Texture, "texture"}}}};
inline const char* to_string(CoeffStorage v) { return kCoeffStorageNames.name(v); }

struct DrawableOptions {
  Basis basis = Basis::SphericalHarmonics;
  CoeffStorage storage = CoeffStorage::Auto;  ///< Auto: see coefficients_in_texture() (lung_drawable.h)
  bool half_float = false;                    ///< coefficients as 16-bit floats (half the memory traffic)
};

}  // namespace lungar::render
