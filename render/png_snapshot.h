/// @file png_snapshot.h
/// @brief Writes RGBA8 images to PNG (libpng), atomically: a temporary file renamed into place on success.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "config/base/result.h"

namespace lungar::render {

/// `rgba` holds width * height * 4 bytes, top row first. On any failure no file is left under `path`.
Status write_png(const std::string& path, int width, int height, std::span<const std::uint8_t> rgba);

/// Reads back the given rectangle of the bound read framebuffer and writes it with write_png.
Status snapshot_png(const std::string& path, int x, int y, int width, int height);

}  // namespace lungar::render
