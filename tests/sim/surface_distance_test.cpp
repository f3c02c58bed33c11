/// @file surface_distance_test.cpp
/// @brief The Hausdorff distance of the bake report: zero for a surface against itself, the gap between two
///        concentric spheres, and the one vertex pulled out of a surface, both ways round.
#include <gtest/gtest.h>

#include "sim/mesh/surface_distance.h"
#include "test_meshes.h"

namespace lungar::sim {
namespace {

TEST(SurfaceDistance, HausdorffOfConcentricSpheresAndOfAPulledVertex) {
  const TriMesh a = test::uv_sphere(30, 40, [](const Eigen::Vector3d& p) { return 50 * p; });
  const TriMesh b = test::uv_sphere(17, 23, [](const Eigen::Vector3d& p) { return 53 * p; });
  EXPECT_EQ(hausdorff_mm(a, a, 2), 0.0);
  // From b's vertices the nearest point of a is about 3 mm in (a's flat triangles sit a little inside r = 50).
  EXPECT_NEAR(hausdorff_mm(a, b, 2), 3.0, 0.6);
  TriMesh pulled = a;
  pulled.positions[500] *= 1.2;  // 10 mm out
  EXPECT_NEAR(hausdorff_mm(a, pulled, 1), 10.0, 0.5) << "a's farthest point from pulled's surface";
  EXPECT_NEAR(hausdorff_mm(pulled, a, 2), hausdorff_mm(a, pulled, 2), 1e-12) << "symmetric";
}

}  // namespace
}  // namespace lungar::sim
