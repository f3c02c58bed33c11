/// @file partial_files.h
/// @brief Test helper: the partial files a write left beside its output ("<name>.partial-XXXXXX", see
/// config/base/atomic_file.h), which a finished or refused write must not leave.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lungar::testing {

/// The names of the files beside `path` whose name starts with "<path's name>.partial".
inline std::vector<std::string> partial_files_beside(const std::filesystem::path& path) {
  std::vector<std::string> found;
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::string prefix = path.filename().string() + ".partial";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) found.push_back(name);
  }
  return found;
}

}  // namespace lungar::testing
