/// @file text_file.h
/// @brief Writes a small text output (stats JSON, a registration) whole or not at all: a temporary file beside it,
/// then a rename, so a reader never sees half a file under the final name.
#pragma once

#include <string>

namespace lungar::platform {

/// Creates the parent folder if needed. False with `error` ("PATH: what") when anything fails; then no file is left
/// under `path` or beside it.
bool write_text_atomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace lungar::platform
