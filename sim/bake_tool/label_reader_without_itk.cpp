/// @file label_reader_without_itk.cpp
/// @brief read_label_image for a lungar-bake built without ITK (LUNGAR_LABEL_MAPS=OFF): one clear refusal.
///
/// Debian builds ITK (libinsighttoolkit5-dev) for amd64 only, so an arm64 board's lungar-bake bakes meshes and
/// the procedural pair but no label maps. The CMake option picks this file instead of itk_label_reader.cpp.
#include "sim/bake_tool/itk_label_reader.h"

namespace lungar::sim::itk_io {

lungar::Result<LabelImage> read_label_image(const std::string& path, const std::vector<std::int64_t>&) {
  return fail(path + ": label maps are read through ITK, and this lungar-bake was built without it "
                     "(LUNGAR_LABEL_MAPS=OFF: Debian ships ITK for amd64 only); expected a surface (--mesh) here, "
                     "or bake the label map on an amd64 machine and copy its .lungbake");
}

}  // namespace lungar::sim::itk_io
