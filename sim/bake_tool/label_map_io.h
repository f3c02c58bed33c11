/// @file label_map_io.h
/// @brief CT label maps in through ITK (NRRD, NIfTI .nii / .nii.gz, MetaImage .mha / .mhd), for lungar-bake only:
///        one mask per asked label, on the map's own voxel grid placed in LPS millimetres.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "sim/voxel/voxel_grid.h"

namespace lungar::sim {

/// A lung asked for by `--label NAME=VALUE`.
struct LabelRequest {
  std::string name;
  std::int64_t value = 0;
};

/// "NAME=VALUE" -> request; the error names the option and what was expected.
lungar::Result<LabelRequest> parse_label_request(const std::string& text);

/// One lung's voxels from the map: the mask cropped to the label's bounding box.
struct LabelMask {
  LabelRequest label;
  VoxelMask mask;
  std::int64_t voxels = 0;  ///< voxels with the label's value
};

/// Reads the map at `path` and cuts one mask per request. ITK's physical space is DICOM LPS whatever the file
/// stores (NIfTI's RAS qform/sform are turned round by ITK), so the grids' origins and axes, from the file's
/// origin, spacing and direction cosines, are LPS millimetres. Fails with one line naming the file and the field:
/// not a readable label map, not 3-D, not integer, a singular voxel frame, unreadable voxels (a corrupt gzip
/// stream), a label with no voxel.
lungar::Result<std::vector<LabelMask>> read_label_masks(const std::string& path, const std::vector<LabelRequest>& labels);

/// A lesion asked for by `lungar-bake --lesion NAME=VALUE`: a label of the same map (a segmented tumour).
struct LabelLesion {
  LabelRequest label;
  std::size_t lung = 0;                                   ///< index into the masks: the lung around it
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();  ///< LPS
  double volume_ml = 0;
  std::int64_t voxels = 0;
};

/// The lungs' masks as above, with lesions: each lesion label's voxels join the mask of the lung whose voxels touch
/// most of its faces, so that the lung's surface goes round the tumour instead of leaving a cavity where the
/// segmentation cut it out; its centroid and volume are measured on its voxels. A lesion label with no voxel, or
/// that no lung touches, is one line naming it.
lungar::Result<std::vector<LabelMask>> read_label_masks(const std::string& path,
                                                        const std::vector<LabelRequest>& labels,
                                                        const std::vector<LabelRequest>& lesion_labels,
                                                        std::vector<LabelLesion>& lesions);

}  // namespace lungar::sim
