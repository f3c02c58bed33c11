// Command-line overrides: each option lands on the right setting, and bad values are named, whether they come
// through the command line (checked against config's name tables) or are set directly.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include "drivers/tracker/tracker_config.h"
#include "platform/app/runtime_options.h"

using lungar::platform::apply_overrides;
using lungar::platform::RuntimeOptions;

namespace {

/// Parses `args` as lungar's command line; the CLI11 error text, or "" when it parses.
std::string parse(std::vector<std::string> args, RuntimeOptions& o) {
  CLI::App app;
  lungar::platform::add_runtime_options(app, o);
  std::reverse(args.begin(), args.end());  // CLI11 takes a reversed vector
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RuntimeOptions, OverridesLandOnTheirSettings) {
  RuntimeOptions o;
  ASSERT_EQ(parse({"--tracker", "replay:logs/turn.trk", "--view", "mono", "--mode", "mesh", "--deform", "cpu1",
                   "--headless", "--asset", "a.lungbake", "--scenario", "teach.toml", "--frames", "7"},
                  o),
            "");
  lungar::platform::Settings s;
  ASSERT_TRUE(apply_overrides(o, s).ok());
  EXPECT_EQ(s.trackers().source, lungar::drivers::TrackerSource::Replay);
  EXPECT_EQ(s.trackers().replay_file, "logs/turn.trk");
  EXPECT_FALSE(s.trackers().replay_truncated) << "a truncated log is refused unless asked";
  EXPECT_EQ(s.hmd.view, lungar::platform::View::Mono);
  EXPECT_EQ(s.render.mode, lungar::render::DrawMode::Mesh);
  EXPECT_EQ(s.render.deform, lungar::platform::Deform::Cpu1);
  EXPECT_EQ(s.display.output, lungar::platform::Output::Headless);
  EXPECT_EQ(s.sim.asset, "a.lungbake");
  EXPECT_EQ(s.breathing.scenario, "teach.toml");
  EXPECT_EQ(o.frames, 7);
  EXPECT_FALSE(o.seconds.has_value());
}

TEST(RuntimeOptions, TheCommandLineRefusesNamesThatAreNotInTheTables) {
  RuntimeOptions o;
  EXPECT_EQ(parse({"--view", "left"}, o),
            "--view: expected mono, stereo or ventilation, or a view and the map (stereo,ventilation), got 'left'");
  EXPECT_EQ(parse({"--deform", "cuda"}, o), "--deform: cuda not in {gpu,cpu7,cpu1,none}");
  EXPECT_EQ(parse({"--frames", "many"}, o), "Could not convert: --frames = many");
}

TEST(RuntimeOptions, OutputOpenXr) {
  RuntimeOptions o;
  o.output = "openxr";
  lungar::platform::Settings s;
  EXPECT_TRUE(apply_overrides(o, s));
  EXPECT_EQ(s.display.output, lungar::platform::Output::OpenXr);
}

TEST(RuntimeOptions, IgtlTrackerTakesHostAndPortWhereGiven) {
  lungar::platform::Settings s;
  RuntimeOptions o;
  o.tracker = "igtl:192.168.1.20:18945";
  ASSERT_TRUE(apply_overrides(o, s));
  EXPECT_EQ(s.trackers().source, lungar::drivers::TrackerSource::Igtl);
  EXPECT_EQ(s.trackers().igtl.host, "192.168.1.20");
  EXPECT_EQ(s.trackers().igtl.port, 18945);
  lungar::platform::Settings d;
  o.tracker = "igtl:plus.lab";  // the config's port (18944 by default)
  ASSERT_TRUE(apply_overrides(o, d));
  EXPECT_EQ(d.trackers().igtl.host, "plus.lab");
  EXPECT_EQ(d.trackers().igtl.port, 18944);
  lungar::platform::Settings e;
  o.tracker = "igtl";  // host and port from the config
  ASSERT_TRUE(apply_overrides(o, e));
  EXPECT_EQ(e.trackers().source, lungar::drivers::TrackerSource::Igtl);
  EXPECT_EQ(e.trackers().igtl.host, "127.0.0.1");
}

TEST(RuntimeOptions, BadValuesAreNamed) {
  lungar::platform::Settings s;
  RuntimeOptions o;
  o.output = "hmd";
  EXPECT_EQ(apply_overrides(o, s).error(),
            "--output: expected auto, window, fullscreen, headless or openxr, got 'hmd'");
  o = {};
  o.tracker = "replay:";
  EXPECT_EQ(apply_overrides(o, s).error(),
            "--tracker: expected mock, hid, igtl[:HOST[:PORT]] or replay:FILE.trk, got 'replay:'");
  o = {};
  o.tracker = "replay";
  EXPECT_EQ(apply_overrides(o, s).error(),
            "--tracker: expected mock, hid, igtl[:HOST[:PORT]] or replay:FILE.trk, got 'replay'");
  o = {};
  o.tracker = "igtl:";
  EXPECT_EQ(apply_overrides(o, s).error(), "--tracker: expected igtl:HOST[:PORT] with a host, got 'igtl:'");
  o = {};
  o.tracker = "igtl:plus.lab:70000";
  EXPECT_EQ(apply_overrides(o, s).error(), "--tracker: expected a port in [1, 65535] after igtl:HOST:, got '70000'");
  o = {};
  o.view = "left";
  EXPECT_EQ(apply_overrides(o, s).error(),
            "--view: expected mono, stereo or ventilation, or a view and the map (stereo,ventilation), got 'left'");
  o = {};
  o.view = "mono,ventilation";
  ASSERT_TRUE(apply_overrides(o, s));
  EXPECT_EQ(s.hmd.view, lungar::platform::View::Mono);
  EXPECT_TRUE(s.render.ventilation_map);
  o = {};
  o.view = "mono,stereo";
  EXPECT_FALSE(apply_overrides(o, s)) << "one view";
  o = {};
  o.deform = "cuda";
  EXPECT_EQ(apply_overrides(o, s).error(), "--deform: expected gpu, cpu7, cpu1 or none, got 'cuda'");
  o = {};
  o.frames = 0;
  EXPECT_EQ(apply_overrides(o, s).error(), "--frames: expected a positive number of frames, got 0");
}

TEST(RuntimeOptions, TheSamePathologyGivenTwiceIsRefusedNamingBoth) {
  lungar::platform::Settings s;
  RuntimeOptions o;
  o.pathologies = {"pneumothorax:right:30", "pneumothorax:right:30"};
  const lungar::Status twice = apply_overrides(o, s);
  ASSERT_FALSE(twice);
  EXPECT_EQ(twice.error().rfind("--pathology: pathology 'pneumothorax:right:30': repeats 'pneumothorax:right:30'", 0),
            0u)
      << twice.error();
  EXPECT_TRUE(s.sim.pathologies.empty()) << "nothing taken";
  o.pathologies = {"pneumothorax:right:30", "pneumothorax:left:30"};
  EXPECT_TRUE(apply_overrides(o, s));
}

TEST(RuntimeOptions, ReplayTruncatedAsksForATruncatedLogToBeReplayed) {
  RuntimeOptions o;
  ASSERT_EQ(parse({"--tracker", "replay:cut.trk", "--replay-truncated"}, o), "");
  lungar::platform::Settings s;
  ASSERT_TRUE(apply_overrides(o, s));
  EXPECT_TRUE(s.trackers().replay_truncated);
}
