/// @file lod_order.cpp
/// @brief Level-of-detail vertex order by hierarchical grid occupancy.
#include "sim/mesh/lod_order.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace lungar::sim {

std::vector<std::uint32_t> lod_order(const std::vector<Eigen::Vector3d>& positions) {
  const auto n = static_cast<std::uint32_t>(positions.size());
  std::vector<std::uint32_t> order;
  order.reserve(n);
  if (n == 0) return order;
  Eigen::Vector3d lo = positions[0], hi = positions[0];
  for (const auto& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = std::max((hi - lo).maxCoeff(), 1e-9);
  // Visit vertices in a scrambled but fixed order, so that a level's picks are spread over its cells rather
  // than following the input's scan lines.
  std::vector<std::uint32_t> scan(n);
  for (std::uint32_t i = 0; i < n; ++i) scan[i] = i;
  std::sort(scan.begin(), scan.end(), [](std::uint32_t a, std::uint32_t b) {
    return (a * 2654435761u) < (b * 2654435761u) || ((a * 2654435761u) == (b * 2654435761u) && a < b);
  });
  std::vector<char> taken(n, 0);
  std::unordered_set<std::uint64_t> occupied;
  for (int level = 1; level <= 20 && order.size() < n; ++level) {
    const double cell = extent / static_cast<double>(1u << level);
    auto key = [&](std::uint32_t v) {
      const Eigen::Vector3d q = (positions[v] - lo) / cell;
      const auto ix = static_cast<std::uint64_t>(q.x()), iy = static_cast<std::uint64_t>(q.y()),
                 iz = static_cast<std::uint64_t>(q.z());
      return (ix << 42) | (iy << 21) | iz;
    };
    occupied.clear();
    occupied.reserve(order.size() * 2 + 16);
    for (std::uint32_t v : order) occupied.insert(key(v));
    for (std::uint32_t v : scan)
      if (!taken[v] && occupied.insert(key(v)).second) {
        taken[v] = 1;
        order.push_back(v);
      }
  }
  for (std::uint32_t v : scan)
    if (!taken[v]) order.push_back(v);
  return order;
}

void reorder_vertices(TriMesh& mesh, const std::vector<std::uint32_t>& order) {
  std::vector<std::uint32_t> new_index(order.size());
  std::vector<Eigen::Vector3d> positions(order.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    new_index[order[i]] = i;
    positions[i] = mesh.positions[order[i]];
  }
  mesh.positions = std::move(positions);
  for (Triangle& t : mesh.triangles)
    for (std::uint32_t& v : t) v = new_index[v];
}

}  // namespace lungar::sim
