/// @file text_file.cpp
/// @brief Temporary file + rename.
#include "platform/text_file.h"

#include <filesystem>
#include <fstream>

namespace lungar::platform {

bool write_text_atomically(const std::string& path, const std::string& text, std::string& error) {
  const std::filesystem::path p(path);
  std::error_code ec;
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream o(tmp, std::ios::trunc);
    o << text;
    if (!o.flush()) {
      error = path + ": cannot write it";
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    error = path + ": cannot rename the temporary file: " + ec.message();
    std::filesystem::remove(tmp, ec);
    return false;
  }
  return true;
}

}  // namespace lungar::platform
