/// @file label_map_io.cpp
/// @brief --label parsing, and the ITK reader's cropped labels turned into sim's voxel masks.
#include "sim/bake_tool/label_map_io.h"

#include <charconv>
#include <filesystem>

#include "sim/bake_tool/compressed_check.h"
#include "sim/bake_tool/itk_label_reader.h"

namespace lungar::sim {

lungar::Result<LabelRequest> parse_label_request(const std::string& text) {
  const auto eq = text.find('=');
  LabelRequest r;
  r.name = text.substr(0, eq == std::string::npos ? 0 : eq);
  const std::string value = eq == std::string::npos ? "" : text.substr(eq + 1);
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), r.value);
  if (r.name.empty() || value.empty() || ec != std::errc() || end != value.data() + value.size())
    return fail("--label: expected NAME=VALUE with an integer VALUE (e.g. right=2), got '" + text + "'");
  return r;
}

lungar::Result<std::vector<LabelMask>> read_label_masks(const std::string& path, const std::vector<LabelRequest>& labels) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail(path + ": cannot open: " + (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  if (labels.empty()) return fail("--label: expected at least one NAME=VALUE (e.g. --label right=2 --label left=3)");
  if (lungar::Status intact = check_compressed_voxels(path); !intact) return fail(intact.error());
  std::vector<std::int64_t> values;
  for (const LabelRequest& l : labels) values.push_back(l.value);
  lungar::Result<itk_io::LabelImage> image = itk_io::read_label_image(path, values);
  if (!image) return fail(image.error());
  VoxelGrid whole;
  whole.size = image->size;
  whole.origin = Eigen::Vector3d(image->origin[0], image->origin[1], image->origin[2]);
  whole.axes = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(image->axes.data());
  std::vector<LabelMask> out;
  for (std::size_t l = 0; l < labels.size(); ++l) {
    itk_io::CroppedLabel& c = image->labels[l];
    if (c.voxels == 0) {
      std::string seen;
      for (std::int64_t v : image->values_seen) seen += (seen.empty() ? "" : ", ") + std::to_string(v);
      return fail(path + ": --label " + labels[l].name + "=" + std::to_string(labels[l].value) +
                  ": no voxel has this value (the map holds " + seen + (image->more_values ? ", ..." : "") +
                  "); expected the label of a lung");
    }
    LabelMask m{labels[l], {}, c.voxels};
    m.mask.grid.size = c.size;
    m.mask.grid.axes = whole.axes;
    m.mask.grid.origin = whole.point(Eigen::Vector3d(c.lo[0], c.lo[1], c.lo[2]));
    m.mask.inside = std::move(c.inside);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace lungar::sim
