/// @file itk_label_reader.h
/// @brief The only file that sees ITK: reads a label map and cuts one cropped mask per label, into plain types.
///
/// ITK ships its own copy of Eigen (3.3) under the same include guards as the system's (3.4) that sim/ uses,
/// so no translation unit may include both: this header holds no Eigen, and label_map_io.cpp turns its output
/// into sim's voxel grids.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::sim::itk_io {

/// One label's voxels: the bounding box [lo, lo + size) of the map's grid and 1 where the label is.
struct CroppedLabel {
  std::int64_t value = 0;
  std::int64_t voxels = 0;
  std::array<int, 3> lo{}, size{};
  std::vector<std::uint8_t> inside;  ///< i fastest, then j, then k
};

struct LabelImage {
  std::array<int, 3> size{};
  std::array<double, 3> origin{};   ///< voxel (0, 0, 0), mm, LPS (ITK's physical space)
  std::array<double, 9> axes{};     ///< row-major 3x3: column a is one step along voxel axis a, mm, LPS
  std::vector<CroppedLabel> labels;  ///< one per requested value, in order
  std::vector<std::int64_t> values_seen;  ///< the first 16 distinct values, for an error message
  bool more_values = false;
};

/// Registers ITK's readers and writers of the three formats lungar reads (no other ITK format is linked); once per
/// process, from any thread. read_label_image calls it; so do the tests that write label maps.
void register_formats();

/// Reads `path` (NRRD, NIfTI, MetaImage) and crops every value in `values`. Errors name the file and the field.
lungar::Result<LabelImage> read_label_image(const std::string& path, const std::vector<std::int64_t>& values);

}  // namespace lungar::sim::itk_io
