/// @file voxel_surface_test.cpp
/// @brief Label-map masks to lung surfaces, without files: simple points, stray islands dropped, cavities and
///        tunnels closed in voxel space (genus 0 where the raw mask has a handle), marching tetrahedra closed,
///        outward and accurate (volume, centroid), mirrored voxel frames, and the vertex count asked for.
#include <gtest/gtest.h>

#include <numbers>

#include "sim/mesh/mesh_repair.h"
#include "sim/mesh/spherical_map.h"
#include "sim/voxel/freudenthal.h"
#include "sim/voxel/label_surface.h"
#include "sim/voxel/marching_tetrahedra.h"
#include "sim/voxel/mask_topology.h"

namespace lungar::sim {
namespace {

/// A mask of n^3 voxels of `mm` each, inside where `inside(x)` holds for the voxel's centre (mm, LPS).
VoxelMask mask_of(int n, double mm, const std::function<bool(const Eigen::Vector3d&)>& inside) {
  VoxelMask m;
  m.grid.size = {n, n, n};
  m.grid.axes = Eigen::Matrix3d::Identity() * mm;
  m.grid.origin = Eigen::Vector3d::Constant(-mm * (n - 1) / 2.0);
  m.inside.resize(static_cast<std::size_t>(m.grid.count()));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        m.inside[static_cast<std::size_t>(m.grid.index(i, j, k))] = inside(m.grid.point(Eigen::Vector3d(i, j, k)));
  return m;
}

/// A solid torus about z (radii 12 and 5 mm): one handle.
bool in_torus(const Eigen::Vector3d& p) {
  const double ring = std::hypot(p.x(), p.y()) - 12;
  return ring * ring + p.z() * p.z() < 25;
}

/// The marching-tetrahedra surface of a binary mask as it is (no repair).
TriMesh raw_surface(const VoxelMask& m) {
  std::vector<float> f(m.inside.size());
  for (std::size_t v = 0; v < f.size(); ++v) f[v] = m.inside[v] ? 0.5f : -0.5f;
  return marching_tetrahedra(m.grid, f);
}

/// Whether `m` is one closed, 2-manifold, outward component (sim's own mesh check).
bool closed_manifold(const TriMesh& m) {
  std::vector<std::string> notes;
  const auto parts = repair_surface(m, "test", notes);
  return parts && parts->size() == 1 && notes.empty();
}

TEST(VoxelTopology, SimplePointsFollowTheLink) {
  EXPECT_FALSE(is_simple_point(0)) << "an isolated point: removing it deletes a component";
  EXPECT_FALSE(is_simple_point(0x3fff)) << "a point walled in: adding it fills a cavity";
  EXPECT_TRUE(is_simple_point(1)) << "a point with one inside neighbour: the end of a line";
  EXPECT_FALSE(is_simple_point(0b11)) << "+x and -x only: the middle of a line cannot go";
}

TEST(VoxelTopology, RawTorusHasAHandleAndTheClosingMakesItABall) {
  VoxelMask m = mask_of(44, 1.0, in_torus);
  const TriMesh raw = raw_surface(m);
  ASSERT_TRUE(closed_manifold(raw));
  EXPECT_EQ(euler_characteristic(raw), 0) << "marching tetrahedra keeps the handle of the raw mask";
  const MaskTopologyRepair r = close_to_ball(m);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.removed_voxels, 0);
  EXPECT_GT(r.filled_voxels, 0);
  const double hole = std::numbers::pi * 7 * 7 * 10;  // the ring's hole: radius 12 - 5 mm, as high as the ring
  EXPECT_LT(r.filled_voxels, 1.2 * hole) << "the hole is filled, nothing around it";
  const TriMesh closed = raw_surface(m);
  ASSERT_TRUE(closed_manifold(closed));
  EXPECT_EQ(euler_characteristic(closed), 2);
}

TEST(VoxelTopology, StrayIslandsGoAndCavitiesFill) {
  VoxelMask m = mask_of(40, 1.0, [](const Eigen::Vector3d& p) {
    const double r = p.norm();
    const bool shell = r < 14 && r > 6;              // a ball with a cavity of radius 6 mm
    const bool island = (p - Eigen::Vector3d(16, 16, 16)).norm() < 2.5;
    return shell || island;
  });
  const MaskTopologyRepair r = close_to_ball(m);
  EXPECT_EQ(r.components, 2);
  EXPECT_GT(r.removed_voxels, 20);
  EXPECT_NEAR(static_cast<double>(r.filled_voxels), 4.0 / 3.0 * std::numbers::pi * 216, 150) << "the cavity, filled";
  EXPECT_EQ(count_components(m), 1);
  EXPECT_EQ(euler_characteristic(raw_surface(m)), 2);
}

TEST(LabelSurface, EllipsoidComesOutClosedOutwardAndAccurate) {
  const Eigen::Vector3d half(30, 22, 45);
  VoxelMask m = mask_of(100, 1.0, [&](const Eigen::Vector3d& p) { return p.cwiseQuotient(half).squaredNorm() < 1; });
  const double exact = 4.0 / 3.0 * std::numbers::pi * half.prod();
  for (std::uint32_t target : {0u, 8000u}) {
    const auto s = label_surface(m, target);
    ASSERT_TRUE(s) << s.error();
    ASSERT_TRUE(closed_manifold(s->mesh)) << target;
    EXPECT_EQ(euler_characteristic(s->mesh), 2);
    EXPECT_NEAR(enclosed_volume(s->mesh) / exact, 1.0, 0.02) << target;
    EXPECT_LT(volume_centroid(s->mesh).norm(), 0.3) << target;
    if (target > 0) {
      EXPECT_GE(s->mesh.positions.size(), target) << "the working grid is corrected to reach the count";
      EXPECT_LE(s->mesh.positions.size(), 1.05 * target);
      EXPECT_GT(s->grid_mm, 1.0) << "a coarser grid than the mask's for fewer vertices";
    }
  }
}

TEST(LabelSurface, MirroredVoxelFrameStillFacesOutward) {
  VoxelMask m = mask_of(30, 1.0, [](const Eigen::Vector3d& p) { return p.norm() < 11; });
  m.grid.axes(0, 0) = -1.0;  // i runs towards -x, as in a map stored right to left
  const auto s = label_surface(m, 0);
  ASSERT_TRUE(s) << s.error();
  EXPECT_NEAR(enclosed_volume(s->mesh) / (4.0 / 3.0 * std::numbers::pi * 1331), 1.0, 0.03);
}

TEST(LabelSurface, AMaskThinnerThanTheGridIsOneClearError) {
  VoxelMask m = mask_of(20, 1.0, [](const Eigen::Vector3d& p) { return p.norm() < 0.8; });  // one voxel
  const auto s = label_surface(m, 50000);
  ASSERT_FALSE(s) << "a single voxel is no lung";
  EXPECT_NE(s.error().find("expected a lung"), std::string::npos) << s.error();
}

}  // namespace
}  // namespace lungar::sim
