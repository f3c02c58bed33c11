/// @file lesion_rows_test.cpp
/// @brief A lesion's own rows (sim/motion/lesion_rows.h) move it exactly as the interior field moves its centre, in
///        every posture; its surface weights are harmonic coordinates (they sum to 1, none below 0); and the run's
///        excursion (sim/motion/excursion_tracker.h) is exact for a straight path and close for a curved one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pathology_test_support.h"
#include "tests/lung_axis.h"
#include "sim/force/breath_share.h"
#include "sim/force/force_sh.h"
#include "sim/motion/excursion_tracker.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion_rows.h"
#include "sim/motion/motion_figures.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::sliding_asset;

const InteriorDisplacement& rows_field() {
  static const InteriorDisplacement f(sliding_asset());
  return f;
}

/// A lesion 8 mm across, `up` of the way from the lung's lowest inside point to its highest on the vertical
/// through its vertices' centroid.
PlacedLesion lesion_at(std::size_t lung_index, double up) {
  const testing::LungAxis axis = testing::lung_axis(sliding_asset(), rows_field(), lung_index);
  EXPECT_LT(axis.low_z, axis.high_z);
  const Lesion l{"l" + std::to_string(lung_index), axis.at(up), 4.0};
  Result<std::vector<PlacedLesion>> placed = place_lesions(rows_field(), {l});
  EXPECT_TRUE(placed) << (placed ? "" : placed.error());
  return placed ? placed->front() : PlacedLesion{l, lung_index};
}

TEST(LesionRows, SurfaceWeightsSumToOneAndNoneIsNegative) {
  for (std::size_t l = 0; l < sliding_asset().lungs.size(); ++l)
    for (double up : {0.15, 0.5, 0.85}) {
      const PlacedLesion p = lesion_at(l, up);
      const std::vector<VertexWeight> w = rows_field().surface_weights(p.lesion.centre_mm, p.lung);
      double sum = 0, least = 1;
      for (const VertexWeight& e : w) {
        sum += e.weight;
        least = std::min(least, e.weight);
        const BakedLung& lung = sliding_asset().lungs[l];
        ASSERT_GE(e.vertex, lung.first_vertex);
        ASSERT_LT(e.vertex, lung.first_vertex + lung.vertex_count) << "a weight on the other lung's vertex";
      }
      EXPECT_NEAR(sum, 1.0, 1e-5) << "lung " << l << " at " << up;
      EXPECT_GT(least, -1e-6) << "lung " << l << " at " << up;
      EXPECT_GT(w.size(), 20u) << "a point inside is moved by many vertices, not one";
    }
}

TEST(LesionRows, MoveTheLesionAsTheInteriorFieldMovesItsCentreInEveryPosture) {
  const BakedAsset& a = sliding_asset();
  const PatientState patient = PatientState::of(a);
  std::vector<PlacedLesion> lesions;
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    for (double up : {0.15, 0.5, 0.85}) lesions.push_back(lesion_at(l, up));
  const std::vector<LesionRows> rows = lesion_rows(a, rows_field(), lesions);
  ASSERT_EQ(rows.size(), lesions.size());
  const InteriorPoints centres = lesion_centres(lesions);
  const std::uint32_t c = a.coefficients();
  for (const Eigen::Vector3d& g : {test::kSupine, test::kLeftSideDown, Eigen::Vector3d(0, 0, -1)}) {
    const std::vector<float> surface = displacement_vectors(a, patient, g, 500.0);
    const std::vector<float> expected = rows_field().displacement(surface, centres);
    std::vector<float> force(c);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::size_t l = rows[k].placed.lung;
      force_sh_exact(a, a.lungs[l], patient.lungs[l], g, force.data());
      const Eigen::Vector3d d =
          rows[k].displacement(force, linear_weights(a, patient.lungs[l], g), 500.0 * breath_share(a, patient, l, g));
      const Eigen::Vector3d want(expected[3 * k], expected[3 * k + 1], expected[3 * k + 2]);
      EXPECT_LT((d - want).norm(), 0.01 + 0.002 * want.norm())
          << rows[k].placed.lesion.name << " g " << g.transpose() << ": rows " << d.transpose() << ", field "
          << want.transpose();
      EXPECT_GT(want.norm(), 0.05) << "the case moves the lesion";
    }
  }
}

TEST(PlaceLesions, ABallThatReachesOutAlongAnyOneAxisIsRefusedAndOneThatFitsIsKept) {
  const BakedAsset& a = sliding_asset();
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    const Eigen::Vector3d middle = testing::lung_axis(a, rows_field(), l).at(0.5);
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {-1.0, 1.0}) {
        Eigen::Vector3d u = Eigen::Vector3d::Zero();
        u[axis] = sign;
        // Out from the middle along u to the surface, then 3 mm back in: a 4 mm ball there pokes 1 mm out along u
        // alone (its points along the diagonals next to u reach 2.8 mm along it, not out), a 2 mm one fits.
        double out = 0;
        while (rows_field().lung_containing(middle + out * u) == static_cast<int>(l) && out < 400) out += 0.25;
        const Eigen::Vector3d centre = middle + (out - 3.0) * u;
        const std::string where = a.lungs[l].name + " along " + std::to_string(sign * (axis + 1));
        const auto big = place_lesions(rows_field(), {{"big", centre, 4.0}});
        ASSERT_FALSE(big) << where << ": a ball reaching 3 mm out of its lung was kept";
        EXPECT_NE(big.error().find("reaches out of its lung"), std::string::npos) << big.error();
        const auto small = place_lesions(rows_field(), {{"small", centre, 2.0}});
        EXPECT_TRUE(small) << where << ": " << (small ? "" : small.error());
        // A segmented lesion (from a label) is checked at its centre only: the lung was meshed round its voxels.
        EXPECT_TRUE(place_lesions(rows_field(), {{"segmented", centre, 4.0, true}})) << where;
      }
  }
}

TEST(ExcursionTracker, IsExactAlongALineAndCloseOnACircle) {
  ExcursionTracker line;
  EXPECT_EQ(line.peak_to_peak_mm(), 0.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 2.0);
  for (int i = 0; i <= 100; ++i) line.add(axis * std::cos(std::numbers::pi * i / 10));  // breaths on one line
  EXPECT_NEAR(line.peak_to_peak_mm(), 2 * axis.norm(), 1e-3);
  EXPECT_NEAR(line.si_mm(), 4.0, 1e-3);
  // A circle of radius 5 in a tilted plane: the true peak-to-peak is its diameter, 10.
  ExcursionTracker circle;
  const Eigen::Vector3d u = Eigen::Vector3d(1, 2, 0.5).normalized();
  const Eigen::Vector3d v = u.cross(Eigen::Vector3d(0.2, -0.4, 1)).normalized();
  for (int i = 0; i < 720; ++i) {
    const double t = i * std::numbers::pi / 360;
    circle.add(5 * (std::cos(t) * u + std::sin(t) * v));
  }
  EXPECT_LE(circle.peak_to_peak_mm(), 10.0 + 1e-9);
  EXPECT_GE(circle.peak_to_peak_mm(), 0.88 * 10.0);
  EXPECT_EQ(circle.positions(), 720);
}

}  // namespace
}  // namespace lungar::sim
