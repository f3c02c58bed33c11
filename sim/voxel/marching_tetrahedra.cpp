/// @file marching_tetrahedra.cpp
/// @brief Six tetrahedra a cube along its main diagonal; one vertex per crossed edge, shared through a hash map.
#include "sim/voxel/marching_tetrahedra.h"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "sim/voxel/freudenthal.h"

namespace lungar::sim {
namespace {

/// The 6 tetrahedra of the unit cube: corner 0, then one axis step at a time in each order of the axes.
constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

class Extractor {
 public:
  Extractor(const VoxelGrid& grid, const std::vector<float>& field) : g_(grid), f_(field) {
    for (int d = 0; d < 7; ++d) {
      const auto& e = kFreudenthalEdges[d];
      direction_[e[0] + 2 * e[1] + 4 * e[2]] = d;
    }
    vertex_of_edge_.reserve(static_cast<std::size_t>(g_.count() / 16));
  }

  void cube(int i, int j, int k) {
    std::array<std::array<int, 3>, 4> corner{};
    for (const auto& order : kAxisOrders) {
      corner[0] = {i, j, k};
      for (int s = 0; s < 3; ++s) {
        corner[s + 1] = corner[s];
        ++corner[s + 1][order[s]];
      }
      tetrahedron(corner);
    }
  }

  TriMesh take() {
    if (g_.axes.determinant() < 0)  // a mirrored voxel frame turns every triangle inside out
      for (Triangle& t : mesh_.triangles) std::swap(t[1], t[2]);
    for (Eigen::Vector3d& p : mesh_.positions) p = g_.point(p);
    return std::move(mesh_);
  }

 private:
  float value(const std::array<int, 3>& c) const { return f_[static_cast<std::size_t>(g_.index(c[0], c[1], c[2]))]; }

  /// The vertex on the edge a -> b (a before b along the cube's diagonal chain), in index coordinates for now.
  std::uint32_t edge_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
    const int d = direction_[(b[0] - a[0]) + 2 * (b[1] - a[1]) + 4 * (b[2] - a[2])];
    const std::uint64_t key = static_cast<std::uint64_t>(g_.index(a[0], a[1], a[2])) * 7 + static_cast<std::uint64_t>(d);
    auto [it, fresh] = vertex_of_edge_.try_emplace(key, static_cast<std::uint32_t>(mesh_.positions.size()));
    if (fresh) {
      const double fa = value(a), fb = value(b);
      const double t = std::clamp(fa / (fa - fb), 0.05, 0.95);
      const Eigen::Vector3d pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]);
      mesh_.positions.push_back(pa + t * (pb - pa));
    }
    return it->second;
  }

  /// Adds (p, q, r) facing from `in` towards `out` (centroids of the inside and outside corners).
  void triangle(std::uint32_t p, std::uint32_t q, std::uint32_t r, const Eigen::Vector3d& in, const Eigen::Vector3d& out) {
    const auto& x = mesh_.positions;
    if ((x[q] - x[p]).cross(x[r] - x[p]).dot(out - in) < 0) std::swap(q, r);
    mesh_.triangles.push_back({p, q, r});
  }

  void tetrahedron(const std::array<std::array<int, 3>, 4>& c) {
    std::array<int, 4> inside{}, outside{};
    int n_in = 0, n_out = 0;
    for (int v = 0; v < 4; ++v) (value(c[v]) > 0 ? inside[n_in++] : outside[n_out++]) = v;
    if (n_in == 0 || n_out == 0) return;
    Eigen::Vector3d in = Eigen::Vector3d::Zero(), out = Eigen::Vector3d::Zero();
    for (int v = 0; v < n_in; ++v) in += Eigen::Vector3d(c[inside[v]][0], c[inside[v]][1], c[inside[v]][2]) / n_in;
    for (int v = 0; v < n_out; ++v) out += Eigen::Vector3d(c[outside[v]][0], c[outside[v]][1], c[outside[v]][2]) / n_out;
    auto on = [&](int a, int b) { return a < b ? edge_vertex(c[a], c[b]) : edge_vertex(c[b], c[a]); };
    if (n_in == 1 || n_out == 1) {
      const int lone = n_in == 1 ? inside[0] : outside[0];
      const std::array<int, 4>& rest = n_in == 1 ? outside : inside;
      triangle(on(lone, rest[0]), on(lone, rest[1]), on(lone, rest[2]), in, out);
      return;
    }
    // Two in (a, b), two out (c, d): the crossing is the quad ac, ad, bd, bc, cut along ac-bd.
    const std::uint32_t ac = on(inside[0], outside[0]), ad = on(inside[0], outside[1]);
    const std::uint32_t bd = on(inside[1], outside[1]), bc = on(inside[1], outside[0]);
    const std::size_t first = mesh_.triangles.size();
    triangle(ac, ad, bd, in, out);
    // The second half runs the shared edge ac-bd the other way round (each half separates a, b from c, d, so
    // both tests agree; this just spells out that they must).
    const bool kept = mesh_.triangles[first][1] == ad;
    mesh_.triangles.push_back(kept ? Triangle{ac, bd, bc} : Triangle{ac, bc, bd});
  }

  const VoxelGrid& g_;
  const std::vector<float>& f_;
  std::array<int, 8> direction_{};
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_edge_;
  TriMesh mesh_;
};

}  // namespace

TriMesh marching_tetrahedra(const VoxelGrid& grid, const std::vector<float>& field) {
  Extractor x(grid, field);
  for (int k = 0; k + 1 < grid.size[2]; ++k)
    for (int j = 0; j + 1 < grid.size[1]; ++j)
      for (int i = 0; i + 1 < grid.size[0]; ++i) {
        // Most cubes lie wholly inside or outside: skip them before cutting them into tetrahedra.
        bool pos = false, neg = false;
        for (int c = 0; c < 8; ++c) {
          const float f = field[static_cast<std::size_t>(grid.index(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2)))];
          (f > 0 ? pos : neg) = true;
        }
        if (pos && neg) x.cube(i, j, k);
      }
  return x.take();
}

}  // namespace lungar::sim
