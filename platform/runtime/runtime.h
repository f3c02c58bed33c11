/// @file runtime.h
/// @brief The lungar Runtime: create, then frame after frame. Its frame is docs/design.md's "One frame", step by
/// step: breathe -> force SH -> head views -> deform and draw -> present and record. What it reads and where it
/// draws plug in behind small interfaces (FrameOutput, PoseSource, BreathingClock, FrameListener), and what it is
/// told comes in a small RuntimeConfig: a new output or pose source is a new implementation, not a new branch.
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "config/base/result.h"
#include "drivers/breath/source/breathing_clock.h"
#include "platform/runtime/breath_swing.h"
#include "platform/runtime/display_requests.h"
#include "platform/runtime/frame_listener.h"
#include "platform/runtime/frame_output.h"
#include "platform/runtime/frame_stats.h"
#include "platform/runtime/lung_course.h"
#include "platform/runtime/lung_scene.h"
#include "platform/runtime/pose_source.h"
#include "platform/runtime/runtime_config.h"
#include "render/hud_line.h"
#include "render/lesion_drawable.h"
#include "render/renderer.h"
#include "render/ventilation_legend.h"
#include "sim/deform/deform_eq1.h"
#include "sim/motion/excursion_tracker.h"
#include "sim/motion/lesion_rows.h"
#include "sim/motion/ventral_share.h"

namespace lungar::platform {

/// What a Runtime is made of. The output's GL context must be current on the thread that calls frame().
struct RuntimeParts {
  std::shared_ptr<LungScene> scene;                       ///< the baked lungs and their GPU buffers
  std::unique_ptr<FrameOutput> output;                    ///< where the views are drawn and presented
  std::unique_ptr<PoseSource> poses;                      ///< the head's and the patient's poses each frame
  std::unique_ptr<breath::BreathingClock> breathing;      ///< the breath's volume each frame (drivers/breath/)
  std::vector<std::shared_ptr<FrameListener>> listeners;  ///< told of every frame (recorders, the classroom)
  /// The lungs' shapes changing during the run (none: as loaded).
  std::shared_ptr<LungCourse> course;
  /// What the class asks this display to show (the instructor's console); none: only the V key.
  std::shared_ptr<const DisplayRequests> display;
  /// Lesions inside the lungs, each with its own coefficient rows (sim/motion/lesion_rows.h); none: none drawn.
  std::vector<sim::LesionRows> lesions;
  /// The frame's clock (monotonic ns); the bench scripts it so that every configuration sees the same inputs.
  std::function<std::int64_t()> clock = monotonic_ns;
};

class Runtime {
 public:
  /// Checks that the parts fit the config (CPU eq. 1 needs transfer rows, mesh mode needs triangles) and sizes
  /// every per-frame buffer once.
  static Result<std::unique_ptr<Runtime>> create(const RuntimeConfig& config, RuntimeParts parts);

  /// One frame, presented and recorded in the stats.
  Status frame();
  /// One more frame, not recorded, whose picture is written to `png_path` before it is presented.
  Status final_frame(const std::string& png_path);
  /// False once the output was closed or a finite pose source has delivered everything (after the first frame).
  bool keep_running();
  /// The stats JSON of the frames so far (docs/design.md, Contracts), every part adding its own; `wall_s` is the run's
  /// length.
  nlohmann::ordered_json stats_json(double wall_s) const;
  /// One human line for the console.
  std::string summary(double wall_s) const;

  long frames() const { return frames_; }
  /// The breathing and the pathologies in force at the last status update, as the status line's second line shows
  /// them and the log says each time they change ("breathing normal 20/min 420 mL, pathologies none").
  const std::string& lesson() const { return lesson_; }
  FrameOutput& output() { return *parts_.output; }
  PoseSource& poses() { return *parts_.poses; }
  const FrameStats& frame_stats() const { return stats_; }
  /// What the last frame drew (points per eye before culling, points deformed by transform feedback).
  const render::FrameStats& last_draw() const { return last_draw_; }

 private:
  Runtime(const RuntimeConfig& config, RuntimeParts parts);
  Status draw_frame(const std::string* snapshot_png);

  // docs/design.md, "One frame"
  sim::BreathingSample breathe(std::int64_t now_ns) const;                     // 1.
  void force_sh(std::int64_t now_ns, FrameState& state);                       // 2.
  const FrameViews& head_views(std::int64_t now_ns, std::int64_t display_ns);  // 3.
  Status deform_and_draw(const FrameState& state, const FrameViews& views);    // 4.
  Status present_and_record(const FrameState& state);                          // 5.

  void follow_course(std::int64_t now_ns);
  void deform_on_cpu(const FrameState& state);
  void move_lesions();
  render::FrameInputs frame_inputs(const FrameState& state, const FrameViews& views) const;
  Status draw_views(const render::FrameInputs& in, const FrameViews& views);
  void draw_status_line(std::int64_t now_ns, double dv_ml, const FrameViews& views);
  void follow_lesson(std::int64_t now_ns);
  void draw_legend(const FrameViews& views);
  void take_keys();
  /// The ventilation map on or off (`why` ends the log line), where the vertex shader draws the points.
  void show_ventilation(bool on, const char* why);

  const RuntimeConfig config_;
  RuntimeParts parts_;
  const sim::BakedAsset& asset_;  ///< as loaded, never written: what the patient is now is patient_
  /// The patient now: as loaded, then each frame as the course has it (follow_course); the force, the split and
  /// the stats read it.
  sim::PatientState patient_;
  std::int64_t max_ahead_ns_ = 0;

  // Per-frame buffers, sized once.
  std::vector<float> force_;          ///< f_lm of every lung, lung-major
  std::vector<float> cpu_positions_;  ///< --deform cpu7 | cpu1
  std::optional<sim::Eq1Deformer> eq1_;
  std::optional<sim::VentralShare> ventral_;  ///< the stats' ventral_share, from force_ alone
  std::vector<render::LungFrame> lung_frames_;
  std::optional<render::LesionDrawable> lesion_drawable_;  ///< made when there are lesions
  std::vector<render::LesionFrame> lesion_frames_;         ///< one per RuntimeParts::lesions
  std::vector<sim::ExcursionTracker> lesion_excursions_;   ///< each lesion's path so far, for the stats
  render::PositionSource source_ = render::PositionSource::Shader;

  std::optional<render::HudLine> hud_;  ///< the status line, drawn over the scene
  std::optional<render::HudLine> lesson_hud_;  ///< under it, the breathing and the pathologies in force
  std::string lesson_;
  bool ventilation_ = false;           ///< the ventilation map is shown (config, then the V key or the class)
  std::uint64_t display_version_ = 0;  ///< the class's display request last taken (parts_.display)
  std::optional<render::VentilationLegend> legend_;  ///< made when the map is first shown
  BreathSwing swing_;                   ///< the last breath's dV swing, for the map

  drivers::PoseSample last_patient_, last_head_, measured_head_;
  double frame_estimate_ms_ = 16.0;
  std::int64_t previous_submit_ns_ = 0;
  std::int64_t hud_updated_ns_ = 0;
  long frames_ = 0;
  FrameStats stats_;
  render::FrameStats last_draw_;
};

}  // namespace lungar::platform
