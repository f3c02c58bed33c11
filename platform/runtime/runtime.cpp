/// @file runtime.cpp
/// @brief The frame loop and what it needs set up: asset, EGL output, renderer, tracker, breathing script.
#include "platform/runtime/runtime.h"

#include <GLES3/gl3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "config/settings_load.h"
#include "drivers/mock/mock_trajectory.h"
#include "drivers/tracker/tracker.h"
#include "platform/egl/egl_context.h"
#include "platform/runtime/demo_asset.h"
#include "platform/runtime/frame_stats.h"
#include "platform/runtime/log.h"
#include "platform/runtime/patient_force.h"
#include "platform/scenario_adapter.h"
#include "platform/text_file.h"
#include "render/frame_target.h"
#include "render/hud_line.h"
#include "render/lens_distortion.h"
#include "render/lung_drawable.h"
#include "render/png_snapshot.h"
#include "render/renderer.h"
#include "render/stereo_view.h"
#include "sim/asset/asset_io.h"
#include "sim/deform/deform_eq1.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/gravity.h"

namespace lungar::platform {

std::atomic<bool> g_stop_requested{false};

namespace {

using drivers::PoseSample;
using drivers::Role;

constexpr double kDemoSeconds = 10.0;
const char* const kDefaultSnapshot = "out/snapshot.png";
const char* const kDefaultStats = "out/stats.json";

glm::mat4 pose_matrix(const std::array<double, 3>& p, const std::array<double, 4>& q_wxyz) {
  const glm::quat q(static_cast<float>(q_wxyz[0]), static_cast<float>(q_wxyz[1]), static_cast<float>(q_wxyz[2]),
                    static_cast<float>(q_wxyz[3]));
  glm::mat4 m = glm::mat4_cast(glm::normalize(q));
  m[3] = glm::vec4(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]), 1.f);
  return m;
}

Eigen::Quaterniond to_eigen(const std::array<double, 4>& q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }

/// A pose to use before a tracker has delivered one: the mock's static scene (patient ahead, head in front).
PoseSample fallback_pose(Role role) {
  PoseSample s;
  s.role = role;
  if (auto p = drivers::mock_pose("static", role, 0.0)) {
    s.position_mm = p->position_mm;
    s.orientation_wxyz = p->orientation_wxyz;
  }
  return s;
}

/// The head sensor looks along its +y with +z up (drivers/mock, the HID layouts); the renderer's head frame is
/// OpenGL's camera (+y up, looking down -z): a +90 degree turn about x takes one to the other.
glm::mat4 head_to_world(const PoseSample& head, const std::array<double, 3>& eye_offset_mm) {
  glm::mat4 m = pose_matrix(head.position_mm, head.orientation_wxyz);
  m = glm::translate(m, glm::vec3(static_cast<float>(eye_offset_mm[0]), static_cast<float>(eye_offset_mm[1]),
                                  static_cast<float>(eye_offset_mm[2])));
  return glm::rotate(m, glm::radians(90.f), glm::vec3(1.f, 0.f, 0.f));
}

glm::vec3 to_vec3(const std::array<double, 3>& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}

struct Output {
  std::unique_ptr<EglContext> context;
  std::optional<render::FrameTarget> target;  ///< headless: the frame goes here
  int width = 0, height = 0;
};

/// A window when a display is there (or asked for), else headless.
Result<Output> open_output(const config::Settings& s, int want_width, int want_height) {
  using config::Output;
  Output out_kind = s.display.output;
  const char* display = std::getenv("DISPLAY");
  if (out_kind == Output::Auto) out_kind = (display && *display) ? Output::Window : Output::Headless;
  platform::Output out;
  if (out_kind != Output::Headless) {
    WindowOptions w;
    w.x_px = s.display.x_px;
    w.y_px = s.display.y_px;
    w.width_px = out_kind == Output::Fullscreen ? s.display.width_px : want_width;
    w.height_px = out_kind == Output::Fullscreen ? s.display.height_px : want_height;
    w.fullscreen = out_kind == Output::Fullscreen;
    w.output = s.display.x11_output;
    w.vsync = s.display.vsync;
    auto ctx = EglContext::window(w);
    if (!ctx && !w.output.empty() && w.fullscreen) {
      return fail("display.x11_output: " + ctx.error());  // the field to fix
    }
    if (ctx) {
      out.context = ctx.take();
      out.width = out.context->width();
      out.height = out.context->height();
      return out;
    }
    if (s.display.output != Output::Auto) return fail("display: " + ctx.error());
    log_line("no window (" + ctx.error() + "); running headless");
  }
  auto ctx = EglContext::headless();
  if (!ctx) return fail("display: " + ctx.error());
  out.context = ctx.take();
  auto target = render::FrameTarget::create(want_width, want_height);
  if (!target) return fail("display: " + target.error());
  out.target.emplace(target.take());
  out.width = want_width;
  out.height = want_height;
  return out;
}

}  // namespace

int run_runtime(const config::Settings& s, const RuntimeOptions& o) {
  log_line(config::summarize(s));
  const bool stereo = s.hmd.view == config::View::Stereo;
  const config::Deform deform = s.render.deform;

  // --- the asset ---------------------------------------------------------------------------------------
  DemoAssetOptions demo;
  demo.transfer_rows = deform == config::Deform::Cpu1;
  Result<sim::BakedAsset> loaded =
      s.sim.asset.empty() ? load_or_bake_demo_asset(demo, log_line) : sim::load_asset(s.sim.asset);
  if (!loaded) {
    log_line("error: " + loaded.error());
    return 1;
  }
  const sim::BakedAsset& asset = *loaded;
  if (deform == config::Deform::Cpu1 && !asset.has_transfer_rows()) {
    log_line("error: " + s.sim.asset + ": --deform cpu1 expected an asset baked with explicit transfer rows, got none");
    return 1;
  }
  const std::uint32_t coefficients = asset.coefficients();
  log_line("asset: " + std::to_string(asset.vertex_count()) + " nodes, " + std::to_string(asset.lungs.size()) +
           " lungs, " + std::to_string(coefficients) + " SH coefficients");

  // --- breathing ---------------------------------------------------------------------------------------
  const double limit_s = o.seconds ? *o.seconds : (o.frames ? 0.0 : kDemoSeconds);
  auto script = load_breathing_script(s.breathing, limit_s > 0 ? limit_s : 60.0);
  if (!script) {
    log_line("error: " + script.error);
    return 1;
  }
  const bool scenario_turns = !script.script->orientation.turns().empty();

  // --- output, renderer --------------------------------------------------------------------------------
  const render::HmdGeometry hmd{s.hmd.ipd_mm,     s.hmd.fov_inner_deg, s.hmd.fov_outer_deg, s.hmd.fov_up_deg,
                                s.hmd.fov_down_deg, s.hmd.eye_width_px, s.hmd.eye_height_px, s.hmd.near_mm,
                                s.hmd.far_mm};
  const render::StereoView stereo_view(hmd);
  auto output = open_output(s, stereo ? stereo_view.target_width() : s.hmd.eye_width_px, stereo_view.target_height());
  if (!output) {
    log_line("error: " + output.error());
    return 1;
  }
  log_line("output: " + output->context->describe() +
           (output->target ? " (headless, " : " (window, ") + std::to_string(output->width) + "x" +
           std::to_string(output->height) + ")");
  auto drawable = render::LungDrawable::create(asset, {.half_float = s.render.half_float});
  if (!drawable) {
    log_line("error: asset: " + drawable.error());
    return 1;
  }
  auto renderer = render::Renderer::create(*drawable);
  if (!renderer) {
    log_line("error: renderer: " + renderer.error());
    return 1;
  }

  std::optional<render::HudLine> hud;
  if (s.render.hud) hud.emplace();
  // The lens pass: the scene is drawn undistorted into its own target, then pre-distorted into the output.
  std::optional<render::FrameTarget> lens_scene;
  std::optional<render::LensDistortion> lens;
  render::LensParams lens_params;
  std::array<std::array<float, 2>, 2> lens_centres = {std::array<float, 2>{0.5f, 0.5f}, {0.5f, 0.5f}};
  if (s.hmd.lens.enabled) {
    auto scene = render::FrameTarget::create(output->width, output->height);
    auto pass = render::LensDistortion::create();
    if (!scene || !pass) {
      log_line("error: lens distortion: " + (scene ? pass.error() : scene.error()));
      return 1;
    }
    lens_scene.emplace(scene.take());
    lens.emplace(pass.take());
    for (int c = 0; c < 3; ++c) {
      lens_params.k1[c] = static_cast<float>(s.hmd.lens.k1[c]);
      lens_params.k2[c] = static_cast<float>(s.hmd.lens.k2[c]);
    }
    if (stereo) lens_centres = {render::lens_centre(hmd, true), render::lens_centre(hmd, false)};
  }
  auto bind_output = [&] {
    if (output->target) {
      output->target->bind();
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, output->width, output->height);
    }
  };

  // --- tracker -----------------------------------------------------------------------------------------
  drivers::TrackerOptions topts;
  topts.record_path = o.record_path;
  topts.log = [](const std::string& line) { log_line(line); };
  auto made = drivers::make_tracker(s.trackers, topts);
  if (!made.tracker) {
    log_line("error: tracker: " + made.error);
    return 1;
  }
  drivers::Tracker& tracker = *made.tracker;
  log_line("tracker: " + tracker.describe());

  // --- per-frame state, sized once ---------------------------------------------------------------------
  const Eigen::Quaterniond registration = registration_rotation(s.registration);
  const glm::mat4 registration_m =
      pose_matrix(s.registration.translation_mm, s.registration.rotation_wxyz);
  std::vector<float> force(asset.lungs.size() * coefficients, 0.f);
  std::vector<float> cpu_positions(deform == config::Deform::Gpu ? 0 : asset.positions.size());
  std::optional<sim::Eq1Deformer> eq1;
  if (deform == config::Deform::Cpu1) eq1.emplace(asset);
  std::vector<render::LungFrame> lung_frames(asset.lungs.size());
  const std::array<glm::vec3, 2> colors = {to_vec3(s.render.color_left), to_vec3(s.render.color_right)};
  for (std::size_t l = 0; l < lung_frames.size(); ++l) {
    lung_frames[l].force = std::span<const float>(force.data() + l * coefficients, coefficients);
    // LPS: +x is the patient's left, so the lung whose centre has the larger x is the left one.
    lung_frames[l].color = asset.lungs[l].centre[0] >= 0 ? colors[0] : colors[1];
  }
  std::array<render::EyeView, 2> eyes;
  PoseSample last_patient = fallback_pose(Role::Patient);
  PoseSample last_head = fallback_pose(Role::Head);
  FrameStats stats(o.frames ? static_cast<std::size_t>(*o.frames) + 1 : 8192);
  const std::int64_t max_ahead_ns = static_cast<std::int64_t>(s.hmd.prediction_max_ms * 1e6);

  const std::int64_t t0 = drivers::monotonic_ns();
  std::int64_t previous = t0;
  double frame_estimate_ms = 16.0;
  long frame = 0;
  std::int64_t hud_updated = 0;
  bool window_open = true;

  // One frame: DESIGN.md's five steps. `final_frame` is drawn after the loop for the snapshot, not counted.
  auto draw_frame = [&](bool present) -> bool {
    const std::int64_t now = drivers::monotonic_ns();
    const double t = static_cast<double>(now - t0) * 1e-9;
    // 1. breathing
    const sim::BreathingSample breath = script.script->driver.at(t);
    // 2. patient pose -> gravity in the lung frame -> force SH per lung
    const PoseSample patient = tracker.latest(Role::Patient, now);
    if (patient.valid()) last_patient = patient;
    Eigen::Quaterniond patient_q = to_eigen(last_patient.orientation_wxyz);
    if (scenario_turns && s.trackers.source == config::TrackerSource::Mock) {
      patient_q = script.script->orientation.at(t);  // a teaching scenario turns the patient itself
    }
    const Eigen::Quaterniond lung_q = lung_in_world(patient_q, registration);
    patient_force_sh(asset, s.sim.orientation_mode, lung_q, force);
    // 3. head pose, predicted to when this frame will be shown
    const std::int64_t display_ns = now + static_cast<std::int64_t>(frame_estimate_ms * 1e6);
    const PoseSample head = tracker.predicted(Role::Head, display_ns, max_ahead_ns);
    if (head.valid()) last_head = head;
    const PoseSample measured_head = tracker.latest(Role::Head, now);  // its arrival dates the pose age
    const glm::mat4 head_m = head_to_world(last_head, s.hmd.head_to_eye_mm);
    std::span<const render::EyeView> eye_span;
    if (stereo) {
      eyes = stereo_view.eyes(head_m);
      eye_span = std::span<const render::EyeView>(eyes.data(), 2);
    } else {
      eyes[0] = stereo_view.mono(head_m, output->width, output->height);
      eye_span = std::span<const render::EyeView>(eyes.data(), 1);
    }
    if (!output->target) {  // a window: eyes fill it side by side whatever its size
      const int n = static_cast<int>(eye_span.size());
      for (int e = 0; e < n; ++e) eyes[e].viewport = {e * output->width / n, 0, output->width / n, output->height};
    }
    // 4. uniforms (or CPU deformation), draw
    render::PositionSource source = render::PositionSource::Shader;
    if (deform != config::Deform::Gpu) {
      if (deform == config::Deform::Cpu7) {
        sim::deform_eq7(asset, force, breath.dv_ml, cpu_positions);
      } else {
        eq1->deform(sim::gravity_in_lung_frame(lung_q), breath.dv_ml, cpu_positions);
      }
      if (auto up = drawable->upload_positions(cpu_positions); !up) log_line("error: " + up.error());
      source = render::PositionSource::Uploaded;
    }
    for (std::size_t l = 0; l < lung_frames.size(); ++l) {
      lung_frames[l].volume_change_ml = static_cast<float>(breath.dv_ml * asset.lungs[l].volume_share);
    }
    render::FrameInputs in;
    in.lungs = lung_frames;
    in.eyes = eye_span;
    in.model = pose_matrix(last_patient.position_mm, {patient_q.w(), patient_q.x(), patient_q.y(), patient_q.z()}) *
               registration_m;
    in.mode = s.render.mode == config::RenderMode::Mesh ? render::DrawMode::Mesh : render::DrawMode::Points;
    in.source = source;
    in.strategy = s.render.stereo_strategy == config::StereoStrategy::PerEye ? render::StereoStrategy::PerEye
                                                                             : render::StereoStrategy::DeformOnce;
    in.overlay_rest = s.render.overlay_rest;
    in.point_size_px = static_cast<float>(s.render.point_size_px);
    in.level_of_detail = s.render.lod;
    in.background = to_vec3(s.render.background);
    if (lens_scene) {
      lens_scene->bind();
    } else {
      bind_output();
    }
    if (auto drawn = renderer->draw(*drawable, in); !drawn) {
      log_line("error: draw: " + drawn.error());
      return false;
    }
    if (lens) {
      bind_output();
      const auto centres = std::span<const std::array<float, 2>>(lens_centres.data(), eye_span.size());
      if (auto warped = lens->apply(*lens_scene, eye_span, centres, lens_params); !warped) {
        log_line("error: lens distortion: " + warped.error());
        return false;
      }
    }
    if (hud) {
      // The on-screen line: frame rate, pose age, tracker state; refreshed four times a second.
      if (now - hud_updated >= 250000000) {
        hud_updated = now;
        const double age_ms =
            measured_head.valid() ? static_cast<double>(now - measured_head.t_arrival_ns) * 1e-6 : -1.0;
        char text[render::HudLine::kMaxChars + 1];
        std::snprintf(text, sizeof text, "%.0f FPS  POSE AGE %.0f MS  TRACKER %s%s  DV %.0f ML",
                      frame_estimate_ms > 0 ? 1000.0 / frame_estimate_ms : 0.0, age_ms,
                      drivers::to_string(tracker.state()), measured_head.stale() ? " (STALE POSE)" : "",
                      breath.dv_ml);
        hud->set_text(text);
      }
      for (const auto& eye : eye_span) hud->draw(eye.viewport);
    }
    // 5. swap or finish; record timing and pose age
    if (present) {
      if (output->target) {
        glFinish();
      } else if (auto swapped = output->context->swap_buffers(); !swapped) {
        log_line("error: " + swapped.error());
        return false;
      }
      const std::int64_t submitted = drivers::monotonic_ns();
      const double frame_ms = static_cast<double>(submitted - previous) * 1e-6;
      previous = submitted;
      frame_estimate_ms = 0.9 * frame_estimate_ms + 0.1 * frame_ms;
      const double age_ms =
          measured_head.valid() ? static_cast<double>(submitted - measured_head.t_arrival_ns) * 1e-6 : -1.0;
      stats.record(frame_ms, age_ms, breath.dv_ml);
    }
    return true;
  };

  {
    char limit[96];
    if (o.frames && limit_s > 0) {
      std::snprintf(limit, sizeof limit, "%ld frames or %.1f s", *o.frames, limit_s);
    } else if (o.frames) {
      std::snprintf(limit, sizeof limit, "%ld frames", *o.frames);
    } else if (limit_s > 0) {
      std::snprintf(limit, sizeof limit, "%.1f s", limit_s);
    } else {
      std::snprintf(limit, sizeof limit, "until stopped");
    }
    log_line(std::string("running ") + limit + " (Ctrl-C stops)");
  }
  int exit_code = 0;
  while (!g_stop_requested.load()) {
    if (o.frames && frame >= *o.frames) break;
    if (limit_s > 0 && static_cast<double>(drivers::monotonic_ns() - t0) * 1e-9 >= limit_s) break;
    if (s.trackers.source == config::TrackerSource::Replay && tracker.finished() && frame > 0) {
      log_line("replay finished");
      break;
    }
    if (!output->target) window_open = output->context->process_events();
    if (!window_open) break;
    if (!draw_frame(true)) {
      exit_code = 1;
      break;
    }
    ++frame;
  }
  const double wall_s = static_cast<double>(drivers::monotonic_ns() - t0) * 1e-9;
  if (g_stop_requested.load()) log_line("stop requested; writing the outputs");

  // --- outputs -----------------------------------------------------------------------------------------
  const std::string snapshot = !o.snapshot_path.empty() ? o.snapshot_path : std::string(kDefaultSnapshot);
  const std::string stats_path = !o.stats_json_path.empty() ? o.stats_json_path : std::string(kDefaultStats);
  if (exit_code == 0 && draw_frame(false)) {
    std::error_code ec;
    if (std::filesystem::path(snapshot).has_parent_path()) {
      std::filesystem::create_directories(std::filesystem::path(snapshot).parent_path(), ec);
    }
    if (auto shot = render::snapshot_png(snapshot, 0, 0, output->width, output->height); !shot) {
      log_line("error: snapshot: " + shot.error());
      exit_code = 1;
    } else {
      log_line("snapshot: " + snapshot);
    }
  }
  if (!output->target) (void)output->context->swap_buffers();  // show the last frame; the outputs are written either way
  const drivers::TrackerStats ts = tracker.stats();
  tracker.stop();
  // The mean delivered rate over the run: the instantaneous rate says little once a replay has ended.
  const double rate_hz = wall_s > 0 ? static_cast<double>(ts.accepted) / wall_s : 0.0;
  const TrackerCounters counters{ts.reports, ts.malformed, ts.reconnects, rate_hz, drivers::to_string(ts.state)};
  std::string write_error;
  if (!write_text_atomically(stats_path,
                             stats.to_json(config::to_string(s.hmd.view), config::to_string(deform),
                                           asset.vertex_count(), counters, wall_s),
                             write_error)) {
    log_line("error: stats: " + write_error);
    exit_code = 1;
  } else {
    log_line("stats: " + stats_path);
  }
  log_line(stats.summary(counters));
  return exit_code;
}

}  // namespace lungar::platform
