/// @file test_meshes.h
/// @brief Small closed surfaces for the sim tests: a UV sphere (deformed at will) and a torus.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "sim/mesh/tri_mesh.h"

namespace lungar::sim::test {

/// A closed UV sphere of unit radius with `rings` latitude bands and `segments` longitudes, outward, each point
/// passed through `shape`.
inline TriMesh uv_sphere(int rings, int segments,
                         const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& shape = nullptr) {
  TriMesh m;
  auto put = [&](const Eigen::Vector3d& p) {
    m.positions.push_back(shape ? shape(p) : p);
    return static_cast<std::uint32_t>(m.positions.size() - 1);
  };
  const std::uint32_t south = put({0, 0, -1});
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = std::numbers::pi * r / rings, phi = 2 * std::numbers::pi * s / segments;
      put({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta)});
    }
  const std::uint32_t north = put({0, 0, 1});
  auto at = [&](int r, int s) { return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({south, at(1, s + 1), at(1, s)});
    m.triangles.push_back({north, at(rings - 1, s), at(rings - 1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
  }
  return m;
}

/// A unit icosphere: the icosahedron split `levels` times (10 * 4^levels + 2 vertices), outward, each point passed
/// through `shape`. Its triangles are all nearly equilateral, unlike a UV sphere's slivers at the poles.
inline TriMesh icosphere(int levels, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& shape = nullptr) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriMesh m;
  for (const auto& v : {Eigen::Vector3d(-1, t, 0), Eigen::Vector3d(1, t, 0), Eigen::Vector3d(-1, -t, 0),
                        Eigen::Vector3d(1, -t, 0), Eigen::Vector3d(0, -1, t), Eigen::Vector3d(0, 1, t),
                        Eigen::Vector3d(0, -1, -t), Eigen::Vector3d(0, 1, -t), Eigen::Vector3d(t, 0, -1),
                        Eigen::Vector3d(t, 0, 1), Eigen::Vector3d(-t, 0, -1), Eigen::Vector3d(-t, 0, 1)})
    m.positions.push_back(v.normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      auto [it, fresh] = middle.try_emplace({std::min(a, b), std::max(a, b)}, 0u);
      if (fresh) {
        m.positions.push_back((m.positions[a] + m.positions[b]).normalized());
        it->second = static_cast<std::uint32_t>(m.positions.size() - 1);
      }
      return it->second;
    };
    std::vector<Triangle> split;
    for (const Triangle& f : m.triangles) {
      const std::uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      split.insert(split.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    m.triangles = std::move(split);
  }
  if (shape)
    for (Eigen::Vector3d& p : m.positions) p = shape(p);
  return m;
}

/// A torus (genus 1) of radii 2 and 0.7 about z.
inline TriMesh torus(int rings, int segments) {
  TriMesh m;
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double u = 2 * std::numbers::pi * r / rings, v = 2 * std::numbers::pi * s / segments;
      m.positions.emplace_back((2 + 0.7 * std::cos(v)) * std::cos(u), (2 + 0.7 * std::cos(v)) * std::sin(u), 0.7 * std::sin(v));
    }
  auto at = [&](int r, int s) { return static_cast<std::uint32_t>((r % rings) * segments + (s % segments)); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  return m;
}

}  // namespace lungar::sim::test
