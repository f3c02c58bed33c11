/// @file bake_command.h
/// @brief What `lungar-bake` does once its command line is parsed: import or generate, bake, write the asset
///        and the report. Tests call it directly.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/bake/bake.h"
#include "config/base/result.h"
#include "sim/mesh/procedural_lungs.h"

namespace lungar::sim {

struct BakeCommand {
  bool procedural = false;
  std::uint32_t nodes = kDefaultProceduralNodes;
  std::uint64_t seed = 1;
  std::vector<std::string> meshes;
  std::string units = "mm";
  std::string out;                 ///< the .lungbake path
  std::string report_json;         ///< "" for none
  BakeOptions options;
};

/// Runs the bake; on any error nothing is left under `out` (or the report's path). `notes` collects repairs.
Result<BakeReport> run_bake_command(const BakeCommand& command, const BakeProgress& progress,
                                    std::vector<std::string>& notes);

}  // namespace lungar::sim
