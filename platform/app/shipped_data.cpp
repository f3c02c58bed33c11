/// @file shipped_data.cpp
/// @brief The search order for shipped data (shipped_data.h).
#include "platform/app/shipped_data.h"

#include <cstdlib>

namespace lungar::platform {

std::vector<std::filesystem::path> shipped_data_places(const std::string& sub, const std::string& source_sub) {
  namespace fs = std::filesystem;
  std::vector<fs::path> places;
  if (const char* d = std::getenv("LUNGAR_DATA_DIR"); d && *d) places.push_back(fs::path(d) / sub);
  std::error_code ec;
  if (const fs::path self = fs::read_symlink("/proc/self/exe", ec); !ec)
    places.push_back(self.parent_path() / ".." / "share" / "lungar" / sub);
  places.push_back(fs::path(LUNGAR_SOURCE_DIR) / source_sub);
  return places;
}

}  // namespace lungar::platform
