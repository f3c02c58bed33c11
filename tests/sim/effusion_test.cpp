/// @file effusion_test.cpp
/// @brief A pleural effusion (sim/pathology/effusion.cpp): the lung on its side loses the fluid's volume from its
///        base, its apex stays, it takes less of each breath and the other lung more, it can come and go while the
///        lungs are drawn (its shape is a map of the loaded one), and a spec that cannot be is refused in one line.
#include <gtest/gtest.h>

#include <string>

#include "pathology_test_support.h"
#include "sim/pathology/lung_shapes.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim {
namespace {

/// The lung's lowest and highest rest height (lung frame, +z superior), mm.
std::pair<double, double> heights(const BakedAsset& a, const BakedLung& lung) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    lo = std::min(lo, double{a.positions[3 * i + 2]});
    hi = std::max(hi, double{a.positions[3 * i + 2]});
  }
  return {lo, hi};
}

}  // namespace

TEST(Effusion, TheLungLosesTheFluidsVolumeFromItsBaseAndItsApexStays) {
  const BakedAsset& healthy = test::sliding_asset();
  const std::size_t right = test::index_of(healthy, "right"), left = test::index_of(healthy, "left");
  const test::Sick sick = test::with({"effusion:right:400"});
  const test::Breath before = test::breathe(test::with({}), 500), after = test::breathe(sick, 500);
  // Measured on the surface itself, not on the figures the plug-in set.
  EXPECT_NEAR(before.rest_ml[right] - after.rest_ml[right], 400.0, 0.005 * before.rest_ml[right]);
  EXPECT_NEAR(after.rest_ml[left], before.rest_ml[left], 1e-9) << "the other lung is untouched";
  EXPECT_NEAR(sick.lungs[right].rest_volume_ml, healthy.lungs[right].rest_volume_ml - 400.0, 1e-6);
  const auto [lo, hi] = heights(healthy, healthy.lungs[right]);
  const auto [sick_lo, sick_hi] = heights(sick, sick.lungs[right]);
  EXPECT_NEAR(sick_hi, hi, 1e-3) << "the apex stays";
  EXPECT_NEAR(sick_lo - lo, (hi - lo) * 400.0 / healthy.lungs[right].rest_volume_ml, 0.01) << "the base rises";
  // The compressed base no longer ventilates: the right lung takes less of the breath, the left lung the rest.
  EXPECT_LT(after.change_ml[right], before.change_ml[right] - 10.0);
  EXPECT_GT(after.change_ml[left], before.change_ml[left] + 10.0);
  EXPECT_NEAR(after.change_ml[right] + after.change_ml[left], 500.0, 15.0);
}

TEST(Effusion, ItCanComeAndGoWhileTheLungsAreDrawn) {
  const BakedAsset& healthy = test::sliding_asset();
  const test::Sick sick = test::with({"effusion:left:300"});
  Result<std::vector<LungShape>> shapes = lung_shapes(healthy, sick, sick.patient);
  ASSERT_TRUE(shapes) << shapes.error();
  auto p = parse_pathology("effusion:left:300");
  ASSERT_TRUE(p) << p.error();
  EXPECT_TRUE((*p)->model().may_change_in_a_run());
  for (std::size_t l = 0; l < healthy.lungs.size(); ++l) {
    const BakedLung& lung = healthy.lungs[l];
    EXPECT_LT(test::worst_map_error(healthy, sick, (*shapes)[l].from_loaded, lung), 0.01) << lung.name;
    EXPECT_EQ((*shapes)[l].figures.breath_weight, sick.patient.lungs[l].breath_weight);
  }
}

TEST(Effusion, WhatCannotBeIsRefusedInOneLine) {
  BakedAsset a = test::sliding_asset();
  const BakedAsset untouched = a;
  const std::size_t right = test::index_of(a, "right");
  const std::string too_much =
      "effusion:right:" + std::to_string(static_cast<int>(0.9 * a.lungs[right].rest_volume_ml));
  PatientState patient = PatientState::of(a);
  const Status s = apply_pathologies(a, patient, {too_much});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("'" + too_much + "'"), std::string::npos) << s.error();
  EXPECT_NE(s.error().find("ML: expected at most 80 %"), std::string::npos) << s.error();
  EXPECT_EQ(a.positions, untouched.positions) << "all or nothing";
  const std::pair<const char*, const char*> refused[] = {{"effusion:right", "expected effusion:SIDE:ML"},
                                                         {"effusion:middle:300", "SIDE"},
                                                         {"effusion:right:5", "ML: expected a number from 10 to 5000"},
                                                         {"effusion:right:lots", "ML"}};
  for (const auto& [spec, why] : refused) {
    auto r = parse_pathology(spec);
    ASSERT_FALSE(r) << spec;
    EXPECT_NE(r.error().find(why), std::string::npos) << r.error();
  }
  const Status twice = check_pathologies({"effusion:left:200", "effusion:left:300"});
  ASSERT_FALSE(twice);
  EXPECT_NE(twice.error().find("one effusion a lung"), std::string::npos) << twice.error();
  EXPECT_TRUE(check_pathologies({"effusion:left:200", "effusion:right:300", "pneumothorax:right:20"}));
}

}  // namespace lungar::sim
