/// @file label_map_io.cpp
/// @brief --label parsing, and the ITK reader's cropped labels turned into sim's voxel masks.
#include "sim/bake_tool/label_map_io.h"

#include <algorithm>
#include <array>
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

namespace {

using Index3 = std::array<int, 3>;

bool inside_crop(const itk_io::CroppedLabel& c, const Index3& whole) {
  Index3 q;
  for (int a = 0; a < 3; ++a) {
    q[a] = whole[a] - c.lo[a];
    if (q[a] < 0 || q[a] >= c.size[a]) return false;
  }
  return c.inside[(static_cast<std::size_t>(q[2]) * c.size[1] + q[1]) * c.size[0] + q[0]] != 0;
}

/// Calls f(whole index) for every voxel of the crop that holds its label.
template <class F>
void each_voxel(const itk_io::CroppedLabel& c, F f) {
  std::size_t v = 0;
  for (int k = 0; k < c.size[2]; ++k)
    for (int j = 0; j < c.size[1]; ++j)
      for (int i = 0; i < c.size[0]; ++i, ++v)
        if (c.inside[v]) f(Index3{c.lo[0] + i, c.lo[1] + j, c.lo[2] + k});
}

/// `lesion`'s voxels added to `lung`'s crop, grown to hold both.
void merge_into(itk_io::CroppedLabel& lung, const itk_io::CroppedLabel& lesion) {
  itk_io::CroppedLabel both;
  both.value = lung.value;
  both.voxels = lung.voxels;
  for (int a = 0; a < 3; ++a) {
    both.lo[a] = std::min(lung.lo[a], lesion.lo[a]);
    both.size[a] = std::max(lung.lo[a] + lung.size[a], lesion.lo[a] + lesion.size[a]) - both.lo[a];
  }
  both.inside.assign(static_cast<std::size_t>(both.size[0]) * both.size[1] * both.size[2], 0);
  auto mark = [&](const Index3& w) {
    both.inside[(static_cast<std::size_t>(w[2] - both.lo[2]) * both.size[1] + (w[1] - both.lo[1])) * both.size[0] +
                (w[0] - both.lo[0])] = 1;
  };
  each_voxel(lung, mark);
  each_voxel(lesion, mark);
  lung = std::move(both);
}

}  // namespace

lungar::Result<std::vector<LabelMask>> read_label_masks(const std::string& path, const std::vector<LabelRequest>& labels) {
  std::vector<LabelLesion> none;
  return read_label_masks(path, labels, {}, none);
}

lungar::Result<std::vector<LabelMask>> read_label_masks(const std::string& path,
                                                        const std::vector<LabelRequest>& labels,
                                                        const std::vector<LabelRequest>& lesion_labels,
                                                        std::vector<LabelLesion>& lesions) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail(path + ": cannot open: " + (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  if (labels.empty()) return fail("--label: expected at least one NAME=VALUE (e.g. --label right=2 --label left=3)");
  if (lungar::Status intact = check_compressed_voxels(path); !intact) return fail(intact.error());
  std::vector<std::int64_t> values;
  for (const LabelRequest& l : labels) values.push_back(l.value);
  for (const LabelRequest& l : lesion_labels) values.push_back(l.value);
  lungar::Result<itk_io::LabelImage> image = itk_io::read_label_image(path, values);
  if (!image) return fail(image.error());
  VoxelGrid whole;
  whole.size = image->size;
  whole.origin = Eigen::Vector3d(image->origin[0], image->origin[1], image->origin[2]);
  whole.axes = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(image->axes.data());
  std::string seen;
  for (std::int64_t v : image->values_seen) seen += (seen.empty() ? "" : ", ") + std::to_string(v);
  if (image->more_values) seen += ", ...";
  for (std::size_t l = 0; l < labels.size(); ++l)
    if (image->labels[l].voxels == 0)
      return fail(path + ": --label " + labels[l].name + "=" + std::to_string(labels[l].value) +
                  ": no voxel has this value (the map holds " + seen + "); expected the label of a lung");
  // Each lesion into the lung that touches most of its voxels' faces, before the lungs' crops become masks.
  lesions.clear();
  for (std::size_t k = 0; k < lesion_labels.size(); ++k) {
    const LabelRequest& req = lesion_labels[k];
    const itk_io::CroppedLabel& c = image->labels[labels.size() + k];
    const std::string who = path + ": --lesion " + req.name + "=" + std::to_string(req.value);
    if (c.voxels == 0)
      return fail(who + ": no voxel has this value (the map holds " + seen + "); expected the label of a lesion");
    std::vector<std::int64_t> touches(labels.size(), 0);
    LabelLesion lesion{req, 0, Eigen::Vector3d::Zero(), 0, c.voxels};
    each_voxel(c, [&](const Index3& w) {
      lesion.centroid_mm += whole.point(Eigen::Vector3d(w[0], w[1], w[2]));
      for (int a = 0; a < 3; ++a)
        for (int s : {-1, 1}) {
          Index3 n = w;
          n[a] += s;
          for (std::size_t l = 0; l < labels.size(); ++l) touches[l] += inside_crop(image->labels[l], n);
        }
    });
    lesion.centroid_mm /= static_cast<double>(c.voxels);
    lesion.volume_ml = static_cast<double>(c.voxels) * whole.voxel_volume_mm3() / 1000.0;
    const auto most = std::max_element(touches.begin(), touches.end());
    if (*most == 0) return fail(who + ": no lung's voxels touch it; expected a lesion inside a lung (--label)");
    lesion.lung = static_cast<std::size_t>(most - touches.begin());
    merge_into(image->labels[lesion.lung], c);
    lesions.push_back(lesion);
  }
  std::vector<LabelMask> out;
  for (std::size_t l = 0; l < labels.size(); ++l) {
    itk_io::CroppedLabel& c = image->labels[l];
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
