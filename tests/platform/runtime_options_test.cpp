// Command-line overrides: each option lands on the right setting, and bad values are named.
#include <gtest/gtest.h>

#include "platform/runtime/runtime_options.h"

using lungar::platform::apply_overrides;
using lungar::platform::RuntimeOptions;
namespace cfg = lungar::config;

TEST(RuntimeOptions, OverridesLandOnTheirSettings) {
  RuntimeOptions o;
  o.tracker = "replay:logs/turn.trk";
  o.view = "mono";
  o.mode = "mesh";
  o.deform = "cpu1";
  o.headless = true;
  o.asset_path = "a.lungbake";
  o.scenario_path = "teach.toml";
  cfg::Settings s;
  EXPECT_EQ(apply_overrides(o, s), "");
  EXPECT_EQ(s.trackers.source, cfg::TrackerSource::Replay);
  EXPECT_EQ(s.trackers.replay_file, "logs/turn.trk");
  EXPECT_EQ(s.hmd.view, cfg::View::Mono);
  EXPECT_EQ(s.render.mode, cfg::RenderMode::Mesh);
  EXPECT_EQ(s.render.deform, cfg::Deform::Cpu1);
  EXPECT_EQ(s.display.output, cfg::Output::Headless);
  EXPECT_EQ(s.sim.asset, "a.lungbake");
  EXPECT_EQ(s.breathing.scenario, "teach.toml");
}

TEST(RuntimeOptions, BadValuesAreNamed) {
  cfg::Settings s;
  RuntimeOptions o;
  o.tracker = "replay:";
  EXPECT_EQ(apply_overrides(o, s), "--tracker: expected mock, hid or replay:FILE.trk, got 'replay:'");
  o = {};
  o.view = "left";
  EXPECT_EQ(apply_overrides(o, s), "--view: expected mono or stereo, got 'left'");
  o = {};
  o.deform = "cuda";
  EXPECT_EQ(apply_overrides(o, s), "--deform: expected gpu, cpu7, cpu1 or none, got 'cuda'");
  o = {};
  o.frames = 0;
  EXPECT_EQ(apply_overrides(o, s), "--frames: expected a positive number of frames, got 0");
}
