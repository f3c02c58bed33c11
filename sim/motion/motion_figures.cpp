/// @file motion_figures.cpp
/// @brief Tertiles by rest position, means of |d| in each, and the faces' shares.
#include "sim/motion/motion_figures.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "sim/deform/deform_eq7.h"
#include "sim/force/breath_share.h"
#include "sim/force/force_sh.h"

namespace lungar::sim {
namespace {

/// Mean |d| over the top third of the points by rest coordinate `axis`, over the bottom third.
double tertile_ratio(std::span<const float> rest, const std::vector<double>& magnitude, int axis) {
  const std::size_t n = magnitude.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
    return rest[3 * std::size_t{i} + axis] < rest[3 * std::size_t{j} + axis];
  });
  const std::size_t third = n / 3;
  if (third == 0) return 0;
  double low = 0, high = 0;
  for (std::size_t k = 0; k < third; ++k) {
    low += magnitude[order[k]];
    high += magnitude[order[n - 1 - k]];
  }
  return low > 0 ? high / low : 0.0;
}

/// The figures without faces, and each point's |d| in `magnitude`.
MotionFigures figures_and_magnitudes(std::span<const float> rest, std::span<const float> d,
                                     std::vector<double>& magnitude) {
  const std::size_t n = rest.size() / 3;
  MotionFigures f;
  magnitude.assign(n, 0.0);
  double sum = 0, sum_z = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = d[3 * i], y = d[3 * i + 1], z = d[3 * i + 2];
    magnitude[i] = std::sqrt(x * x + y * y + z * z);
    sum += magnitude[i];
    sum_z += std::abs(z);
    f.max_displacement_mm = std::max(f.max_displacement_mm, magnitude[i]);
  }
  if (n == 0 || !(sum > 0)) return f;
  f.si_share = sum_z / sum;
  f.mean_displacement_mm = sum / static_cast<double>(n);
  f.apex_base_ratio = tertile_ratio(rest, magnitude, 2);  // +z superior: top over bottom
  f.dorsal_ventral_ratio = tertile_ratio(rest, magnitude, 1);  // +y posterior: back over front
  return f;
}

}  // namespace

MotionFigures point_motion_figures(std::span<const float> rest, std::span<const float> d) {
  std::vector<double> magnitude;
  return figures_and_magnitudes(rest, d, magnitude);
}

MotionFigures motion_figures(const BakedAsset& a, std::span<const float> d, const std::vector<SurfaceRegion>& regions) {
  const std::size_t n = a.vertex_count();
  std::vector<double> magnitude;
  MotionFigures f = figures_and_magnitudes(std::span<const float>(a.positions.data(), 3 * n), d, magnitude);
  if (n == 0 || !(f.mean_displacement_mm > 0) || regions.size() != n) return f;
  std::array<double, kSurfaceRegionCount> area{}, volume{}, moved{};
  std::array<std::size_t, kSurfaceRegionCount> count{};
  double area_all = 0, volume_all = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(regions[i]);
    const double swept = a.areas[i] * (d[3 * i] * a.normals[3 * i] + d[3 * i + 1] * a.normals[3 * i + 1] +
                                       d[3 * i + 2] * a.normals[3 * i + 2]);
    area[r] += a.areas[i];
    volume[r] += swept;
    moved[r] += magnitude[i];
    ++count[r];
    area_all += a.areas[i];
    volume_all += swept;
  }
  for (std::size_t r = 0; r < kSurfaceRegionCount; ++r) {
    f.regions[r].area_mm2 = area[r];
    f.regions[r].area_share = area_all > 0 ? area[r] / area_all : 0;
    f.regions[r].volume_share = volume_all != 0 ? volume[r] / volume_all : 0;
    f.regions[r].mean_displacement_mm = count[r] > 0 ? moved[r] / static_cast<double>(count[r]) : 0;
  }
  return f;
}

std::vector<float> displacement_vectors(const BakedAsset& a, const PatientState& patient, const Eigen::Vector3d& g,
                                        double delta_volume_ml) {
  const std::uint32_t c = a.coefficients();
  const std::size_t n = a.vertex_count();
  std::vector<float> force(a.lungs.size() * c), scalar(n), out(3 * n);
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    force_sh_exact(a, a.lungs[l], patient.lungs.at(l), g, force.data() + l * c);
  displacement_eq7(a, force, scalar);
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    const BakedLung& lung = a.lungs[l];
    const double scale = delta_volume_ml * breath_share(a, patient, l, g);
    const std::array<float, 4> w = linear_weights(a, patient.lungs[l], g);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      for (int k = 0; k < 3; ++k)
        out[3 * i + k] = static_cast<float>(scale * scalar[i] * a.directions[3 * i + k]);
      add_off_axis(a, i, w, static_cast<float>(scale), &out[3 * i]);
    }
  }
  return out;
}

}  // namespace lungar::sim
