// How long a run lasts: a scenario runs for its own length unless --seconds says otherwise, and the log says which.
#include <gtest/gtest.h>

#include "platform/app/run_limit.h"

using lungar::config::Scenario;
using lungar::platform::describe_limit;
using lungar::platform::run_limit_s;
using lungar::platform::RuntimeOptions;

namespace {

Scenario lesson(double duration_s) {
  Scenario sc;
  sc.source = "ards-proning.toml";
  sc.name = "ARDS, turned prone";
  sc.duration_s = duration_s;
  return sc;
}

}  // namespace

TEST(RunLimit, AScenarioRunsForItsOwnLengthNotTheDemos) {
  const Scenario long_one = lesson(50.0), short_one = lesson(4.0);
  RuntimeOptions o;
  EXPECT_EQ(run_limit_s(o, &long_one), 50.0) << "not cut short at the demo's 10 s";
  EXPECT_EQ(run_limit_s(o, &short_one), 4.0) << "not run past its end";
  o.frames = 6;
  EXPECT_EQ(run_limit_s(o, &long_one), 50.0) << "--frames alone still ends with the scenario";
}

TEST(RunLimit, SecondsSaysOtherwise) {
  const Scenario sc = lesson(50.0);
  RuntimeOptions o;
  o.seconds = 3.0;
  EXPECT_EQ(run_limit_s(o, &sc), 3.0);
  o.seconds = 0.0;
  EXPECT_EQ(run_limit_s(o, &sc), 0.0) << "0: until stopped";
}

TEST(RunLimit, WithoutAScenarioTheDemoRunsTenSecondsOrTheFramesAsked) {
  RuntimeOptions o;
  EXPECT_EQ(run_limit_s(o, nullptr), 10.0);
  o.frames = 6;
  EXPECT_EQ(run_limit_s(o, nullptr), 0.0);
}

TEST(RunLimit, TheLogLineSaysTheLengthIsTheScenariosAndHowToChangeIt) {
  const Scenario sc = lesson(50.0);
  RuntimeOptions o;
  EXPECT_EQ(describe_limit(o, &sc),
            "running 50.0 s, the scenario ARDS, turned prone's length (--seconds changes it) (Ctrl-C stops)");
  o.seconds = 3.0;
  EXPECT_EQ(describe_limit(o, &sc), "running 3.0 s (Ctrl-C stops)");
  o.seconds.reset();
  EXPECT_EQ(describe_limit(o, nullptr), "running 10.0 s (Ctrl-C stops)");
}
