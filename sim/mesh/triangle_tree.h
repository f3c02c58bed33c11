/// @file triangle_tree.h
/// @brief A bounding-box tree over a surface's triangles and the nearest point of the surface to a point: the
///        Hausdorff distance of the bake report (sim/mesh/surface_distance.h) and the boundary values of the
///        interior displacement (sim/motion/interior_displacement.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// The point of a surface nearest to a query point.
struct NearestPoint {
  std::uint32_t triangle = 0;         ///< index into the mesh's triangles
  std::array<double, 3> weights{};    ///< barycentric weights of the triangle's three vertices (sum 1, each >= 0)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double distance2 = 0;               ///< squared distance from the query, mm^2
};

/// A median-split bounding-box tree over a mesh's triangles, for branch-and-bound nearest-point queries. Holds a
/// reference to the mesh, which must outlive it.
class TriangleTree {
 public:
  explicit TriangleTree(const TriMesh& mesh);

  /// The nearest point of the surface to p (exact point-to-triangle distances); the mesh must have a triangle.
  NearestPoint nearest(const Eigen::Vector3d& p) const;

  /// Squared distance from p to the nearest triangle (infinity for a mesh without triangles).
  double nearest_d2(const Eigen::Vector3d& p) const;

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    std::uint32_t first = 0, count = 0;  ///< leaf: triangles [first, first + count) of order_; inner: children
  };
  void build(std::uint32_t slot, std::size_t lo, std::size_t hi);

  const TriMesh& m_;
  std::vector<std::uint32_t> order_;
  std::vector<Eigen::Vector3d> centre_;
  std::vector<Node> nodes_;
};

}  // namespace lungar::sim
