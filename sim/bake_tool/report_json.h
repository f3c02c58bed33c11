/// @file report_json.h
/// @brief The bake report as JSON (snake_case keys with unit suffixes, docs/design.md "Contracts") and its
///        atomic write.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/bake/bake.h"

namespace lungar::sim {

/// Every figure of BakeReport (the asset's size, the map, the accuracy against the exact eq. (1), physiology),
/// plus timings per stage, the lungs' names, and the repair notes.
nlohmann::json report_json(const BakeReport& report, const std::vector<std::string>& notes);


}  // namespace lungar::sim
