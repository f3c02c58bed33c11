/// @file interior_displacement.cpp
/// @brief Per lung: the grid and its inside nodes, the boundary nodes' nearest surface points, the Laplacian
///        (conjugate gradients with an incomplete Cholesky preconditioner), trilinear evaluation, and a parity
///        test along +x for sampling.
#include "sim/motion/interior_displacement.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

#include "sim/mesh/tri_mesh.h"
#include "sim/mesh/triangle_tree.h"
#include "sim/voxel/voxelize.h"

namespace lungar::sim {

struct InteriorDisplacement::Lung {
  std::uint32_t first_vertex = 0;
  TriMesh mesh;                              ///< the lung's rest surface, its own vertex indices
  std::unique_ptr<TriangleTree> tree;        ///< over `mesh` (which stays where it is: Lung lives on the heap)
  VoxelMask grid;                            ///< inside[] at the grid nodes
  std::vector<std::int32_t> unknown;         ///< per grid node: its unknown, or -1
  std::vector<std::int32_t> boundary;        ///< per grid node: its boundary node, or -1
  std::vector<NearestPoint> boundary_point;  ///< per boundary node: the surface point it takes its value from
  Eigen::SparseMatrix<double> laplacian;     ///< unknowns x unknowns: 6 on the diagonal, -1 per inside neighbour
  Eigen::SparseMatrix<double> coupling;      ///< unknowns x boundary nodes: 1 per boundary neighbour
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double>> solver;
  // The parity test: triangles binned by their (y, z) footprint on cells of `bin_step`.
  Eigen::Vector2d bin_origin = Eigen::Vector2d::Zero();
  double bin_step = 1;
  int bins_y = 0, bins_z = 0;
  std::vector<std::vector<std::uint32_t>> bins;
  Eigen::AlignedBox3d box;

  bool encloses(const Eigen::Vector3d& p) const;
  /// The displacement of the surface point `q` when the vertices move by `d` (the asset's, 3 per vertex).
  Eigen::Vector3d surface_value(const NearestPoint& q, std::span<const float> d) const;
};

namespace {

constexpr int kNeighbour6[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

/// Lung `l` of the asset as a surface of its own.
TriMesh interior_lung_mesh(const BakedAsset& a, const BakedLung& lung) {
  TriMesh m;
  m.positions.reserve(lung.vertex_count);
  for (std::uint32_t i = 0; i < lung.vertex_count; ++i) {
    const float* p = &a.positions[3 * (std::size_t{lung.first_vertex} + i)];
    m.positions.emplace_back(p[0], p[1], p[2]);
  }
  for (std::uint32_t t = 0; t < lung.index_count; t += 3) {
    const std::uint32_t* v = &a.triangles[lung.first_index + t];
    m.triangles.push_back({v[0] - lung.first_vertex, v[1] - lung.first_vertex, v[2] - lung.first_vertex});
  }
  return m;
}

/// A grid node around a point and its trilinear weight.
struct Corner {
  Eigen::Vector3i node;
  double weight = 0;
};

/// The 8 nodes of the grid cell holding x (clamped onto the grid) and their trilinear weights, which sum to 1.
std::array<Corner, 8> corners(const VoxelGrid& g, double h, const Eigen::Vector3d& x) {
  const Eigen::Vector3d q = (x - g.origin) / h;
  Eigen::Vector3i base;
  Eigen::Vector3d t;
  for (int c = 0; c < 3; ++c) {
    base[c] = std::clamp(static_cast<int>(std::floor(q[c])), 0, g.size[c] - 2);
    t[c] = std::clamp(q[c] - base[c], 0.0, 1.0);
  }
  std::array<Corner, 8> out;
  for (int corner = 0; corner < 8; ++corner) {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    out[static_cast<std::size_t>(corner)] = {base + Eigen::Vector3i(di, dj, dk),
                                             (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2])};
  }
  return out;
}

/// A double in [0, 1) from 53 bits of the generator: the same on every standard library (std::uniform_real_
/// distribution is not specified bit for bit).
double unit_interval(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

bool InteriorDisplacement::Lung::encloses(const Eigen::Vector3d& p) const {
  if (!box.contains(p)) return false;
  const int j = static_cast<int>(std::floor((p.y() - bin_origin.x()) / bin_step));
  const int k = static_cast<int>(std::floor((p.z() - bin_origin.y()) / bin_step));
  if (j < 0 || k < 0 || j >= bins_y || k >= bins_z) return false;
  int crossings = 0;
  for (std::uint32_t t : bins[static_cast<std::size_t>(k) * bins_y + j]) {
    const std::optional<double> x = x_crossing(mesh, t, p.y(), p.z());
    if (x && *x > p.x()) ++crossings;
  }
  return crossings % 2 == 1;
}

Eigen::Vector3d InteriorDisplacement::Lung::surface_value(const NearestPoint& q, std::span<const float> d) const {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const std::size_t v = first_vertex + std::size_t{mesh.triangles[q.triangle][k]};
    value += q.weights[k] * Eigen::Vector3d(d[3 * v], d[3 * v + 1], d[3 * v + 2]);
  }
  return value;
}

InteriorDisplacement::InteriorDisplacement(const BakedAsset& a, double spacing_mm) {
  double volume_mm3 = 0;
  for (const BakedLung& lung : a.lungs) volume_mm3 += lung.rest_volume_ml * 1000.0;
  spacing_ = spacing_mm > 0 ? spacing_mm : std::max(1.0, std::cbrt(volume_mm3 / kAutoNodes));
  const double h = spacing_;
  for (const BakedLung& baked : a.lungs) {
    auto l = std::make_unique<Lung>();
    l->first_vertex = baked.first_vertex;
    l->mesh = interior_lung_mesh(a, baked);
    l->tree = std::make_unique<TriangleTree>(l->mesh);
    for (const Eigen::Vector3d& p : l->mesh.positions) l->box.extend(p);
    l->grid = voxelize(l->mesh, h);  // two empty nodes of margin: every neighbour below is on the grid
    const VoxelGrid& g = l->grid.grid;
    const auto node_count = static_cast<std::size_t>(g.count());
    l->unknown.assign(node_count, -1);
    l->boundary.assign(node_count, -1);
    std::int32_t unknowns = 0;
    for (std::size_t n = 0; n < node_count; ++n)
      if (l->grid.inside[n]) l->unknown[n] = unknowns++;
    // Boundary nodes: the outside nodes among the 26 neighbours of an inside node (the corners of every cell an
    // inside point can fall in, and the Laplacian's 6 neighbours), each with its nearest surface point.
    for (int k = 0; k < g.size[2]; ++k)
      for (int j = 0; j < g.size[1]; ++j)
        for (int i = 0; i < g.size[0]; ++i) {
          if (!l->grid.inside[static_cast<std::size_t>(g.index(i, j, k))]) continue;
          for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
              for (int di = -1; di <= 1; ++di) {
                const auto m = static_cast<std::size_t>(g.index(i + di, j + dj, k + dk));
                if (l->grid.inside[m] || l->boundary[m] >= 0) continue;
                l->boundary[m] = static_cast<std::int32_t>(l->boundary_point.size());
                l->boundary_point.push_back(l->tree->nearest(g.point(Eigen::Vector3d(i + di, j + dj, k + dk))));
              }
        }
    // The 7-point Laplacian, scaled by h^2: at an inside node, 6 u - (sum of the neighbours) = 0, the boundary
    // neighbours moved to the right-hand side through `coupling`.
    std::vector<Eigen::Triplet<double>> lap, cup;
    lap.reserve(7 * static_cast<std::size_t>(unknowns));
    for (int k = 0; k < g.size[2]; ++k)
      for (int j = 0; j < g.size[1]; ++j)
        for (int i = 0; i < g.size[0]; ++i) {
          const std::int32_t row = l->unknown[static_cast<std::size_t>(g.index(i, j, k))];
          if (row < 0) continue;
          lap.emplace_back(row, row, 6.0);
          for (const auto& o : kNeighbour6) {
            const auto m = static_cast<std::size_t>(g.index(i + o[0], j + o[1], k + o[2]));
            if (l->unknown[m] >= 0) lap.emplace_back(row, l->unknown[m], -1.0);
            else cup.emplace_back(row, l->boundary[m], 1.0);
          }
        }
    l->laplacian.resize(unknowns, unknowns);
    l->laplacian.setFromTriplets(lap.begin(), lap.end());
    l->coupling.resize(unknowns, static_cast<Eigen::Index>(l->boundary_point.size()));
    l->coupling.setFromTriplets(cup.begin(), cup.end());
    l->solver.setTolerance(1e-8);
    if (unknowns > 0) l->solver.compute(l->laplacian);
    // Parity bins over (y, z) at the grid's step.
    l->bin_step = h;
    l->bin_origin = Eigen::Vector2d(l->box.min().y() - h, l->box.min().z() - h);
    l->bins_y = static_cast<int>(std::ceil(l->box.sizes().y() / h)) + 3;
    l->bins_z = static_cast<int>(std::ceil(l->box.sizes().z() / h)) + 3;
    l->bins.assign(static_cast<std::size_t>(l->bins_y) * l->bins_z, {});
    for (std::uint32_t t = 0; t < l->mesh.triangles.size(); ++t) {
      Eigen::AlignedBox3d tb;
      for (std::uint32_t v : l->mesh.triangles[t]) tb.extend(l->mesh.positions[v]);
      const int j0 = static_cast<int>(std::floor((tb.min().y() - l->bin_origin.x()) / h));
      const int j1 = static_cast<int>(std::floor((tb.max().y() - l->bin_origin.x()) / h));
      const int k0 = static_cast<int>(std::floor((tb.min().z() - l->bin_origin.y()) / h));
      const int k1 = static_cast<int>(std::floor((tb.max().z() - l->bin_origin.y()) / h));
      for (int k = std::max(k0, 0); k <= std::min(k1, l->bins_z - 1); ++k)
        for (int j = std::max(j0, 0); j <= std::min(j1, l->bins_y - 1); ++j)
          l->bins[static_cast<std::size_t>(k) * l->bins_y + j].push_back(t);
    }
    lungs_.push_back(std::move(l));
  }
}

InteriorDisplacement::~InteriorDisplacement() = default;
InteriorDisplacement::InteriorDisplacement(InteriorDisplacement&&) noexcept = default;
InteriorDisplacement& InteriorDisplacement::operator=(InteriorDisplacement&&) noexcept = default;

std::size_t InteriorDisplacement::inside_nodes(std::size_t lung) const {
  return static_cast<std::size_t>(lungs_.at(lung)->laplacian.rows());
}

int InteriorDisplacement::lung_containing(const Eigen::Vector3d& p) const {
  for (std::size_t l = 0; l < lungs_.size(); ++l)
    if (lungs_[l]->encloses(p)) return static_cast<int>(l);
  return -1;
}

InteriorPoints InteriorDisplacement::sample(std::size_t count, std::uint64_t seed) const {
  InteriorPoints out;
  Eigen::AlignedBox3d box;
  for (const auto& l : lungs_) box.extend(l->box);
  if (count == 0 || box.isEmpty()) return out;
  std::mt19937_64 rng(seed);
  out.positions.reserve(3 * count);
  out.lung_of_point.reserve(count);
  // The lungs fill some 40 % of their box; a million tries per point wanted means the surface encloses nothing.
  for (std::size_t tries = 0; out.size() < count; ++tries) {
    if (tries > 1000000 + 1000 * count) throw std::runtime_error("no volume inside the lungs' surfaces to sample");
    Eigen::Vector3d p;
    for (int c = 0; c < 3; ++c) p[c] = box.min()[c] + unit_interval(rng) * box.sizes()[c];
    const int lung = lung_containing(p);
    if (lung < 0) continue;
    for (int c = 0; c < 3; ++c) out.positions.push_back(static_cast<float>(p[c]));
    out.lung_of_point.push_back(static_cast<std::uint8_t>(lung));
  }
  return out;
}

std::vector<float> InteriorDisplacement::displacement(std::span<const float> surface_d,
                                                      const InteriorPoints& points) const {
  std::vector<float> out(3 * points.size(), 0.0f);
  for (std::size_t li = 0; li < lungs_.size(); ++li) {
    const Lung& l = *lungs_[li];
    bool any = false;
    for (std::uint8_t lp : points.lung_of_point) any = any || std::size_t{lp} == li;
    if (!any) continue;
    // Boundary values, then the interior nodes: L u = C b, a column per component.
    Eigen::MatrixXd b(static_cast<Eigen::Index>(l.boundary_point.size()), 3);
    for (std::size_t n = 0; n < l.boundary_point.size(); ++n)
      b.row(static_cast<Eigen::Index>(n)) = l.surface_value(l.boundary_point[n], surface_d).transpose();
    Eigen::MatrixXd u(l.laplacian.rows(), 3);
    if (l.laplacian.rows() > 0) {
      const Eigen::MatrixXd rhs = l.coupling * b;
      // Start from the boundary's mean: the solution of a uniform motion, which the surface nearly is far from
      // the diaphragm.
      const Eigen::RowVector3d mean = b.rows() > 0 ? Eigen::RowVector3d(b.colwise().mean()) : Eigen::RowVector3d::Zero();
      const Eigen::MatrixXd guess = Eigen::MatrixXd::Ones(u.rows(), 1) * mean;
      u = l.solver.solveWithGuess(rhs, guess);
    }
    const VoxelGrid& g = l.grid.grid;
    auto node_value = [&](int i, int j, int k) -> Eigen::Vector3d {
      const auto n = static_cast<std::size_t>(g.index(i, j, k));
      if (l.unknown[n] >= 0) return u.row(l.unknown[n]).transpose();
      if (l.boundary[n] >= 0) return l.surface_value(l.boundary_point[static_cast<std::size_t>(l.boundary[n])], surface_d);
      // A cell with no inside corner (a sliver thinner than the grid step): the nearest surface point's motion.
      return l.surface_value(l.tree->nearest(g.point(Eigen::Vector3d(i, j, k))), surface_d);
    };
    for (std::size_t p = 0; p < points.size(); ++p) {
      if (std::size_t{points.lung_of_point[p]} != li) continue;
      const Eigen::Vector3d x(points.positions[3 * p], points.positions[3 * p + 1], points.positions[3 * p + 2]);
      Eigen::Vector3d value = Eigen::Vector3d::Zero();
      for (const Corner& c : corners(g, spacing_, x))
        if (c.weight > 0) value += c.weight * node_value(c.node[0], c.node[1], c.node[2]);
      for (int c = 0; c < 3; ++c) out[3 * p + c] = static_cast<float>(value[c]);
    }
  }
  return out;
}

std::vector<VertexWeight> InteriorDisplacement::surface_weights(const Eigen::Vector3d& p, std::size_t lung) const {
  const Lung& l = *lungs_.at(lung);
  const VoxelGrid& g = l.grid.grid;
  // p's weights on the inside nodes (a) and, directly, on surface points (its boundary corners', and the nearest
  // surface point of a corner that is neither, as displacement() takes them).
  Eigen::VectorXd a = Eigen::VectorXd::Zero(l.laplacian.rows());
  std::vector<std::pair<NearestPoint, double>> direct;
  for (const Corner& c : corners(g, spacing_, p)) {
    if (c.weight <= 0) continue;
    const auto n = static_cast<std::size_t>(g.index(c.node[0], c.node[1], c.node[2]));
    if (l.unknown[n] >= 0)
      a[l.unknown[n]] += c.weight;
    else if (l.boundary[n] >= 0)
      direct.emplace_back(l.boundary_point[static_cast<std::size_t>(l.boundary[n])], c.weight);
    else
      direct.emplace_back(l.tree->nearest(g.point(c.node.cast<double>())), c.weight);
  }
  // The boundary values' weights: C' z with L z = a.
  if (a.any()) {
    const Eigen::VectorXd z = l.solver.solve(a);
    const Eigen::VectorXd beta = l.coupling.transpose() * z;
    for (Eigen::Index j = 0; j < beta.size(); ++j)
      if (beta[j] != 0) direct.emplace_back(l.boundary_point[static_cast<std::size_t>(j)], beta[j]);
  }
  std::map<std::uint32_t, double> by_vertex;
  for (const auto& [q, w] : direct)
    for (int k = 0; k < 3; ++k) by_vertex[l.first_vertex + l.mesh.triangles[q.triangle][k]] += w * q.weights[k];
  std::vector<VertexWeight> out;
  out.reserve(by_vertex.size());
  for (const auto& [v, w] : by_vertex)
    if (w != 0) out.push_back({v, w});
  return out;
}

}  // namespace lungar::sim
