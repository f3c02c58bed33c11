/// @file lod_order.cpp
/// @brief Level-of-detail vertex order by progressive Poisson-disk selection.
///
/// Level k keeps a maximal set of vertices no two of which lie closer than r_k, given the levels before it; r_k
/// shrinks by 2^(1/4) a level, so each level adds about 41 % more points. Maximality is what render/ relies on:
/// when level k is complete every vertex lies within r_k of a chosen one, and a prefix that stops part-way
/// through level k+1 is never sparser than level k. An earlier grid-cell order (one random vertex per occupied
/// cell, cells halving) quadrupled the count per level and left holes unless the renderer drew about 6 times the
/// surface; this order is hole-free at about 3 (render/level_of_detail.h).
#include "sim/mesh/lod_order.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lungar::sim {

namespace {

/// Chosen vertices hashed by grid cell of the current radius: an open-addressed table of cell -> first vertex,
/// the rest of the cell chained through `next`. Rebuilt each level (the cell size changes with the radius).
class CellGrid {
 public:
  void rebuild(double cell, const Eigen::Vector3d& origin, const std::vector<Eigen::Vector3d>& positions,
               const std::vector<std::uint32_t>& chosen) {
    cell_ = cell;
    origin_ = origin;
    std::size_t size = 64;
    while (size < 2 * chosen.size() + 16) size *= 2;
    keys_.assign(size, kEmpty);
    heads_.assign(size, kNone);
    next_.resize(positions.size());
    used_ = 0;
    for (std::uint32_t v : chosen) insert(v, positions[v]);
  }

  void insert(std::uint32_t v, const Eigen::Vector3d& p) {
    const std::uint64_t key = key_of(cell_of(p));
    std::size_t slot = find(key);
    if (keys_[slot] == kEmpty) {
      keys_[slot] = key;
      heads_[slot] = kNone;
      if (++used_ * 2 > keys_.size()) {
        grow();
        slot = find(key);
      }
    }
    next_[v] = heads_[slot];
    heads_[slot] = v;
  }

  /// The distance from `p` to the nearest chosen vertex within one cell size, or infinity.
  double nearest(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& positions) const {
    const Eigen::Vector3i c = cell_of(p);
    double best2 = std::numeric_limits<double>::infinity();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const std::size_t slot = find(key_of(c + Eigen::Vector3i(dx, dy, dz)));
          if (keys_[slot] == kEmpty) continue;
          for (std::uint32_t v = heads_[slot]; v != kNone; v = next_[v]) {
            best2 = std::min(best2, (positions[v] - p).squaredNorm());
          }
        }
    return std::sqrt(best2);
  }

 private:
  static constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = (p - origin_) / cell_;
    return {static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())),
            static_cast<int>(std::floor(q.z()))};
  }
  static std::uint64_t key_of(const Eigen::Vector3i& c) {
    // 21 bits a coordinate, offset so that the -1 neighbours of cell 0 stay distinct.
    const auto u = [](int x) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(x) + (1 << 20)) & 0x1FFFFF; };
    return (u(c.x()) << 42) | (u(c.y()) << 21) | u(c.z());
  }
  std::size_t find(std::uint64_t key) const {
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask;
    while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask;
    return slot;
  }
  void grow() {
    std::vector<std::uint64_t> keys = std::move(keys_);
    std::vector<std::uint32_t> heads = std::move(heads_);
    keys_.assign(keys.size() * 2, kEmpty);
    heads_.assign(keys.size() * 2, kNone);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] == kEmpty) continue;
      const std::size_t slot = find(keys[i]);
      keys_[slot] = keys[i];
      heads_[slot] = heads[i];
    }
  }

  double cell_ = 1;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> heads_;
  std::vector<std::uint32_t> next_;
  std::size_t used_ = 0;
};

}  // namespace

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
  // Visit vertices in a scrambled but fixed order, so that a level's picks do not follow the input's scan lines
  // and a level cut short is spread over the whole surface.
  std::vector<std::uint32_t> scan(n);
  for (std::uint32_t i = 0; i < n; ++i) scan[i] = i;
  std::sort(scan.begin(), scan.end(), [](std::uint32_t a, std::uint32_t b) {
    return (a * 2654435761u) < (b * 2654435761u) || ((a * 2654435761u) == (b * 2654435761u) && a < b);
  });
  // known[v]: the distance to the nearest chosen vertex found so far, an upper bound of the true one. A vertex
  // closer than the level's radius to any chosen vertex is rejected without a search; most are, after a few levels.
  std::vector<double> known(n, std::numeric_limits<double>::infinity());
  std::vector<char> taken(n, 0);
  CellGrid grid;
  const double shrink = std::pow(2.0, -0.25);
  for (double r = 0.5 * extent; order.size() < n; r *= shrink) {
    grid.rebuild(r, lo, positions, order);
    for (std::uint32_t v : scan) {
      if (taken[v]) continue;
      if (known[v] < r) continue;
      known[v] = std::min(known[v], grid.nearest(positions[v], positions));
      if (known[v] < r) continue;
      taken[v] = 1;
      known[v] = 0;
      order.push_back(v);
      grid.insert(v, positions[v]);
    }
    if (r < 1e-9 * extent) break;  // only coincident vertices are left: they go last
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
