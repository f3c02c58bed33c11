/// @file spaam_command.cpp
/// @brief The interactive SPAAM loop and its wiring to the settings' tracker and output (spaam_command.h).
#include "platform/app/spaam_command.h"

#include <cstdio>
#include <cstdlib>
#include <memory>

#include <glm/mat4x4.hpp>

#include "config/base/clock.h"
#include "config/base/log_line.h"
#include "config/config_paths.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "platform/app/open_output.h"
#include "platform/app/settings_load.h"
#include "platform/registration/spaam_screen.h"

namespace lungar::platform {

namespace {

/// One key's effect on the session; the note the screen shows after it.
std::string apply_key(char key, SpaamSession& session, const SpaamIo& io) {
  if (key == '\b') return session.undo() ? "undone: the last alignment is dropped" : "nothing to undo";
  if (key != ' ' && key != '\n') return {};
  const SpaamTarget t = session.target();
  const std::array<drivers::PoseSample, 2> poses = io.poses();
  if (Status s = session.confirm(poses[0], poses[1]); !s) {
    io.say(s.error());
    return s.error();
  }
  const Alignment& a = session.alignments()[static_cast<std::size_t>(t.eye)].back();
  char line[200];
  std::snprintf(line, sizeof line, "%s eye %d/%d: [%.1f, %.1f, %.1f] mm at (%.1f, %.1f) px", t.eye ? "right" : "left",
                t.index + 1, t.count, a.point_mm.x(), a.point_mm.y(), a.point_mm.z(), a.pixel.x(), a.pixel.y());
  io.say(line);
  return std::string("recorded ") + (t.eye ? "right" : "left") + " " + std::to_string(t.index + 1);
}

/// The settings --config names, else the ones lungar would choose.
Result<Settings> spaam_settings(const CalibrateDisplayOptions& o) {
  const auto chosen = config::choose_config(o.config_paths, config::XdgDirs::from_environment());
  auto s = load_chosen_settings(chosen);
  if (!s) return s.with_context("");
  const char* display = std::getenv("DISPLAY");
  const bool has_display = display != nullptr && *display != '\0';
  const Output kind = s->display.output;
  if (kind == Output::Window || kind == Output::Fullscreen || (kind == Output::Auto && has_display)) return s;
  return fail(std::string("display.output: the crosshairs need a window (window or fullscreen, or auto with DISPLAY "
                          "set), got ") +
              to_string(kind) + (kind == Output::Auto ? " without DISPLAY" : "") +
              "; or fit a CSV of alignments with --alignments FILE");
}

/// Draws one SPAAM frame on `output`: its eye viewports when it has two side by side, else its target's halves.
Status draw_spaam_frame(FrameOutput& output, SpaamScreen& screen, const HmdSettings& hmd, const SpaamSession& session,
                        const std::string& note) {
  auto timing = output.begin_frame(monotonic_ns());
  if (!timing) return timing.with_context("output: ");
  const FrameViews& views = output.views(glm::mat4(1.f));
  const std::array<int, 2> size = output.target_size();
  std::array<render::Viewport, 2> viewports{render::Viewport{0, 0, size[0] / 2, size[1]},
                                            render::Viewport{size[0] / 2, 0, size[0] - size[0] / 2, size[1]}};
  if (views.count == 2 && views.shared_target) viewports = {views.eyes[0].viewport, views.eyes[1].viewport};
  output.bind_target(0);
  const SpaamTarget t = session.target();
  const std::array<std::string, 3> prompt = session.prompt();
  screen.draw(viewports, t.eye, hmd.eye_width_px, hmd.eye_height_px, t.pixel, {prompt[0], prompt[1], prompt[2], note});
  if (Status s = output.finish_scene(views); !s) return s.with_context("output: ");
  if (Status s = output.end_frame(); !s) return s.with_context("output: ");
  return ok();
}

}  // namespace

Result<bool> run_spaam(SpaamSession& session, const SpaamIo& io) {
  std::string note;
  while (!session.done()) {
    if (!io.poll()) return false;
    for (char key : io.keys()) {
      if (std::string said = apply_key(key, session, io); !said.empty()) note = said;
      if (session.done()) return true;
    }
    if (Status drawn = io.draw(session, note); !drawn) return drawn.with_context("");
  }
  return true;
}

int gather_and_fit(const CalibrateDisplayOptions& o, SpaamSession& session, const SpaamIo& io) {
  auto finished = run_spaam(session, io);
  if (!finished) return io.say(finished.error()), 1;
  if (!*finished) return io.say("aborted: nothing written"), 1;
  const std::string csv = saved_alignments_path(o);
  if (Status s = write_alignments_csv(csv, session.alignments()); !s) return io.say(s.error()), 1;
  io.say("alignments written to " + csv + " (--alignments " + csv + " fits them again)");
  return fit_and_report(session.alignments(), o, csv);
}

int run_spaam_calibration(const CalibrateDisplayOptions& o) {
  if (o.out_path.empty())
    return calibrate_display_say("--out: expected the TOML to write [hmd.display_calibration] to"), 2;
  if (o.stylus_tip_mm && o.fiducial_mm)
    return calibrate_display_say("expected --stylus-tip-mm or --fiducial-mm, not both"), 2;
  if (o.grid < 3 || o.grid > 10)
    return calibrate_display_say("--grid: expected 3 to 10, got " + std::to_string(o.grid)), 2;
  auto settings = spaam_settings(o);
  if (!settings) return calibrate_display_say(settings.error()), 2;
  drivers::TrackerOptions topts;
  topts.log = [](const std::string& line) { lungar::log_line("tracker", line); };
  auto tracker = drivers::make_tracker(settings->trackers(), topts);
  if (!tracker) return calibrate_display_say("tracker: " + tracker.error()), 2;
  const auto& tip = settings->trackers().stylus.tip_offset_mm;
  SpaamPoint point{drivers::Role::Stylus, o.stylus_tip_mm.value_or(Eigen::Vector3d(tip[0], tip[1], tip[2]))};
  if (o.fiducial_mm) point = {drivers::Role::Patient, *o.fiducial_mm};
  auto output = open_output(*settings, calibrate_display_say);
  if (!output) return calibrate_display_say(output.error()), 2;
  calibrate_display_say("output: " + (*output)->describe() + "; tracker: " + (*tracker)->describe());
  SpaamSession session(settings->hmd.eye_width_px, settings->hmd.eye_height_px, point, o.grid);
  SpaamScreen screen;
  FrameOutput& out = **output;
  drivers::Tracker& poses = **tracker;
  SpaamIo io;
  io.poll = [&] { return out.poll_events(); };
  io.keys = [&] { return out.take_keys(); };
  io.poses = [&] {
    const std::int64_t now = monotonic_ns();
    return std::array<drivers::PoseSample, 2>{poses.latest(drivers::Role::Head, now), poses.latest(point.role, now)};
  };
  io.draw = [&](const SpaamSession& s, const std::string& note) {
    return draw_spaam_frame(out, screen, settings->hmd, s, note);
  };
  io.say = calibrate_display_say;
  return gather_and_fit(o, session, io);
}

}  // namespace lungar::platform
