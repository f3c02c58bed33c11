/// @file surface_distance.cpp
/// @brief A median-split bounding-box tree over triangles and a branch-and-bound nearest-triangle query.
#include "sim/mesh/surface_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "sim/parallel/parallel_for.h"

namespace lungar::sim {
namespace {

/// Squared distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double point_triangle_d2(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).squaredNorm();
}

class TriangleTree {
 public:
  explicit TriangleTree(const TriMesh& m) : m_(m), order_(m.triangles.size()) {
    std::iota(order_.begin(), order_.end(), 0u);
    centre_.reserve(m.triangles.size());
    for (const Triangle& t : m.triangles) centre_.push_back((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3);
    if (order_.empty()) return;
    nodes_.reserve(2 * order_.size() / 4 + 2);
    nodes_.emplace_back();
    build(0, 0, order_.size());
  }

  /// Squared distance from p to the nearest triangle.
  double nearest_d2(const Eigen::Vector3d& p) const {
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty() && !nodes_.empty()) {
      const Node& n = nodes_[stack.back()];
      stack.pop_back();
      if (n.box.squaredExteriorDistance(p) >= best) continue;
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
          const Triangle& t = m_.triangles[order_[i]];
          best = std::min(best, point_triangle_d2(p, m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]));
        }
        continue;
      }
      // Nearer child last, so it is searched first.
      const std::uint32_t l = n.first, r = n.first + 1;
      const bool left_nearer = nodes_[l].box.squaredExteriorDistance(p) < nodes_[r].box.squaredExteriorDistance(p);
      stack.push_back(left_nearer ? r : l);
      stack.push_back(left_nearer ? l : r);
    }
    return best;
  }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    std::uint32_t first = 0, count = 0;  ///< leaf: triangles [first, first + count) of order_; inner: children
  };

  /// Fills node `slot` with triangles [lo, hi) of order_, splitting at the median along the widest axis.
  void build(std::uint32_t slot, std::size_t lo, std::size_t hi) {
    Eigen::AlignedBox3d box, centres;
    for (std::size_t i = lo; i < hi; ++i) {
      const Triangle& t = m_.triangles[order_[i]];
      for (std::uint32_t v : t) box.extend(m_.positions[v]);
      centres.extend(centre_[order_[i]]);
    }
    nodes_[slot].box = box;
    if (hi - lo <= 8) {
      nodes_[slot].first = static_cast<std::uint32_t>(lo);
      nodes_[slot].count = static_cast<std::uint32_t>(hi - lo);
      return;
    }
    int axis = 0;
    centres.sizes().maxCoeff(&axis);
    const std::size_t mid = (lo + hi) / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(lo), order_.begin() + static_cast<std::ptrdiff_t>(mid),
                     order_.begin() + static_cast<std::ptrdiff_t>(hi),
                     [&](std::uint32_t x, std::uint32_t y) { return centre_[x][axis] < centre_[y][axis]; });
    const auto left = static_cast<std::uint32_t>(nodes_.size());  // the children are a pair of slots
    nodes_.resize(nodes_.size() + 2);
    nodes_[slot].first = left;
    build(left, lo, mid);
    build(left + 1, mid, hi);
  }

  const TriMesh& m_;
  std::vector<std::uint32_t> order_;
  std::vector<Eigen::Vector3d> centre_;
  std::vector<Node> nodes_;
};

/// The largest distance from a vertex of `from` to the surface `to`.
double one_sided(const TriMesh& from, const TriMesh& to, const Workers& workers) {
  const TriangleTree tree(to);
  std::vector<double> d2(from.positions.size(), 0.0);
  parallel_for(d2.size(), workers, [&](std::size_t i) { d2[i] = tree.nearest_d2(from.positions[i]); });
  return d2.empty() ? 0.0 : std::sqrt(*std::max_element(d2.begin(), d2.end()));
}

}  // namespace

double hausdorff_mm(const TriMesh& a, const TriMesh& b, const Workers& workers) {
  return std::max(one_sided(a, b, workers), one_sided(b, a, workers));
}

}  // namespace lungar::sim
