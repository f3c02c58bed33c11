/// @file compressed_check.h
/// @brief Whether a label map's compressed voxels are intact, before ITK reads them.
///
/// ITK's NRRD reader stops inflating once it holds the voxels it needs, so a gzip stream damaged in its middle
/// can come back as wrong voxels without an error (measured: 64 bytes scribbled over a gzip NRRD were baked).
/// This inflates the whole stream and lets zlib check what the format carries: the gzip trailer's CRC-32 and
/// length (NRRD "encoding: gzip", .nii.gz) or the zlib stream's Adler-32 (MetaImage "CompressedData = True").
#pragma once

#include <string>

#include "config/base/result.h"

namespace lungar::sim {

/// ok() when `path` holds no compressed voxels in the file itself (raw data, or a detached data file) or when
/// they inflate to their end with a matching checksum; else one line naming the file and what is wrong.
lungar::Status check_compressed_voxels(const std::string& path);

}  // namespace lungar::sim
