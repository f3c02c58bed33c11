/// @file spherical_map.cpp
/// @brief The radial and conformal maps of a lung surface onto the unit sphere (see the header).
#include "sim/mesh/spherical_map.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lungar::sim {
namespace {

/// An undirected edge a < b, its cotangent weight (cot alpha + cot beta) / 2 and its two triangles.
struct Edge {
  std::uint32_t a = 0, b = 0;
  double cot = 0;
  std::uint32_t t0 = 0, t1 = 0;
};

/// The edges of a closed surface, each once, with their cotangent weights (the bake's lung surfaces are closed,
/// so every edge is seen from exactly two triangles).
std::vector<Edge> cotangent_edges(const TriMesh& mesh) {
  std::vector<Edge> half;
  half.reserve(3 * mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[(k + 1) % 3], b = tri[(k + 2) % 3];  // the edge opposite corner k
      const Eigen::Vector3d ea = mesh.positions[a] - mesh.positions[tri[k]];
      const Eigen::Vector3d eb = mesh.positions[b] - mesh.positions[tri[k]];
      const double twice_area = ea.cross(eb).norm();
      half.push_back({std::min(a, b), std::max(a, b), twice_area > 0 ? 0.5 * ea.dot(eb) / twice_area : 0.0, t, t});
    }
  }
  std::sort(half.begin(), half.end(), [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  std::vector<Edge> edges;
  edges.reserve(half.size() / 2);
  for (const Edge& h : half) {
    if (!edges.empty() && edges.back().a == h.a && edges.back().b == h.b) {
      edges.back().cot += h.cot;
      edges.back().t1 = h.t0;
    } else {
      edges.push_back(h);
    }
  }
  return edges;
}

std::vector<double> triangle_areas(const TriMesh& mesh, const std::vector<Eigen::Vector3d>& p) {
  std::vector<double> area(mesh.triangles.size());
  for (std::size_t t = 0; t < area.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    area[t] = 0.5 * (p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]).norm();
  }
  return area;
}

/// The plane embedding of the surface punctured at one triangle: that triangle's corners pinned to an equilateral
/// triangle of circumradius `radius`, every other vertex at the `w`-weighted mean of its neighbours (Tutte), from
/// one sparse LDL^T solve of the interior Laplacian. False when the solve fails.
bool plane_embedding(const TriMesh& mesh, const std::vector<Edge>& edges, const std::vector<double>& w,
                     std::uint32_t puncture, double radius, Eigen::MatrixX2d& plane) {
  const auto n = static_cast<Eigen::Index>(mesh.positions.size());
  plane = Eigen::MatrixX2d::Zero(n, 2);
  std::vector<std::int64_t> index(mesh.positions.size(), -1);  // interior unknown, or -2 for a pinned corner
  const Triangle& hole = mesh.triangles[puncture];
  // Seen from outside, the hole runs h0 -> h1 -> h2; the disk that remains runs the other way round its rim,
  // so h0, h2, h1 go anticlockwise in the plane and every other triangle comes out anticlockwise too.
  const double angle_deg[3] = {90.0, -30.0, 210.0};
  for (int k = 0; k < 3; ++k) {
    const double a = angle_deg[k] * std::numbers::pi / 180.0;
    plane.row(hole[k]) = Eigen::RowVector2d(radius * std::cos(a), radius * std::sin(a));
    index[hole[k]] = -2;
  }
  std::int64_t interior = 0;
  for (std::int64_t& i : index)
    if (i == -1) i = interior++;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * edges.size());
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(interior, 2);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::int64_t ia = index[edges[e].a], ib = index[edges[e].b];
    if (ia >= 0) entries.emplace_back(ia, ia, w[e]);
    if (ib >= 0) entries.emplace_back(ib, ib, w[e]);
    if (ia >= 0 && ib >= 0) entries.emplace_back(std::max(ia, ib), std::min(ia, ib), -w[e]);  // lower half
    if (ia >= 0 && ib < 0) rhs.row(ia) += w[e] * plane.row(edges[e].b);
    if (ib >= 0 && ia < 0) rhs.row(ib) += w[e] * plane.row(edges[e].a);
  }
  Eigen::SparseMatrix<double> laplacian(interior, interior);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(laplacian);
  if (ldlt.info() != Eigen::Success) return false;
  const Eigen::MatrixX2d x = ldlt.solve(rhs);
  for (std::size_t v = 0; v < index.size(); ++v)
    if (index[v] >= 0) plane.row(static_cast<Eigen::Index>(v)) = x.row(index[v]);
  return plane.allFinite();
}

/// Inverse stereographic projection, mirrored (y -> -y) so that anticlockwise plane triangles stay positively
/// oriented seen from outside the sphere; the plane's origin goes to the south pole.
std::vector<Eigen::Vector3d> lift_to_sphere(const Eigen::MatrixX2d& plane) {
  std::vector<Eigen::Vector3d> u(static_cast<std::size_t>(plane.rows()));
  for (Eigen::Index i = 0; i < plane.rows(); ++i) {
    const double x = plane(i, 0), y = plane(i, 1), r2 = x * x + y * y;
    u[static_cast<std::size_t>(i)] = Eigen::Vector3d(2 * x, -2 * y, r2 - 1) / (1 + r2);
  }
  return u;
}

/// Moves the `weight`-weighted centroid of the points to the sphere's centre by Moebius transformations:
/// x -> (1 - |a|^2)(x - a)/|x - a|^2 - a spreads the points out around a. For evenly spread points a step with a
/// = 3/4 of the centroid cancels it to first order; repeated, it converges (and keeps orientation and angles).
void balance_centroid(std::vector<Eigen::Vector3d>& u, const std::vector<double>& weight) {
  double total = 0;
  for (double w : weight) total += w;
  for (int iteration = 0; iteration < 200; ++iteration) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < u.size(); ++i) c += weight[i] * u[i];
    c /= total;
    if (c.norm() < 1e-12) return;
    Eigen::Vector3d a = 0.75 * c;
    if (a.norm() > 0.9) a *= 0.9 / a.norm();
    const double k = 1 - a.squaredNorm();
    for (Eigen::Vector3d& x : u) x = (k * (x - a) / (x - a).squaredNorm() - a).normalized();
  }
}

/// The lift is conformal, but the vertices' chord triangles are not its image: a sliver whose middle vertex sits
/// a hair off the straight line in the plane can land a hair on the wrong side of the great circle through the
/// others. Each pass moves the vertices of such triangles to the mean of their neighbours on the sphere (and,
/// from the fourth pass on, their neighbours' too); returns the folds left.
std::uint64_t untangle(const TriMesh& mesh, const std::vector<Edge>& edges, std::vector<Eigen::Vector3d>& u) {
  std::vector<std::uint32_t> start(u.size() + 1, 0), ring(2 * edges.size());
  for (const Edge& e : edges) ++start[e.a + 1], ++start[e.b + 1];
  for (std::size_t v = 0; v < u.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const Edge& e : edges) ring[fill[e.a]++] = e.b, ring[fill[e.b]++] = e.a;
  std::uint64_t folded = folded_on_sphere(mesh, u);
  for (int pass = 0; pass < 20 && folded > 0; ++pass) {
    std::vector<std::uint8_t> move(u.size(), 0);
    for (const Triangle& t : mesh.triangles)
      if (!(u[t[0]].dot(u[t[1]].cross(u[t[2]])) > 0))
        for (std::uint32_t v : t) move[v] = 1;
    if (pass >= 3)
      for (std::size_t v = 0; v < u.size(); ++v)
        if (move[v] == 1)
          for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) move[ring[k]] = move[ring[k]] ? move[ring[k]] : 2;
    for (std::size_t v = 0; v < u.size(); ++v) {
      if (!move[v]) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) mean += u[ring[k]];
      if (mean.norm() > 0) u[v] = mean.normalized();
    }
    folded = folded_on_sphere(mesh, u);
  }
  return folded;
}

/// log(sphere area share / surface area share) per triangle, with the punctured triangle left at 0.
std::vector<double> log_area_ratio(const TriMesh& mesh, const std::vector<double>& surface_area,
                                   const std::vector<Eigen::Vector3d>& u, double surface_total) {
  const std::vector<double> sphere_area = triangle_areas(mesh, u);
  double sphere_total = 0;
  for (double a : sphere_area) sphere_total += a;
  std::vector<double> ratio(mesh.triangles.size());
  for (std::size_t t = 0; t < ratio.size(); ++t) {
    const double s = sphere_area[t] / sphere_total, m = surface_area[t] / surface_total;
    ratio[t] = s > 0 && m > 0 ? std::log(s / m) : 0.0;
  }
  return ratio;
}

double rms_over_area(const std::vector<double>& log_ratio, const std::vector<double>& area, double total) {
  double sum = 0;
  for (std::size_t t = 0; t < area.size(); ++t) sum += area[t] * log_ratio[t] * log_ratio[t];
  return std::sqrt(sum / total);
}

/// The conformal map: the plane embedding with clamped cotangent weights, lifted and balanced.
lungar::Result<SphereMapResult> conformal_map(const TriMesh& mesh) {
  const std::vector<Edge> edges = cotangent_edges(mesh);
  const std::vector<double> area = triangle_areas(mesh, mesh.positions);
  double total = 0;
  for (double a : area) total += a;
  const auto puncture = static_cast<std::uint32_t>(std::max_element(area.begin(), area.end()) - area.begin());
  // The pinned triangle's size: the sphere's cap beyond a plane disk of radius r holds 1/(1 + r^2) of it, so
  // r^2 = total/area - 1 gives the punctured triangle about its share of the sphere from the start.
  const double radius = std::sqrt(std::max(total / area[puncture] - 1.0, 1.0));
  // Cotangent weights, clamped positive: negative ones (obtuse triangles) would void Tutte's guarantee.
  double mean = 0;
  for (const Edge& e : edges) mean += std::abs(e.cot);
  mean /= static_cast<double>(edges.size());
  std::vector<double> w(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) w[e] = std::max(edges[e].cot, 1e-3 * mean);
  Eigen::MatrixX2d plane;
  if (!plane_embedding(mesh, edges, w, puncture, radius, plane)) return fail("the sphere map's sparse solve failed; expected a closed surface");
  std::vector<double> vertex_area(mesh.positions.size(), 0.0);
  for (std::size_t t = 0; t < area.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t]) vertex_area[v] += area[t] / 3;
  SphereMapResult r;
  r.u = lift_to_sphere(plane);
  balance_centroid(r.u, vertex_area);
  r.folded = untangle(mesh, edges, r.u);
  r.area_distortion = rms_over_area(log_area_ratio(mesh, area, r.u, total), area, total);
  return r;
}

}  // namespace

long euler_characteristic(const TriMesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = t[k], b = t[(k + 1) % 3];
      keys.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  std::sort(keys.begin(), keys.end());
  const auto edges = static_cast<long>(std::unique(keys.begin(), keys.end()) - keys.begin());
  return static_cast<long>(mesh.positions.size()) - edges + static_cast<long>(mesh.triangles.size());
}

std::uint64_t folded_on_sphere(const TriMesh& mesh, const std::vector<Eigen::Vector3d>& u) {
  std::uint64_t folded = 0;
  for (const Triangle& t : mesh.triangles)
    if (!(u[t[0]].dot(u[t[1]].cross(u[t[2]])) > 0)) ++folded;
  return folded;
}

lungar::Result<SphereMapResult> map_to_sphere(const TriMesh& mesh, const Eigen::Vector3d& centre, const SphereMapOptions& options) {
  if (options.map == SphereMap::radial) {
    SphereMapResult r;
    r.u.reserve(mesh.positions.size());
    for (const Eigen::Vector3d& p : mesh.positions) {
      const Eigen::Vector3d d = p - centre;
      const double len = d.norm();
      r.u.push_back(len > 0 ? Eigen::Vector3d(d / len) : Eigen::Vector3d::UnitZ());
    }
    r.folded = folded_on_sphere(mesh, r.u);
    const std::vector<double> area = triangle_areas(mesh, mesh.positions);
    double total = 0;
    for (double a : area) total += a;
    r.area_distortion = rms_over_area(log_area_ratio(mesh, area, r.u, total), area, total);
    return r;
  }
  if (const long chi = euler_characteristic(mesh); chi != 2)
    return fail("the surface has Euler characteristic " + std::to_string(chi) + " (" +
                (chi < 2 && chi % 2 == 0 ? std::to_string((2 - chi) / 2) + " handles" : std::string("not a sphere")) +
                "); the " + std::string(kSphereMapNames.name(options.map)) +
                " map expected genus 0 (a closed surface without handles); --map radial accepts it");
  if (mesh.positions.size() < 4) return fail("the surface has fewer than 4 vertices; expected a closed surface");
  return conformal_map(mesh);
}

}  // namespace lungar::sim
