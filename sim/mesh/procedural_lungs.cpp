/// @file procedural_lungs.cpp
/// @brief Cube-sphere tessellation of a radial lung shape: ellipsoid, apex taper, diaphragm dome, medial
///        concavity, cardiac notch, seeded bumps.
#include "sim/mesh/procedural_lungs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

namespace lungar::sim {
namespace {

struct Bump {
  Eigen::Vector3d direction;
  double amplitude;
  double width;
};

struct LungShape {
  double a, b, c;            ///< ellipsoid half-axes: lateral (x), antero-posterior (y), height (z), mm
  double medial_sign;        ///< +1 when the medial side is +x (the right lung), -1 for the left lung
  bool cardiac_notch;
  double target_volume_mm3;
  std::vector<Bump> bumps;
};

/// Smooth minimum: keeps r(u) smooth where the dome meets the side (the costophrenic angle), which keeps the
/// pressure field smooth on the sphere.
double soft_min(double x, double y, double k) {
  const double m = std::min(x, y);
  return m - k * std::log(std::exp((m - x) / k) + std::exp((m - y) / k));
}

/// Distance from the centre along unit u to the surface, before the final volume scaling.
double radius(const LungShape& s, const Eigen::Vector3d& u) {
  const double side =
      1.0 / std::sqrt((u.x() / s.a) * (u.x() / s.a) + (u.y() / s.b) * (u.y() / s.b) + (u.z() / s.c) * (u.z() / s.c));
  // Apex: the upper half narrows to a cone-like dome.
  const double up = std::max(0.0, u.z());
  double r = side * (1.0 - 0.30 * up * (1.0 - up * up));
  // Diaphragm: a paraboloid dome z = -H + D (1 - rho^2 / rho_b^2) bulging up into the base.
  if (u.z() < 0) {
    const double H = 0.72 * s.c, D = 0.22 * s.c, rho_b = 1.05 * s.b;
    const double rho2 = (u.x() * s.b / s.a) * (u.x() * s.b / s.a) + u.y() * u.y();
    const double qa = D * rho2 / (rho_b * rho_b), qb = u.z(), qc = H - D;
    double dome = 1e9;
    const double disc = qb * qb - 4 * qa * qc;
    if (qa < 1e-12) dome = qc / -qb;
    else if (disc >= 0) dome = (-qb - std::sqrt(disc)) / (2 * qa);
    r = soft_min(r, dome, 0.12 * s.c);
  }
  // Medial face: concave where it meets the mediastinum and the heart.
  const double towards_medial = s.medial_sign * u.x();
  r *= 1.0 - 0.25 * std::exp(-(1.0 - towards_medial) / 0.35);
  if (s.cardiac_notch) {  // left lung: anterior, medial, inferior
    const Eigen::Vector3d notch = Eigen::Vector3d(s.medial_sign, -0.9, -0.55).normalized();
    r *= 1.0 - 0.25 * std::exp(-(1.0 - u.dot(notch)) / 0.12);
  }
  for (const Bump& b : s.bumps) r *= 1.0 + b.amplitude * std::exp(-(1.0 - u.dot(b.direction)) / b.width);
  return r;
}

/// Unit directions of an equal-angle cube sphere with n points per cube edge, and its triangles.
TriMesh cube_sphere(int n) {
  TriMesh m;
  std::map<std::array<int, 3>, std::uint32_t> index;
  auto vertex = [&](std::array<int, 3> p) {
    auto [it, fresh] = index.try_emplace(p, static_cast<std::uint32_t>(m.positions.size()));
    if (fresh) {
      Eigen::Vector3d q;
      for (int k = 0; k < 3; ++k) q[k] = std::tan(std::numbers::pi / 4 * (2.0 * p[k] / (n - 1) - 1.0));
      m.positions.push_back(q.normalized());
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n - 1})
      for (int i = 0; i + 1 < n; ++i)
        for (int j = 0; j + 1 < n; ++j) {
          auto at = [&](int di, int dj) {
            std::array<int, 3> p{};
            p[axis] = side;
            p[(axis + 1) % 3] = i + di;
            p[(axis + 2) % 3] = j + dj;
            return vertex(p);
          };
          const std::uint32_t v00 = at(0, 0), v10 = at(1, 0), v01 = at(0, 1), v11 = at(1, 1);
          for (Triangle t : {Triangle{v00, v10, v11}, Triangle{v00, v11, v01}}) {
            const auto& a = m.positions[t[0]];
            if (a.dot(m.positions[t[1]].cross(m.positions[t[2]])) < 0) std::swap(t[1], t[2]);
            m.triangles.push_back(t);
          }
        }
  return m;
}

LungMesh make_lung(const char* name, const LungShape& shape, const Eigen::Vector3d& centre, std::uint32_t nodes) {
  const int n = std::max(3, 1 + static_cast<int>(std::lround(std::sqrt(std::max(0.0, (nodes - 2.0) / 6.0)))));
  LungMesh lung;
  lung.name = name;
  lung.mesh = cube_sphere(n);
  for (Eigen::Vector3d& p : lung.mesh.positions) p *= radius(shape, p);
  const double scale = std::cbrt(shape.target_volume_mm3 / enclosed_volume(lung.mesh));
  for (Eigen::Vector3d& p : lung.mesh.positions) p = centre + scale * p;
  lung.has_centre = false;  // the bake takes the volume centroid, as for imported lungs (better eq. 7 fit)
  lung.centre = centre;
  return lung;
}

}  // namespace

std::vector<LungMesh> procedural_lungs(std::uint32_t total_nodes, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double lo, double hi) {  // not std::uniform_real_distribution: same numbers on every library
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  auto bumps = [&] {
    std::vector<Bump> out;
    for (int k = 0; k < 5; ++k) {
      Eigen::Vector3d d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if (d.norm() < 1e-3) d = Eigen::Vector3d::UnitX();
      out.push_back({d.normalized(), uniform(-0.04, 0.04), uniform(0.3, 0.8)});
    }
    return out;
  };
  const LungShape right{60, 88, 125, +1.0, false, 2.7e6, bumps()};
  const LungShape left{55, 85, 120, -1.0, true, 2.3e6, bumps()};
  const std::uint32_t total = std::max<std::uint32_t>(total_nodes, 52);
  const auto right_nodes = static_cast<std::uint32_t>(std::lround(total * 0.52));
  std::vector<LungMesh> lungs;
  lungs.push_back(make_lung("right", right, Eigen::Vector3d(-85, 0, 0), right_nodes));
  lungs.push_back(make_lung("left", left, Eigen::Vector3d(85, 0, 0), total - right_nodes));
  return lungs;
}

}  // namespace lungar::sim
