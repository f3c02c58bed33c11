/// @file png_snapshot.cpp
/// @brief libpng writer with setjmp error handling, and the framebuffer snapshot.
#include "render/png_snapshot.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

#include "config/base/atomic_file.h"
#include "render/frame_target.h"

namespace lungar::render {
namespace {

// libpng reports errors through longjmp; this keeps the jump away from C++ objects with destructors.
bool encode(std::FILE* file, int width, int height, const std::uint8_t* rgba, const char** rows_storage_error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    *rows_storage_error = "libpng failed while encoding";
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int r = 0; r < height; ++r) {
    png_write_row(png, const_cast<png_bytep>(rgba + static_cast<std::size_t>(r) * width * 4));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

Status write_png(const std::string& path, int width, int height, std::span<const std::uint8_t> rgba) {
  if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * height * 4) {
    return fail(path + ": image: expected " + std::to_string(width) + "x" + std::to_string(height) +
                " RGBA pixels, got " + std::to_string(rgba.size()) + " bytes");
  }
  AtomicFile file;
  if (Status opened = file.open(path); !opened) return opened;
  const char* why = "write failed";
  if (!encode(file.stream(), width, height, rgba.data(), &why)) return fail(path + ": " + why);
  return file.commit();
}

Status snapshot_png(const std::string& path, int x, int y, int width, int height) {
  std::vector<std::uint8_t> rgba;
  read_pixels_top_down(x, y, width, height, rgba);
  return write_png(path, width, height, rgba);
}

}  // namespace lungar::render
