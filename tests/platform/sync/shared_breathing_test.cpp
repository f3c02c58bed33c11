// The trainee's breathing clock: the instructor's driver rebuilt from start and events, evaluated on the
// instructor's time base through the applied offset, which steps on large changes and smooths small ones.
#include <gtest/gtest.h>

#include "drivers/classroom/shared_breathing.h"

using namespace lungar;
using namespace lungar::classroom;

namespace {
constexpr std::int64_t kBase = 1'700'000'000'000'000'000;

std::vector<sim::Event> scenario() {
  sim::PatternChange faster;
  faster.rate_bpm = 20.0;
  return {sim::Event::set(6.0, faster), sim::Event::sigh(15.0)};
}
}  // namespace

TEST(SharedBreathing, TheRebuiltDriverIsTheInstructors) {
  sim::BreathingParams start;
  start.tidal_volume_ml = 450.0;
  auto instructor = sim::BreathingDriver::create(start);
  ASSERT_TRUE(instructor);
  for (const auto& e : scenario()) ASSERT_TRUE(instructor->apply(e));
  auto rebuilt = SharedBreathing::build(start, scenario());
  ASSERT_TRUE(rebuilt) << rebuilt.error();
  for (double t : {0.0, 3.3, 7.1, 12.0, 16.4, 30.0}) {
    EXPECT_DOUBLE_EQ(rebuilt->at(t).dv_ml, instructor->at(t).dv_ml) << "t = " << t;
  }
}

TEST(SharedBreathing, AnEventTheDriverRefusesNamesItsIndex) {
  sim::PatternChange too_deep;
  too_deep.tidal_volume_ml = 2900.0;  // beyond the fibrotic curve's reach
  sim::BreathingParams start;
  start.preset = sim::Preset::Fibrosis;
  auto r = SharedBreathing::build(start, std::vector<sim::Event>{sim::Event::sigh(1.0), sim::Event::set(4.0, too_deep)});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("lungar_scenario_events: events[1]"), std::string::npos) << r.error();
}

TEST(SharedBreathing, BreathingTimeIsTheInstructorsThroughTheOffset) {
  SharedBreathing b;
  sim::BreathingSample s;
  EXPECT_FALSE(b.sample_at(kBase, s));
  auto driver = SharedBreathing::build({}, scenario());
  ASSERT_TRUE(driver);
  b.install(driver.take(), kBase);
  // This station's clock is 250 ms behind the instructor's: its 1.75 s after the base is the instructor's 2 s.
  b.update_offset(250'000'000);
  ASSERT_TRUE(b.sample_at(kBase + 1'750'000'000, s));
  EXPECT_NEAR(s.t_s, 2.0, 1e-9);
  auto reference = SharedBreathing::build({}, scenario());
  EXPECT_DOUBLE_EQ(s.dv_ml, reference->at(2.0).dv_ml);
}

TEST(SharedBreathing, TheAppliedOffsetStepsOnJumpsAndSmoothsJitter) {
  SharedBreathing b;
  b.update_offset(-80'000'000);  // the first estimate is taken whole
  EXPECT_EQ(b.applied_offset_ns(), -80'000'000);
  b.update_offset(-80'000'000 + 400'000);  // 0.4 ms of jitter: a quarter of it
  EXPECT_EQ(b.applied_offset_ns(), -80'000'000 + 100'000);
  b.update_offset(-80'000'000 + 100'000 + 2 * SharedBreathing::kStepNs);  // a restarted instructor: whole
  EXPECT_EQ(b.applied_offset_ns(), -80'000'000 + 100'000 + 2 * SharedBreathing::kStepNs);
}
