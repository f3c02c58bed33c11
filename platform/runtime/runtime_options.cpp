/// @file runtime_options.cpp
/// @brief Command-line overrides on top of the config file.
#include "platform/runtime/runtime_options.h"

namespace lungar::platform {

std::string apply_overrides(const RuntimeOptions& o, config::Settings& s) {
  using namespace lungar::config;
  if (!o.asset_path.empty()) s.sim.asset = o.asset_path;
  if (!o.scenario_path.empty()) s.breathing.scenario = o.scenario_path;
  if (o.headless) s.display.output = Output::Headless;
  if (!o.tracker.empty()) {
    if (o.tracker == "mock") {
      s.trackers.source = TrackerSource::Mock;
    } else if (o.tracker == "hid") {
      s.trackers.source = TrackerSource::Hid;
    } else if (o.tracker.rfind("replay:", 0) == 0 && o.tracker.size() > 7) {
      s.trackers.source = TrackerSource::Replay;
      s.trackers.replay_file = o.tracker.substr(7);
    } else {
      return "--tracker: expected mock, hid or replay:FILE.trk, got '" + o.tracker + "'";
    }
  }
  if (!o.view.empty()) {
    if (o.view == "mono") {
      s.hmd.view = View::Mono;
    } else if (o.view == "stereo") {
      s.hmd.view = View::Stereo;
    } else {
      return "--view: expected mono or stereo, got '" + o.view + "'";
    }
  }
  if (!o.mode.empty()) {
    if (o.mode == "points") {
      s.render.mode = RenderMode::Points;
    } else if (o.mode == "mesh") {
      s.render.mode = RenderMode::Mesh;
    } else {
      return "--mode: expected points or mesh, got '" + o.mode + "'";
    }
  }
  if (!o.deform.empty()) {
    if (o.deform == "gpu") {
      s.render.deform = Deform::Gpu;
    } else if (o.deform == "cpu7") {
      s.render.deform = Deform::Cpu7;
    } else if (o.deform == "cpu1") {
      s.render.deform = Deform::Cpu1;
    } else if (o.deform == "none") {
      s.render.deform = Deform::None;
    } else {
      return "--deform: expected gpu, cpu7, cpu1 or none, got '" + o.deform + "'";
    }
  }
  if (o.frames && *o.frames <= 0) return "--frames: expected a positive number of frames, got " + std::to_string(*o.frames);
  if (o.seconds && !(*o.seconds >= 0)) return "--seconds: expected a duration >= 0 (0: until stopped), got " + std::to_string(*o.seconds);
  return "";
}

}  // namespace lungar::platform
