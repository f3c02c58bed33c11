/// @file label_map_files_support.h
/// @brief Label-map files for the tests, written through ITK (kept out of every file that sees sim's Eigen: ITK
///        carries its own copy under the same include guards, see sim/bake_tool/itk_label_reader.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lungar::sim::test {

/// A 3-D label volume: labels[i + n0 * (j + n1 * k)], voxel (i, j, k) at origin + direction * (spacing o ijk), LPS.
struct LabelVolume {
  std::array<int, 3> size{};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<double, 3> origin{};
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< row-major, ITK's (LPS)
  std::vector<std::uint16_t> labels;
};

/// Writes `v` in the format the extension names (.nrrd, .nii, .nii.gz, .mha); false on failure.
bool write_label_volume(const std::string& path, const LabelVolume& v);

/// The same voxels stored the other way round along i and j: a NIfTI written from it is in RAS order (its
/// qform/sform are the identity in RAS), while every voxel keeps its place in the patient.
LabelVolume stored_in_ras_order(const LabelVolume& v);

/// Reads a label map and keeps every `step`-th voxel along each axis (a small copy of a large map).
bool read_subsampled(const std::string& path, int step, LabelVolume& out);

/// Writes a 2-D image (for the wrong-dimension refusal).
bool write_2d_image(const std::string& path);

}  // namespace lungar::sim::test
