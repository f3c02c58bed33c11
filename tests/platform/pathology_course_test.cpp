// A scenario's pathology events as the lungs' course: before, during and after each event, and the events that
// cannot be (a removal of what is not there, a change of response).
#include <gtest/gtest.h>

#include "config/scenario_load.h"
#include "platform/app/pathology_course.h"
#include "sim/bake/bake.h"
#include "sim/pathology/pathology.h"

using namespace lungar;

namespace {

const sim::BakedAsset& healthy() {
  static const sim::BakedAsset a = [] {
    sim::BakeOptions options;
    options.threads = 2;
    options.evaluate = false;
    options.transfer_rows = false;
    return sim::bake_procedural(3000, 7, options, nullptr).take().asset;
  }();
  return a;
}

config::Scenario scenario(const std::string& events) {
  Result<config::Scenario> s = config::load_scenario_from_string("duration_s = 60.0\n" + events, "s.toml");
  EXPECT_TRUE(s) << s.error();
  return s.take();
}

std::size_t right_of(const sim::BakedAsset& a) { return a.lungs[0].name == "right" ? 0 : 1; }

TEST(PathologyCourse, ATensionPneumothoraxComesThenANeedleLetsItGo) {
  const config::Scenario s = scenario(
      "[[event]]\nat_s = 10.0\nkind = \"pathology\"\nadd = \"pneumothorax:right:40:tension\"\nover_s = 10.0\n"
      "[[event]]\nat_s = 30.0\nkind = \"pathology\"\nremove = \"pneumothorax:right:40:tension\"\nover_s = 20.0\n");
  std::vector<std::string> lines;
  auto course = platform::PathologyCourse::create(healthy(), healthy(), {}, s, [&](const std::string& l) {
    lines.push_back(l);
  });
  ASSERT_TRUE(course) << course.error();
  ASSERT_TRUE(*course);
  EXPECT_EQ(lines.size(), 2u);
  const std::size_t right = right_of(healthy());
  sim::BakedAsset sick = healthy();
  ASSERT_TRUE(sim::apply_pathologies(sick, {"pneumothorax:right:40:tension"}));
  auto weight = [&](double t) { return (*course)->at_seconds(t)[right].figures.breath_weight; };
  auto centre_x = [&](double t) { return double{(*course)->at_seconds(t)[right].figures.centre[0]}; };
  EXPECT_EQ(weight(5.0), 1.0) << "healthy before";
  EXPECT_TRUE((*course)->at_seconds(5.0)[right].from_loaded.isApprox(Eigen::Affine3d::Identity(), 1e-9));
  EXPECT_GT(weight(15.0), sim::kCollapsedLungBreathWeight);
  EXPECT_LT(weight(15.0), 1.0) << "collapsing";
  EXPECT_NEAR(weight(25.0), sim::kCollapsedLungBreathWeight, 1e-12) << "collapsed";
  EXPECT_NEAR(centre_x(25.0), sick.lungs[right].centre[0], 1e-3) << "the mediastinum pushed over";
  EXPECT_GT(centre_x(12.0), centre_x(11.0)) << "moving while it comes";
  EXPECT_LT(centre_x(12.0), centre_x(25.0));
  EXPECT_LT(centre_x(40.0), centre_x(25.0)) << "re-expanding after the needle";
  EXPECT_EQ(weight(55.0), 1.0) << "healthy again";
  EXPECT_NEAR(centre_x(55.0), healthy().lungs[right].centre[0], 1e-3);
}

TEST(PathologyCourse, WhatCannotComeOrGoIsRefusedNamingTheEvent) {
  auto refused = [](const std::string& events, const std::vector<std::string>& start, const char* why) {
    auto course = platform::PathologyCourse::create(healthy(), healthy(), start, scenario(events), nullptr);
    ASSERT_FALSE(course) << events;
    EXPECT_NE(course.error().find(why), std::string::npos) << course.error();
    EXPECT_NE(course.error().find("event[0]"), std::string::npos) << course.error();
  };
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nremove = \"pneumothorax:left:20\"\nover_s = 5.0\n", {},
          "is not present");
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nadd = \"consolidation:left:lower\"\nover_s = 5.0\n", {},
          "give a consolidation or ARDS in its pathology list");
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nadd = \"pneumothorax:centre:20\"\nover_s = 5.0\n", {}, "SIDE");
  auto none = platform::PathologyCourse::create(healthy(), healthy(), {}, scenario(""), nullptr);
  ASSERT_TRUE(none);
  EXPECT_FALSE(*none) << "no event, no course";
}

}  // namespace
