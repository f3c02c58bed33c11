/// @file lung_shapes_test.cpp
/// @brief A tension pneumothorax's mediastinal shift, and the per-lung maps a scenario blends a pathology in and
///        out with (sim/pathology/lung_shapes.h).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/force/dependent_collapse.h"
#include "sim/pathology/lung_shapes.h"
#include "sim/pathology/pathology.h"
#include "pathology_test_support.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::with;
using test::kCollapsedLungBreathWeight;
using test::kTensionShiftMm;
using test::index_of;



std::pair<double, double> x_range(const BakedAsset& a, const BakedLung& lung) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    lo = std::min(lo, double{a.positions[3 * i]});
    hi = std::max(hi, double{a.positions[3 * i]});
  }
  return {lo, hi};
}

TEST(TensionPneumothorax, TheMediastinumMovesOverAndPressesTheOtherLungFromItsMedialSide) {
  const test::Sick plain = with({"pneumothorax:right:40"}), tension = with({"pneumothorax:right:40:tension"});
  const std::size_t right = index_of(plain, "right"), left = index_of(plain, "left");
  // LPS: +x is the patient's left. The collapsed right lung moves towards the left by the shift.
  EXPECT_NEAR(tension.lungs[right].centre[0] - plain.lungs[right].centre[0], kTensionShiftMm, 1e-3);
  EXPECT_NEAR(tension.lungs[right].rest_volume_ml, plain.lungs[right].rest_volume_ml, 1e-9);
  // The left lung's medial face (its low x) moves over by the shift; its lateral face stays on the ribs.
  const auto [plain_lo, plain_hi] = x_range(plain, plain.lungs[left]);
  const auto [tension_lo, tension_hi] = x_range(tension, tension.lungs[left]);
  EXPECT_NEAR(tension_lo - plain_lo, kTensionShiftMm, 0.01);
  EXPECT_NEAR(tension_hi, plain_hi, 0.01);
  const double k = 1.0 - kTensionShiftMm / (plain_hi - plain_lo);
  EXPECT_NEAR(tension.lungs[left].rest_volume_ml / plain.lungs[left].rest_volume_ml, k, 1e-9);
  EXPECT_LT(tension.lungs[left].volume_const, plain.lungs[left].volume_const) << "a pressed lung sweeps less";
  auto p = parse_pathology("pneumothorax:right:40:tension");
  ASSERT_TRUE(p) << p.error();
  EXPECT_EQ((*p)->side(), "right");
  auto bad = parse_pathology("pneumothorax:right:40:tight");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find(":tension"), std::string::npos) << bad.error();
}

TEST(LungShapes, EachLungsNewShapeIsAMapOfItsLoadedOneAndTheBlendGoesBetween) {
  const BakedAsset& healthy = test::sliding_asset();
  const test::Sick sick = with({"pneumothorax:right:40:tension"});
  Result<std::vector<LungShape>> shapes = lung_shapes(healthy, sick, sick.patient);
  ASSERT_TRUE(shapes) << shapes.error();
  for (std::size_t l = 0; l < healthy.lungs.size(); ++l) {
    const BakedLung& lung = healthy.lungs[l];
    EXPECT_LT(test::worst_map_error(healthy, sick, (*shapes)[l].from_loaded, lung), 0.01) << lung.name;
    EXPECT_EQ((*shapes)[l].figures.breath_weight, sick.patient.lungs[l].breath_weight);
    EXPECT_EQ((*shapes)[l].figures.volume_const, sick.lungs[l].volume_const) << "the shape's figures follow it";
  }
  const std::vector<LungShape> same = lung_shapes(healthy, healthy, PatientState::of(healthy)).take();
  const std::vector<LungShape> half = blend(same, *shapes, 0.5);
  const std::size_t right = index_of(healthy, "right");
  // Every coordinate of the centre blends; the collapse moved z (and x) by millimetres, so one left out shows.
  EXPECT_GT(std::abs(sick.lungs[right].centre[2] - healthy.lungs[right].centre[2]), 0.5);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(half[right].figures.centre[k], 0.5 * (healthy.lungs[right].centre[k] + sick.lungs[right].centre[k]),
                1e-3)
        << k;
  }
  EXPECT_NEAR(half[right].figures.breath_weight, 0.5 * (1.0 + kCollapsedLungBreathWeight), 1e-9);
  EXPECT_TRUE(blend(same, *shapes, 1.0)[right].from_loaded.isApprox((*shapes)[right].from_loaded));
  EXPECT_TRUE(blend(same, *shapes, 0.0)[right].from_loaded.isApprox(Eigen::Affine3d::Identity(), 1e-9));
}

TEST(LungShapes, AChangeOfResponseIsRefusedByLungAndArdsRidesWithTheFigures) {
  const BakedAsset& healthy = test::sliding_asset();
  const test::Sick consolidated = with({"consolidation:left:lower"});
  Result<std::vector<LungShape>> c = lung_shapes(healthy, consolidated, consolidated.patient);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().find("lung 'left'"), std::string::npos) << c.error();
  // ARDS changes the force, not the response: its collapse goes with the figures (a trainee takes it so).
  const test::Sick sick = with({"ards:0.5", "pneumothorax:right:20"});
  Result<std::vector<LungShape>> ards = lung_shapes(healthy, sick, sick.patient);
  ASSERT_TRUE(ards) << ards.error();
  for (const LungShape& lung : *ards) {
    ASSERT_TRUE(lung.figures.collapse);
    EXPECT_DOUBLE_EQ(lung.figures.collapse->severity(), 0.5);
  }
  EXPECT_FALSE((*ards)[0].figures.collapse_index == (*ards)[1].figures.collapse_index) << "each lung its own index";
}

}  // namespace
}  // namespace lungar::sim
