/// @file spherical_map_test.cpp
/// @brief The sphere maps of the SH fit: the conformal map is one-to-one (no folded triangle) and balanced where
///        the radial map folds (a bent, non-star-shaped surface), keeps a round sphere round, refuses a surface
///        with a handle in one line; the bake reports both maps side by side.
#include <gtest/gtest.h>

#include <Eigen/SVD>

#include "sim/bake/bake.h"
#include "sim/mesh/procedural_lungs.h"
#include "sim/mesh/spherical_map.h"
#include "test_meshes.h"

namespace lungar::sim {
namespace {

/// An elongated ellipsoid bent into a C about the y axis: its centroid lies outside it, so rays from the centroid
/// cross the surface more than once and the radial map folds.
TriMesh bent_bean() {
  return test::icosphere(5, [](const Eigen::Vector3d& p) {
    const Eigen::Vector3d e(20 * p.x(), 25 * p.y(), 70 * p.z());
    return Eigen::Vector3d(e.x() + 60 * (1 - std::cos(e.z() / 45)), e.y(), e.z());
  });
}

Eigen::Vector3d area_centroid_on_sphere(const TriMesh& m, const std::vector<Eigen::Vector3d>& u) {
  const VertexGeometry g = vertex_geometry(m);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double total = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    c += g.areas[i] * u[i];
    total += g.areas[i];
  }
  return c / total;
}

TEST(SphericalMap, TestSurfacesAreClosedAndOutward) {
  EXPECT_GT(enclosed_volume(test::uv_sphere(10, 12)), 0);
  EXPECT_EQ(euler_characteristic(test::uv_sphere(10, 12)), 2);
  EXPECT_EQ(euler_characteristic(test::torus(16, 12)), 0);
  EXPECT_EQ(euler_characteristic(procedural_lungs(3000, 2)[1].mesh), 2);
}

TEST(SphericalMap, ConformalMapOfARoundSphereIsARotationOfIt) {
  const TriMesh m = test::icosphere(4);  // 2,562 vertices
  const auto r = map_to_sphere(m, Eigen::Vector3d::Zero(), {SphereMap::conformal});
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->folded, 0u);
  EXPECT_GT(r->area_distortion, 0.0);
  EXPECT_LT(r->area_distortion, 0.1) << "a rotation keeps every triangle's share of the area";
  // A conformal map of the round sphere onto itself that keeps the area centroid at the centre is a rotation:
  // the best rotation (Procrustes) must carry every vertex to its image, up to the distortion that pinning the
  // punctured triangle leaves (it shrinks with the triangle: a mean of 0.012 here, 0.006 at 10,242 vertices).
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < m.positions.size(); ++i) h += r->u[i] * m.positions[i].transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d rotation = svd.matrixV() * svd.matrixU().transpose();
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const double e = (rotation * r->u[i] - m.positions[i]).norm();
    sum += e;
    worst = std::max(worst, e);
  }
  EXPECT_LT(sum / m.positions.size(), 0.02);
  EXPECT_LT(worst, 0.05);
}

TEST(SphericalMap, ConformalMapIsOneToOneAndBalancedWhereTheRadialMapFolds) {
  const TriMesh m = bent_bean();
  ASSERT_GT(enclosed_volume(m), 0);
  const Eigen::Vector3d c = volume_centroid(m);
  const auto radial = map_to_sphere(m, c, {SphereMap::radial});
  const auto conformal = map_to_sphere(m, c, {SphereMap::conformal});
  ASSERT_TRUE(radial && conformal) << conformal.error();
  EXPECT_GT(radial->folded, 100u) << "the bent surface should fold under the radial map";
  EXPECT_EQ(conformal->folded, 0u);
  EXPECT_EQ(folded_on_sphere(m, conformal->u), 0u);
  for (const Eigen::Vector3d& u : conformal->u) ASSERT_NEAR(u.norm(), 1.0, 1e-12);
  EXPECT_LT(area_centroid_on_sphere(m, conformal->u).norm(), 1e-6) << "the Moebius balance";
}

TEST(SphericalMap, ConformalMapRefusesASurfaceWithAHandle) {
  const TriMesh m = test::torus(24, 16);
  const auto r = map_to_sphere(m, Eigen::Vector3d::Zero(), {SphereMap::conformal});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("1 handles"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("--map radial"), std::string::npos) << r.error();
  EXPECT_EQ(r.error().find('\n'), std::string::npos);
  EXPECT_TRUE(map_to_sphere(m, Eigen::Vector3d::Zero(), {SphereMap::radial})) << "the radial map takes any surface";
}

TEST(SphericalMap, TheBakeReportsBothMapsSideBySide) {
  LungMesh lung;
  lung.name = "right";
  lung.mesh = bent_bean();
  BakeOptions options;
  options.threads = 2;
  options.transfer_rows = false;
  const auto baked = bake_lungs({lung}, options, nullptr);
  ASSERT_TRUE(baked) << baked.error();
  const BakeReport& r = baked->report;
  EXPECT_EQ(r.map, SphereMap::conformal);
  EXPECT_EQ(r.folded_triangles, 0u);
  ASSERT_EQ(r.maps.size(), 2u);
  EXPECT_EQ(r.maps[1].map, SphereMap::radial);
  EXPECT_GT(r.maps[1].folded_triangles, 100u);
  // Which map fits better depends on the shape (the conformal map crowds long thin ends, the radial one folds
  // hollows): the real lung's figures are checked in mesh_import_test.cpp. Both are measured here.
  EXPECT_GT(r.maps[0].eq7_rms_rel_error, 0);
  EXPECT_GT(r.maps[1].eq7_rms_rel_error, 0);
  ASSERT_EQ(r.per_lung.size(), 1u);
  EXPECT_EQ(r.per_lung[0].folded_triangles, 0u);
  EXPECT_NEAR(r.per_lung[0].eq7_rms_rel_error, r.eq7_rms_rel_error, 1e-12) << "one lung: the same figure";
  ASSERT_EQ(r.bands_sweep.size(), 7u);
  for (const BandsSweepEntry& e : r.bands_sweep) {
    ASSERT_EQ(e.by_map.size(), 2u);
    EXPECT_NEAR(e.by_map[0].eq7_rms_rel_error, e.eq7_rms_rel_error, 1e-15);
  }
}

}  // namespace
}  // namespace lungar::sim
