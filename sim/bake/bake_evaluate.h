/// @file bake_evaluate.h
/// @brief The bake report's accuracy and physiology figures (internal to sim/bake): eq. (7), the linear basis,
///        the paper's interpolation and the truncated rows, each against the exact eq. (1) by sparse solves.
#pragma once

#include <memory>
#include <vector>

#include "sim/bake/bake.h"
#include "sim/bake/lung_bake.h"

namespace lungar::sim {

/// Fills the report's figures; throws Cancelled when `workers` is cancelled.
void evaluate_bake(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& asset,
                   const BakeOptions& options, const Workers& workers, const BakeProgress& progress,
                   BakeReport& report);

}  // namespace lungar::sim
