/// @file mesh_repair.cpp
/// @brief Welding, degenerate-triangle removal, component split, closedness and orientation checks.
#include "sim/mesh/mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace lungar::sim {
namespace {

struct Vec3Hash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::size_t h = 1469598103934665603ull;
    for (double d : p) {
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

/// Flips triangles so that every shared edge is used once in each direction; false if impossible.
bool orient_consistently(std::vector<Triangle>& tris) {
  std::unordered_map<std::uint64_t, std::array<std::uint32_t, 2>> edge_tris;
  edge_tris.reserve(tris.size() * 2);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = edge_tris.try_emplace(edge_key(tris[t][k], tris[t][(k + 1) % 3]),
                                               std::array<std::uint32_t, 2>{t, t});
      if (!fresh) it->second[1] = t;
    }
  auto directed = [](const Triangle& t, std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k)
      if (t[k] == a && t[(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<std::int8_t> state(tris.size(), 0);  // 0 unvisited, 1 visited
  std::queue<std::uint32_t> todo;
  state[0] = 1;
  todo.push(0);
  while (!todo.empty()) {
    const std::uint32_t t = todo.front();
    todo.pop();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
      const auto& pair = edge_tris.at(edge_key(a, b));
      const std::uint32_t other = pair[0] == t ? pair[1] : pair[0];
      if (other == t) continue;
      const bool same_direction = directed(tris[other], a, b);  // a consistent neighbour runs b -> a
      if (state[other] == 0) {
        if (same_direction) std::swap(tris[other][1], tris[other][2]);
        state[other] = 1;
        todo.push(other);
      } else if (same_direction) {
        return false;  // a Moebius-like surface: no consistent orientation exists
      }
    }
  }
  return true;
}

/// Every coordinate finite and every index a vertex.
Status check_soup(const TriMesh& soup, const std::string& source) {
  for (std::size_t i = 0; i < soup.positions.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(soup.positions[i][k]))
        return fail(source + ": vertex " + std::to_string(i) + " coordinate " + "xyz"[k] +
                       " is not finite; expected finite numbers");
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    for (std::uint32_t v : soup.triangles[t])
      if (v >= soup.positions.size())
        return fail(source + ": triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                       "; expected an index below " + std::to_string(soup.positions.size()));
  return ok();
}

/// Welds corners with identical coordinates (STL stores every corner of every triangle) and drops the
/// triangles left without area: the welded positions, and the triangles on them.
Result<std::pair<std::vector<Eigen::Vector3d>, std::vector<Triangle>>> weld_corners(
    const TriMesh& soup, const std::string& source, std::vector<std::string>& notes) {
  std::unordered_map<std::array<double, 3>, std::uint32_t, Vec3Hash> unique;
  unique.reserve(soup.positions.size());
  std::vector<std::uint32_t> weld(soup.positions.size());
  std::vector<Eigen::Vector3d> welded;
  for (std::size_t i = 0; i < soup.positions.size(); ++i) {
    const auto& p = soup.positions[i];
    auto [it, fresh] = unique.try_emplace({p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(welded.size()));
    if (fresh) welded.push_back(p);
    weld[i] = it->second;
  }
  if (welded.size() < soup.positions.size())
    notes.push_back(source + ": welded " + std::to_string(soup.positions.size() - welded.size()) +
                    " repeated corners");

  std::vector<Triangle> tris;
  tris.reserve(soup.triangles.size());
  std::size_t degenerate = 0;
  for (const Triangle& t0 : soup.triangles) {
    const Triangle t{weld[t0[0]], weld[t0[1]], weld[t0[2]]};
    const double twice_area = (welded[t[1]] - welded[t[0]]).cross(welded[t[2]] - welded[t[0]]).norm();
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(twice_area > 0)) {
      ++degenerate;
      continue;
    }
    tris.push_back(t);
  }
  if (degenerate > 0) notes.push_back(source + ": dropped " + std::to_string(degenerate) + " degenerate triangles");
  if (tris.empty()) return fail(source + ": no triangles with non-zero area; expected a closed lung surface");
  return std::pair{std::move(welded), std::move(tris)};
}

/// Closed and 2-manifold: every undirected edge is shared by exactly two triangles.
Status check_closed_manifold(const std::vector<Triangle>& tris, const std::string& source) {
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(tris.size() * 2);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) ++uses[edge_key(t[k], t[(k + 1) % 3])];
  std::size_t open = 0, nonmanifold = 0;
  for (const auto& [key, n] : uses) {
    if (n == 1) ++open;
    if (n > 2) ++nonmanifold;
  }
  if (open > 0)
    return fail(source + ": surface is open (" + std::to_string(open) +
                   " edges belong to one triangle only); expected a closed surface");
  if (nonmanifold > 0)
    return fail(source + ": surface is not manifold (" + std::to_string(nonmanifold) +
                   " edges shared by more than two triangles); expected a 2-manifold surface");
  return ok();
}

/// Connected components by shared vertices, largest first, without stray specks (a fraction of a percent of the
/// surface: segmentation noise, not lungs).
std::vector<std::vector<Triangle>> split_components(const std::vector<Triangle>& tris, std::size_t vertex_count,
                                                    const std::string& source, std::vector<std::string>& notes) {
  std::vector<std::uint32_t> parent(vertex_count);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Triangle& t : tris) {
    const std::uint32_t r0 = find_root(parent, t[0]);
    parent[find_root(parent, t[1])] = r0;
    parent[find_root(parent, t[2])] = r0;
  }
  std::unordered_map<std::uint32_t, std::vector<Triangle>> by_root;
  for (const Triangle& t : tris) by_root[find_root(parent, t[0])].push_back(t);
  std::vector<std::vector<Triangle>> comps;
  for (auto& [root, list] : by_root) comps.push_back(std::move(list));
  std::sort(comps.begin(), comps.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() > b.size() : a.front() < b.front();
  });
  const std::size_t speck = std::max<std::size_t>(1, comps.front().size() / 100);
  std::size_t dropped = 0;
  while (comps.size() > 1 && comps.back().size() < speck) {
    comps.pop_back();
    ++dropped;
  }
  if (dropped > 0) notes.push_back(source + ": dropped " + std::to_string(dropped) + " tiny stray components");
  return comps;
}

/// One component as a mesh of its own, oriented consistently and facing outward.
Result<TriMesh> component_mesh(std::vector<Triangle> comp, const std::vector<Eigen::Vector3d>& welded,
                               const std::string& source, std::vector<std::string>& notes) {
  if (!orient_consistently(comp))
    return fail(source + ": surface cannot be oriented consistently; expected an orientable closed surface");
  TriMesh m;
  std::unordered_map<std::uint32_t, std::uint32_t> remap;
  for (Triangle& t : comp)
    for (std::uint32_t& v : t) {
      auto [it, fresh] = remap.try_emplace(v, static_cast<std::uint32_t>(m.positions.size()));
      if (fresh) m.positions.push_back(welded[v]);
      v = it->second;
    }
  m.triangles = std::move(comp);
  if (m.positions.size() < 4)
    return fail(source + ": a component has " + std::to_string(m.positions.size()) +
                   " vertices; expected a closed lung surface");
  if (enclosed_volume(m) < 0) {
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
    notes.push_back(source + ": triangles faced inward; flipped them to face outward");
  }
  return m;
}

}  // namespace

Result<std::vector<TriMesh>> repair_surface(const TriMesh& soup, const std::string& source,
                                            std::vector<std::string>& notes) {
  if (Status s = check_soup(soup, source); !s) return fail(s.error());
  auto welded = weld_corners(soup, source, notes);
  if (!welded) return fail(welded.error());
  const auto& [positions, tris] = *welded;
  if (Status s = check_closed_manifold(tris, source); !s) return fail(s.error());
  std::vector<TriMesh> out;
  for (auto& comp : split_components(tris, positions.size(), source, notes)) {
    auto mesh = component_mesh(std::move(comp), positions, source, notes);
    if (!mesh) return fail(mesh.error());
    out.push_back(mesh.take());
  }
  return out;
}

}  // namespace lungar::sim
