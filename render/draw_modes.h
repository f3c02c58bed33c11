/// @file draw_modes.h
/// @brief How the renderer draws a frame, in the names settings, the command line and logs give them: points or
/// mesh, the stereo strategy, where the drawn positions come from. Apart from renderer.h so that code which only
/// chooses (settings, the runtime's config) needs no more of the renderer.
#pragma once

#include "config/base/enum_names.h"

namespace lungar::render {

enum class DrawMode { Points, Mesh };
/// PerEye: each eye's draw evaluates eq. (7) (the paper's way; measured faster, so the default: docs/measurements.md).
/// DeformOnce: one transform-feedback pass writes the deformed points into a buffer, then both eyes draw it.
enum class StereoStrategy { PerEye, DeformOnce };
/// Where the drawn positions come from: eq. (7) in the shader, positions uploaded from the CPU
/// (LungDrawable::upload_positions), or the rest shape.
enum class PositionSource { Shader, Uploaded, Rest };

/// The names TOML, the command line and logs give them.
inline constexpr EnumNames<DrawMode, 2> kDrawModeNames{{{{DrawMode::Points, "points"}, {DrawMode::Mesh, "mesh"}}}};
inline constexpr EnumNames<StereoStrategy, 2> kStereoStrategyNames{
    {{{StereoStrategy::PerEye, "per_eye"}, {StereoStrategy::DeformOnce, "deform_once"}}}};
inline const char* to_string(DrawMode v) { return kDrawModeNames.name(v); }
inline const char* to_string(StereoStrategy v) { return kStereoStrategyNames.name(v); }

}  // namespace lungar::render
