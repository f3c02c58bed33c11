/// @file shipped_data.h
/// @brief Where the data lungar ships lies (the demo's label map, the scenarios): one search order for all of it.
/// @ingroup platform
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lungar::platform {

/// The places to look for the shipped folder `sub` ("lungs", "scenarios"), in order: $LUNGAR_DATA_DIR/`sub`,
/// <exe dir>/../share/lungar/`sub` (the Debian package), then the source tree's `source_sub` (a build tree's run).
std::vector<std::filesystem::path> shipped_data_places(const std::string& sub, const std::string& source_sub);

}  // namespace lungar::platform
