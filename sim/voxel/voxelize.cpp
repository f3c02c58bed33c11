/// @file voxelize.cpp
/// @brief Triangles binned by their (y, z) footprint; each grid row's ray crossings sorted and filled by parity.
#include "sim/voxel/voxelize.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace lungar::sim {

double voxel_step_for(const TriMesh& mesh, double max_voxels) {
  double length = 0;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) length += (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm();
  const double mean = mesh.triangles.empty() ? 1.0 : length / (3.0 * static_cast<double>(mesh.triangles.size()));
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : mesh.positions) box.extend(p);
  return std::max(mean, std::cbrt(box.volume() / max_voxels));
}

VoxelMask voxelize(const TriMesh& mesh, double h) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : mesh.positions) box.extend(p);
  VoxelMask m;
  m.grid.axes = Eigen::Matrix3d::Identity() * h;
  // Two empty voxels of margin; the grid is shifted by an odd fraction of a step so that rays rarely graze an
  // edge or a vertex of a surface that was itself cut from a grid.
  m.grid.origin = box.min() - Eigen::Vector3d(2.0 * h, 1.99 * h, 2.03 * h);
  for (int a = 0; a < 3; ++a) m.grid.size[a] = static_cast<int>(std::ceil(box.sizes()[a] / h)) + 5;
  m.inside.assign(static_cast<std::size_t>(m.grid.count()), 0);
  const int ny = m.grid.size[1], nz = m.grid.size[2];
  std::vector<std::vector<std::uint32_t>> bin(static_cast<std::size_t>(ny) * nz);  // triangles over each (j, k) row
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    Eigen::AlignedBox3d tb;
    for (std::uint32_t v : mesh.triangles[t]) tb.extend(mesh.positions[v]);
    const auto lo = ((tb.min() - m.grid.origin) / h).array().ceil().cast<int>();
    const auto hi = ((tb.max() - m.grid.origin) / h).array().floor().cast<int>();
    for (int k = std::max(lo[2], 0); k <= std::min(hi[2], nz - 1); ++k)
      for (int j = std::max(lo[1], 0); j <= std::min(hi[1], ny - 1); ++j) bin[static_cast<std::size_t>(k) * ny + j].push_back(t);
  }
  std::vector<double> cross;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      const double y = m.grid.origin.y() + h * j, z = m.grid.origin.z() + h * k;
      cross.clear();
      for (std::uint32_t t : bin[static_cast<std::size_t>(k) * ny + j])
        if (const std::optional<double> x = x_crossing(mesh, t, y, z)) cross.push_back(*x);
      std::sort(cross.begin(), cross.end());
      for (std::size_t c = 0; c + 1 < cross.size(); c += 2) {
        const int from = static_cast<int>(std::ceil((cross[c] - m.grid.origin.x()) / h));
        const int to = static_cast<int>(std::floor((cross[c + 1] - m.grid.origin.x()) / h));
        for (int i = std::max(from, 0); i <= std::min(to, m.grid.size[0] - 1); ++i)
          m.inside[static_cast<std::size_t>(m.grid.index(i, j, k))] = 1;
      }
    }
  return m;
}

}  // namespace lungar::sim
