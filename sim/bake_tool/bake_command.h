/// @file bake_command.h
/// @brief What `lungar-bake` does once its command line is parsed: import (a mesh, a label map) or generate,
///        simplify, bake, write the asset and the report. Tests call it directly.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/bake/bake.h"
#include "config/base/result.h"
#include "sim/mesh/procedural_lungs.h"

namespace lungar::sim {

/// Vertices of a pair baked from a label map when --nodes is not given: the paper's model size.
inline constexpr std::uint32_t kDefaultLabelMapNodes = 400000;

/// The volume one imported lung may enclose, mL: from a newborn's lung (some 50 mL at rest, less collapsed) to
/// beyond an adult's at total lung capacity (a tall man's pair holds 7-8 L). Outside it the units are wrong (a
/// mesh in mm read with --units m is 10^9 times too large) or the surface is not a lung; --any-volume bakes it.
inline constexpr double kMinLungVolumeMl = 30.0, kMaxLungVolumeMl = 8000.0;

struct BakeCommand {
  bool procedural = false;
  /// Vertices in all, shared between the lungs by surface area; 0: the input's default (procedural pair and
  /// label map: 400,000; meshes: as they are). Meshes with more are simplified to it.
  std::uint32_t nodes = 0;
  std::uint64_t seed = 1;
  std::vector<std::string> meshes;
  std::string labelmap;              ///< NRRD, NIfTI or MetaImage label map
  std::vector<std::string> labels;   ///< NAME=VALUE, one per lung of the label map
  /// --lesion: NAME=VALUE, a label of the label map (a segmented tumour: the ball of its volume at its centroid),
  /// or NAME=x,y,z,radius_mm (LPS); baked into the asset, which the runtime then draws (sim/asset/baked_asset.h).
  std::vector<std::string> lesions;
  std::string units = "mm";
  std::string out;                   ///< the .lungbake path
  std::string report_json;           ///< "" for none
  bool any_volume = false;           ///< --any-volume: bake lungs outside kMinLungVolumeMl..kMaxLungVolumeMl
  BakeOptions options;
};

/// Runs the bake; on any error nothing is left under `out` (or the report's path). `notes` collects repairs.
/// `progress` also hears the import's stages ("label map", "surface", "simplify"). Once command.options.cancel is
/// set, it stops at the next step and fails with "interrupted; nothing was written".
Result<BakeReport> run_bake_command(const BakeCommand& command, const BakeProgress& progress,
                                    std::vector<std::string>& notes);

}  // namespace lungar::sim
