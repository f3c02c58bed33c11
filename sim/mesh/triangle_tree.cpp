/// @file triangle_tree.cpp
/// @brief The tree's median split along the widest axis of the triangles' centres, and the nearest-point search
///        that visits the nearer child first and prunes boxes farther than the best point found.
#include "sim/mesh/triangle_tree.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace lungar::sim {
namespace {

/// The point of triangle (a, b, c) nearest to p, as barycentric weights (Ericson, Real-Time Collision Detection,
/// 5.1.5: the Voronoi regions of the vertices, then of the edges, then the face).
std::array<double, 3> nearest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

}  // namespace

TriangleTree::TriangleTree(const TriMesh& m) : m_(m), order_(m.triangles.size()) {
  std::iota(order_.begin(), order_.end(), 0u);
  centre_.reserve(m.triangles.size());
  for (const Triangle& t : m.triangles) centre_.push_back((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3);
  if (order_.empty()) return;
  nodes_.reserve(2 * order_.size() / 4 + 2);
  nodes_.emplace_back();
  build(0, 0, order_.size());
}

NearestPoint TriangleTree::nearest(const Eigen::Vector3d& p) const {
  NearestPoint best;
  best.distance2 = std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty() && !nodes_.empty()) {
    const Node& n = nodes_[stack.back()];
    stack.pop_back();
    if (n.box.squaredExteriorDistance(p) >= best.distance2) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const Triangle& t = m_.triangles[order_[i]];
        const Eigen::Vector3d &a = m_.positions[t[0]], &b = m_.positions[t[1]], &c = m_.positions[t[2]];
        const std::array<double, 3> w = nearest_on_triangle(p, a, b, c);
        const Eigen::Vector3d q = w[0] * a + w[1] * b + w[2] * c;
        const double d2 = (p - q).squaredNorm();
        if (d2 < best.distance2) best = {order_[i], w, q, d2};
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

double TriangleTree::nearest_d2(const Eigen::Vector3d& p) const { return nearest(p).distance2; }

/// Fills node `slot` with triangles [lo, hi) of order_, splitting at the median along the widest axis.
void TriangleTree::build(std::uint32_t slot, std::size_t lo, std::size_t hi) {
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

}  // namespace lungar::sim
