/// @file interior_displacement_test.cpp
/// @brief The motion inside the lungs (sim/motion/interior_displacement.h) on the sliding procedural pair, supine
///        at 500 mL: a point near the base moves more than one near the apex; near the surface the field meets
///        the surface's motion; an affine motion of the surface is reproduced inside; no interior point moves
///        beyond the surface's extremes (the maximum principle); the samples are inside, uniform and repeatable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/mesh/tri_mesh.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/motion_figures.h"
#include "pathology_test_support.h"
#include "tests/lung_axis.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::sliding_asset;

using test::kSupine;

/// The field of the shared bake, built once per test binary.
const InteriorDisplacement& field() {
  static const InteriorDisplacement f(sliding_asset());
  return f;
}

const std::vector<float>& supine_surface() {
  static const std::vector<float> d =
      displacement_vectors(sliding_asset(), PatientState::of(sliding_asset()), kSupine, 500.0);
  return d;
}

/// One point, in the lung that encloses it.
InteriorPoints one_point(const Eigen::Vector3d& p) {
  const int lung = field().lung_containing(p);
  EXPECT_GE(lung, 0) << p.transpose() << " is inside no lung";
  return {{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())},
          {static_cast<std::uint8_t>(std::max(lung, 0))}};
}

Eigen::Vector3d moved_by(const std::vector<float>& surface_d, const Eigen::Vector3d& p) {
  const std::vector<float> d = field().displacement(surface_d, one_point(p));
  return {d[0], d[1], d[2]};
}

Eigen::Vector3d vertex(const BakedAsset& a, std::size_t i) {
  return {a.positions[3 * i], a.positions[3 * i + 1], a.positions[3 * i + 2]};
}

TEST(InteriorDisplacement, APointNearTheBaseMovesMoreThanOneNearTheApex) {
  const BakedAsset& a = sliding_asset();
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    const BakedLung& lung = a.lungs[l];
    // The vertical line through the lung's rest centroid of vertices; its lowest and highest points inside.
    const testing::LungAxis axis = testing::lung_axis(a, field(), l);
    ASSERT_LT(axis.low_z, axis.high_z) << lung.name;
    const Eigen::Vector3d& c = axis.centroid;
    const double base = moved_by(supine_surface(), {c.x(), c.y(), axis.low_z + 10}).norm();
    const double apex = moved_by(supine_surface(), {c.x(), c.y(), axis.high_z - 10}).norm();
    EXPECT_GT(base, 3.0) << lung.name << ": 10 mm above the diaphragm moves with it";
    EXPECT_GT(base, 2.0 * apex) << lung.name << ": base " << base << " mm, apex " << apex << " mm";
  }
}

TEST(InteriorDisplacement, NearTheSurfaceItMeetsTheSurfacesMotion) {
  const BakedAsset& a = sliding_asset();
  const std::vector<float>& d = supine_surface();
  // Every 20th vertex, a point depth mm inside along its normal: the mean gap to the vertex's own motion.
  auto gap_at = [&](double depth, double& moved) {
    InteriorPoints pts;
    std::vector<std::size_t> from;
    for (std::size_t i = 0; i < a.vertex_count(); i += 20) {
      const Eigen::Vector3d n(a.normals[3 * i], a.normals[3 * i + 1], a.normals[3 * i + 2]);
      const Eigen::Vector3d p = vertex(a, i) - depth * n;
      if (field().lung_containing(p) != a.lung_of_vertex[i]) continue;  // a thin part: the point left the lung
      for (int c = 0; c < 3; ++c) pts.positions.push_back(static_cast<float>(p[c]));
      pts.lung_of_point.push_back(a.lung_of_vertex[i]);
      from.push_back(i);
    }
    const std::vector<float> di = field().displacement(d, pts);
    double gap = 0;
    moved = 0;
    for (std::size_t k = 0; k < from.size(); ++k) {
      const std::size_t i = from[k];
      const Eigen::Vector3d dv(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
      gap += (Eigen::Vector3d(di[3 * k], di[3 * k + 1], di[3 * k + 2]) - dv).norm();
      moved += dv.norm();
    }
    EXPECT_GT(from.size(), a.vertex_count() / 40) << "most points " << depth << " mm in are inside";
    moved /= static_cast<double>(from.size());
    return gap / static_cast<double>(from.size());
  };
  double moved = 0;
  const double near = gap_at(0.5, moved), mid = gap_at(5.0, moved), deep = gap_at(15.0, moved);
  EXPECT_LT(near, 0.1 * moved) << "0.5 mm in: gap " << near << " mm against a mean motion of " << moved << " mm";
  EXPECT_LT(near, mid) << "closer to the surface, closer to its motion";
  EXPECT_LT(mid, deep);
}

TEST(InteriorDisplacement, AnAffineMotionOfTheSurfaceIsReproducedInside) {
  const BakedAsset& a = sliding_asset();
  // d = A x + b: harmonic, so its own extension; the grid meets the surface to within a step.
  Eigen::Matrix3d A;
  A << 0.02, -0.01, 0.03, 0.00, 0.05, -0.02, 0.04, 0.01, -0.06;
  const Eigen::Vector3d b(1.0, -2.0, 3.0);
  std::vector<float> d(a.positions.size());
  for (std::size_t i = 0; i < a.vertex_count(); ++i) {
    const Eigen::Vector3d v = A * vertex(a, i) + b;
    for (int c = 0; c < 3; ++c) d[3 * i + c] = static_cast<float>(v[c]);
  }
  const InteriorPoints pts = field().sample(2000, 5);
  const std::vector<float> di = field().displacement(d, pts);
  double worst = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::Vector3d p(pts.positions[3 * k], pts.positions[3 * k + 1], pts.positions[3 * k + 2]);
    worst = std::max(worst, (Eigen::Vector3d(di[3 * k], di[3 * k + 1], di[3 * k + 2]) - (A * p + b)).norm());
  }
  EXPECT_LT(worst, A.norm() * field().spacing_mm()) << "the largest error, mm";
}

TEST(InteriorDisplacement, NoInteriorPointMovesBeyondTheSurfacesExtremes) {
  const BakedAsset& a = sliding_asset();
  const std::vector<float>& d = supine_surface();
  const InteriorPoints pts = field().sample(3000, 11);
  const std::vector<float> di = field().displacement(d, pts);
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    const BakedLung& lung = a.lungs[l];
    for (int c = 0; c < 3; ++c) {
      float lo = 1e9f, hi = -1e9f;
      for (std::uint32_t i = lung.first_vertex; i < lung.first_vertex + lung.vertex_count; ++i) {
        lo = std::min(lo, d[3 * i + c]);
        hi = std::max(hi, d[3 * i + c]);
      }
      float in_lo = 1e9f, in_hi = -1e9f;
      for (std::size_t k = 0; k < pts.size(); ++k) {
        if (std::size_t{pts.lung_of_point[k]} != l) continue;
        in_lo = std::min(in_lo, di[3 * k + c]);
        in_hi = std::max(in_hi, di[3 * k + c]);
      }
      EXPECT_GE(in_lo, lo - 1e-4f) << lung.name << ", component " << c;
      EXPECT_LE(in_hi, hi + 1e-4f) << lung.name << ", component " << c;
      EXPECT_LT(in_hi - in_lo, hi - lo) << lung.name << ", component " << c << ": inside spans less than the surface";
    }
  }
}

TEST(InteriorDisplacement, SamplesAreInsideUniformOverTheVolumeAndRepeatable) {
  const BakedAsset& a = sliding_asset();
  const InteriorPoints pts = field().sample(4000, 3);
  ASSERT_EQ(pts.size(), 4000u);
  EXPECT_EQ(pts.positions, field().sample(4000, 3).positions) << "the same seed, the same points";
  EXPECT_NE(pts.positions, field().sample(4000, 4).positions);
  std::vector<Eigen::Vector3d> centre(a.lungs.size(), Eigen::Vector3d::Zero());
  std::vector<double> count(a.lungs.size(), 0.0);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::Vector3d p(pts.positions[3 * k], pts.positions[3 * k + 1], pts.positions[3 * k + 2]);
    ASSERT_EQ(field().lung_containing(p), pts.lung_of_point[k]);
    centre[pts.lung_of_point[k]] += p;
    count[pts.lung_of_point[k]] += 1;
  }
  double volume = 0;
  for (const BakedLung& lung : a.lungs) volume += lung.rest_volume_ml;
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    // Each lung's share of the points is its share of the volume, and their mean its volume's centroid.
    EXPECT_NEAR(count[l] / 4000.0, a.lungs[l].rest_volume_ml / volume, 0.03) << a.lungs[l].name;
    const Eigen::Vector3d solid = volume_centroid(test::lung_mesh(a, a.lungs[l]));
    EXPECT_LT((centre[l] / count[l] - solid).norm(), 4.0) << a.lungs[l].name;
  }
}

}  // namespace
}  // namespace lungar::sim
