/// @file scene_lesions.h
/// @brief The settings' lesions (sim.lesion, --lesion) placed in the loaded lungs and given their coefficient rows,
///        for the Runtime to draw and move (platform/runtime/runtime.h, RuntimeParts::lesions).
/// @ingroup platform
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"
#include "sim/motion/lesion_rows.h"

namespace lungar::platform {

/// The asset's own lesions (baked by `lungar-bake --lesion`), then each spec ("NAME=x,y,z,radius_mm") parsed; each
/// checked to lie whole inside one lung of `asset` (the drawn one, its pathologies applied) and given its rows;
/// one line for the first that is not (a spec that repeats a baked lesion's name among them). The interior field is
/// built only when there is a lesion (a second or two on the CT lungs).
Result<std::vector<sim::LesionRows>> scene_lesions(const std::vector<std::string>& specs, const sim::BakedAsset& asset);

}  // namespace lungar::platform
