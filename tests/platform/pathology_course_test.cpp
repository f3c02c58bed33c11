// A scenario's pathology events as the lungs' course: before, during and after each event, and the events that
// cannot be (a removal of what is not there, a change of response).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "config/scenario_load.h"
#include "platform/runtime/pathology_course.h"
#include "sim/bake/bake.h"
#include "sim/force/dependent_collapse.h"
#include "sim/pathology/pathology.h"

using namespace lungar;

namespace {

/// A collapsed lung's weight in the split of the breath (sim/pathology/pneumothorax.cpp).
constexpr double kPneumothoraxBreathWeight = 0.05;

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
  const sim::PathologyTimeline timeline = platform::timeline_of({}, &s);
  EXPECT_EQ(sim::describe(timeline),
            "healthy, then pneumothorax:right:40:tension comes at 10.0 s over 10.0 s, then "
            "pneumothorax:right:40:tension goes at 30.0 s over 20.0 s");
  auto course = platform::PathologyCourse::create(healthy(), healthy(), timeline);
  ASSERT_TRUE(course) << course.error();
  ASSERT_TRUE(*course);
  const auto present = [&](double t) {
    (*course)->at_seconds(t);
    nlohmann::json j;
    (*course)->add_stats(j);
    return j["pathologies"].get<std::vector<std::string>>();
  };
  const auto changing = [&](double t) {
    (*course)->at_seconds(t);
    nlohmann::json j;
    (*course)->add_stats(j);
    return j["pathologies_changing"].get<std::vector<std::string>>();
  };
  const auto shown = [&](double t) {
    (*course)->at_seconds(t);
    return *(*course)->pathologies_now();
  };
  const std::vector<std::string> ptx{"pneumothorax:right:40:tension"};
  EXPECT_TRUE(present(5.0).empty()) << "not yet";
  EXPECT_EQ(shown(5.0), "none");
  EXPECT_EQ(present(15.0), ptx) << "coming: it shows from its onset";
  EXPECT_EQ(changing(15.0), ptx);
  EXPECT_EQ(shown(15.0), "pneumothorax:right:40:tension (coming)");
  EXPECT_EQ(present(25.0), ptx);
  EXPECT_TRUE(changing(25.0).empty());
  EXPECT_EQ(shown(25.0), "pneumothorax:right:40:tension");
  EXPECT_EQ(present(45.0), ptx) << "going";
  EXPECT_EQ(changing(45.0), ptx);
  EXPECT_EQ(shown(45.0), "pneumothorax:right:40:tension (going)");
  EXPECT_TRUE(present(55.0).empty()) << "gone";
  EXPECT_EQ(shown(55.0), "none");
  const std::size_t right = right_of(healthy());
  sim::BakedAsset sick = healthy();
  sim::PatientState sick_patient = sim::PatientState::of(sick);
  ASSERT_TRUE(sim::apply_pathologies(sick, sick_patient, {"pneumothorax:right:40:tension"}));
  auto weight = [&](double t) { return (*course)->at_seconds(t)[right].figures.breath_weight; };
  auto centre_x = [&](double t) { return double{(*course)->at_seconds(t)[right].figures.centre[0]}; };
  EXPECT_EQ(weight(5.0), 1.0) << "healthy before";
  EXPECT_TRUE((*course)->at_seconds(5.0)[right].from_loaded.isApprox(Eigen::Affine3d::Identity(), 1e-9));
  EXPECT_GT(weight(15.0), kPneumothoraxBreathWeight);
  EXPECT_LT(weight(15.0), 1.0) << "collapsing";
  EXPECT_NEAR(weight(25.0), kPneumothoraxBreathWeight, 1e-12) << "collapsed";
  EXPECT_NEAR(centre_x(25.0), sick.lungs[right].centre[0], 1e-3) << "the mediastinum pushed over";
  EXPECT_GT(centre_x(12.0), centre_x(11.0)) << "moving while it comes";
  EXPECT_LT(centre_x(12.0), centre_x(25.0));
  EXPECT_LT(centre_x(40.0), centre_x(25.0)) << "re-expanding after the needle";
  EXPECT_EQ(weight(55.0), 1.0) << "healthy again";
  EXPECT_NEAR(centre_x(55.0), healthy().lungs[right].centre[0], 1e-3);
}

TEST(PathologyCourse, WhatCannotComeOrGoIsRefusedNamingTheEvent) {
  auto refused = [](const std::string& events, const std::vector<std::string>& start, const char* why) {
    const config::Scenario s = scenario(events);
    auto course = platform::PathologyCourse::create(healthy(), healthy(), platform::timeline_of(start, &s));
    ASSERT_FALSE(course) << events;
    EXPECT_NE(course.error().find(why), std::string::npos) << course.error();
    EXPECT_NE(course.error().find("pathology event 1"), std::string::npos) << course.error();
  };
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nremove = \"pneumothorax:left:20\"\nover_s = 5.0\n", {},
          "is not present");
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nadd = \"consolidation:left:lower\"\nover_s = 5.0\n", {},
          "(a consolidation) must be the drawn lungs' own");
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nadd = \"ards:0.5\"\nover_s = 5.0\n", {},
          "'ards' cannot come or go during a run");
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nadd = \"pneumothorax:centre:20\"\nover_s = 5.0\n", {}, "SIDE");
  refused("[[event]]\nat_s = 1.0\nkind = \"pathology\"\nadd = \"pneumothorax:right:40:tension\"\nover_s = 5.0\n",
          {"pneumothorax:right:20"}, "repeats 'pneumothorax:right:20'");
}

TEST(PathologyCourse, StartsFromLungsDrawnOtherwiseAndTakesAnArdsFromTheStart) {
  // A classroom's trainee draws its own lungs (healthy here) and takes the instructor's: a right pneumothorax and
  // an ARDS from the start. The pneumothorax is a map of the drawn lungs, the ARDS their force's collapse.
  const sim::PathologyTimeline instructor{{"pneumothorax:right:30", "ards:0.6"}, {}};
  sim::BakedAsset drawn = healthy();
  sim::PatientState drawn_patient = sim::PatientState::of(drawn);
  ASSERT_TRUE(sim::apply_pathologies(drawn, drawn_patient, {"emphysema:0.5"}));  // the trainee's own, overruled
  auto course = platform::PathologyCourse::create(healthy(), drawn, instructor);
  ASSERT_TRUE(course) << course.error();
  sim::BakedAsset sick = healthy();
  sim::PatientState sick_patient = sim::PatientState::of(sick);
  ASSERT_TRUE(sim::apply_pathologies(sick, sick_patient, instructor.start));
  const std::size_t right = right_of(healthy());
  const auto& now = (*course)->at_seconds(1.0);
  EXPECT_NEAR(now[right].figures.rest_volume_ml, sick.lungs[right].rest_volume_ml, 1e-6);
  ASSERT_TRUE(now[right].figures.collapse) << "the ARDS's collapse goes with the figures";
  EXPECT_DOUBLE_EQ(now[right].figures.collapse->severity(), 0.6);
  const std::size_t i = drawn.lungs[right].first_vertex + 10;
  const Eigen::Vector3d from(drawn.positions[3 * i], drawn.positions[3 * i + 1], drawn.positions[3 * i + 2]);
  const Eigen::Vector3d to(sick.positions[3 * i], sick.positions[3 * i + 1], sick.positions[3 * i + 2]);
  EXPECT_LT((now[right].from_loaded * from - to).norm(), 0.05) << "mapped from the emphysema to the pneumothorax";
  sim::BakedAsset consolidated = healthy();
  sim::PatientState consolidated_patient = sim::PatientState::of(consolidated);
  ASSERT_TRUE(sim::apply_pathologies(consolidated, consolidated_patient, {"consolidation:left:lower"}));
  auto refused = platform::PathologyCourse::create(healthy(), consolidated, instructor);
  ASSERT_FALSE(refused) << "the drawn lungs' consolidation is baked into their response";
  EXPECT_NE(refused.error().find("pathology at the start"), std::string::npos) << refused.error();
}

}  // namespace

TEST(PathologyCourse, AChangeMadeBeforeTheLastEndedGoesOnFromWhereTheLungsAreWithoutAJump) {
  // An instructor drops a pneumothorax over 10 s and, 4 s in, makes it larger over 5 s (one event replacing it):
  // the lungs go on from the part-collapsed state, never back to the start or ahead to the first one's end.
  const sim::PathologyTimeline timeline{
      {}, {{10.0, 10.0, "pneumothorax:right:20", ""}, {14.0, 5.0, "pneumothorax:right:50", "pneumothorax:right:20"}}};
  ASSERT_TRUE(sim::check_timeline(timeline)) << sim::check_timeline(timeline).error();
  EXPECT_EQ(sim::present_after(timeline, 2), std::vector<std::string>{"pneumothorax:right:50"});
  auto course = platform::PathologyCourse::create(healthy(), healthy(), timeline);
  ASSERT_TRUE(course) << course.error();
  const std::size_t right = right_of(healthy());
  const auto volume = [&](double t) { return (*course)->at_seconds(t)[right].figures.rest_volume_ml; };
  double largest_step = 0;
  for (double t = 9.0; t < 21.0; t += 0.01)
    largest_step = std::max(largest_step, std::abs(volume(t + 0.01) - volume(t)));
  const double swing = volume(9.0) - volume(20.0);
  ASSERT_GT(swing, 100.0) << "the lung collapses by half";
  EXPECT_LT(largest_step, 0.01 * swing) << "no jump when the second change starts or the first would have ended";
  EXPECT_LT(volume(15.0), volume(14.0)) << "the second change goes on collapsing it";
  nlohmann::json j;
  (*course)->at_seconds(16.0);
  (*course)->add_stats(j);
  EXPECT_EQ(j["pathologies"], (std::vector<std::string>{"pneumothorax:right:20", "pneumothorax:right:50"}))
      << "while one becomes the other, both show, as a pathology coming or going does";
  (*course)->at_seconds(19.5);
  (*course)->add_stats(j);
  EXPECT_EQ(j["pathologies"], (std::vector<std::string>{"pneumothorax:right:50"}));
}
