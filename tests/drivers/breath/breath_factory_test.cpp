/// @file breath_factory_test.cpp
/// @brief make_breath_source(): which source a name picks, what each step refuses, and the clock each source makes
///        (the model's, a trace's, a live marker's, a DDS source's through the opener the wiring hands in).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/breath/breath_factory/breath_factory.h"

namespace lungar::breath {
namespace {

/// The model: steady normal breathing for a minute, the patient supine.
std::shared_ptr<const sim::BreathingScript> steady_script() {
  auto driver = sim::BreathingDriver::create(sim::BreathingParams{});
  auto track = sim::OrientationTrack::create(Eigen::Quaterniond::Identity(), {});
  EXPECT_TRUE(driver && track);
  return std::make_shared<const sim::BreathingScript>(
      sim::BreathingScript{driver.take(), track.take(), 60.0, sim::BreathingParams{}, {}});
}

/// A DDS feed's stand-in: it only names itself in the stats.
class NamedFeed final : public SurrogateFeed {
 public:
  void feed(double, Followers&) override {}
  void add_stats(nlohmann::json& stats) const override { stats["breath_source"] = "stand-in"; }
};

struct Made {
  Result<std::unique_ptr<BreathingClock>> clock;
  std::vector<std::string> log;
  nlohmann::json stats;
};

Made make(const std::string& source, OpenDdsFeed open_dds = {}) {
  auto chosen = choose_breath_source(source, 0);
  EXPECT_TRUE(chosen) << (chosen ? "" : chosen.error());
  Made m{fail("not made"), {}, nlohmann::json::object()};
  BreathSourceOptions options;
  options.script = steady_script();
  options.open_dds = std::move(open_dds);
  options.log = [&m](const std::string& line) { m.log.push_back(line); };
  m.clock = make_breath_source(*chosen, options, 0);
  if (m.clock) (*m.clock)->add_stats(m.stats);
  return m;
}

TEST(BreathFactory, NamesTheModelAMarkerADdsSourceOrElseATraceFile) {
  EXPECT_EQ(breath_kind(""), BreathKind::Model);
  EXPECT_EQ(breath_kind("model"), BreathKind::Model) << "[breathing] source's default";
  EXPECT_EQ(breath_kind("marker:stylus"), BreathKind::Marker);
  for (const char* dds : {"amm", "amm@3", "openice", "openice:flow@7", "openice@232", "amm:volume"})
    EXPECT_EQ(breath_kind(dds), BreathKind::Dds) << dds;
  for (const char* file :
       {"traces/amm@home.csv", "ammonia.csv", "openice.vxp", "markers.csv", "model.csv", "model@2", "marker", "trace"})
    EXPECT_EQ(breath_kind(file), BreathKind::Trace) << file;
}

TEST(BreathFactory, AMarkersRoleIsCheckedBeforeTheTrackerAndItsFeedTapsTheTracker) {
  for (const char* bad : {"marker:patient", "marker:", "marker:chest"}) {
    auto chosen = choose_breath_source(bad, 0);
    ASSERT_FALSE(chosen) << bad;
    EXPECT_NE(chosen.error().find("marker:ROLE: expected the tracker role"), std::string::npos) << chosen.error();
    EXPECT_NE(chosen.error().find(std::string("got '") + (bad + 7) + "'"), std::string::npos) << chosen.error();
  }
  auto marker = choose_breath_source("marker:stylus", 0);
  ASSERT_TRUE(marker);
  EXPECT_TRUE(marker->followed());
  EXPECT_TRUE(marker->tracker_tap());
  auto model = choose_breath_source("", 0);
  ASSERT_TRUE(model);
  EXPECT_FALSE(model->followed());
  EXPECT_FALSE(model->tracker_tap()) << "only a live marker listens to the tracker";
}

TEST(BreathFactory, TheModelBreathesTheScriptAndSaysNothing) {
  Made m = make("");
  ASSERT_TRUE(m.clock);
  EXPECT_EQ(m.stats["breathing_preset"], "normal");
  EXPECT_FALSE(m.stats.contains("breath_source"));
  EXPECT_TRUE(m.log.empty());
  EXPECT_DOUBLE_EQ((*m.clock)->at(1'000'000'000).v_ml, steady_script()->driver.at(1.0).v_ml);
}

TEST(BreathFactory, ATraceIsFollowedAndSaysWhatItFollows) {
  const std::string path = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/breath/extmarker/201205101541-UCC-1-N-130-6.csv";
  Made m = make(path);
  ASSERT_TRUE(m.clock) << m.clock.error();
  EXPECT_EQ(m.stats["breath_source"], "trace");
  EXPECT_EQ(m.stats["breath_file"], path);
  EXPECT_EQ(m.stats["breath_format"], "extmarker");
  EXPECT_EQ(m.stats["breath_state"], "model") << "FollowedBreathing around the feed: nothing followed yet";
  ASSERT_EQ(m.log.size(), 1u);
  EXPECT_EQ(m.log[0].rfind("breathing: following " + path + " (", 0), 0u) << m.log[0];
  Made missing = make("no/such/trace.csv");
  ASSERT_FALSE(missing.clock);
  EXPECT_NE(missing.clock.error().find("no/such/trace.csv"), std::string::npos) << missing.clock.error();
  EXPECT_TRUE(missing.log.empty());
}

TEST(BreathFactory, AMarkerSaysItFollowsLiveOnceTheTrackerRuns) {
  Made m = make("marker:head");
  ASSERT_TRUE(m.clock);
  EXPECT_EQ(m.stats["breath_source"], "marker:head");
  ASSERT_EQ(m.log.size(), 1u);
  EXPECT_EQ(m.log[0],
            "breathing: following the head marker live (its breathing axis from its first 10 s), the model until then");
}

TEST(BreathFactory, ADdsSourceGoesToItsReadersOrTheStandInGiven) {
  std::vector<std::string> asked;
  Made m = make("openice:flow@7", [&asked](const std::string& source) -> Result<std::shared_ptr<SurrogateFeed>> {
    asked.push_back(source);
    return std::shared_ptr<SurrogateFeed>(std::make_shared<NamedFeed>());
  });
  ASSERT_TRUE(m.clock);
  EXPECT_EQ(asked, std::vector<std::string>{"openice:flow@7"});
  EXPECT_EQ(m.stats["breath_source"], "stand-in");
  Made refused = make("amm", [](const std::string&) -> Result<std::shared_ptr<SurrogateFeed>> {
    return fail("'amm': no Fast DDS");
  });
  ASSERT_FALSE(refused.clock);
  EXPECT_EQ(refused.clock.error(), "'amm': no Fast DDS");
  // Without a stand-in the readers' own opener reads the spec: a domain that is not one is refused by it.
  Made without = make("openice@domain");
  ASSERT_FALSE(without.clock);
  EXPECT_NE(without.clock.error().find("openice@domain"), std::string::npos) << without.clock.error();
}

}  // namespace
}  // namespace lungar::breath
