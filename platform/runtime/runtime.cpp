/// @file runtime.cpp
/// @brief The frame, as docs/design.md's five steps ("One frame"), and what they need sized once.
#include "platform/runtime/runtime.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "config/base/log_line.h"
#include "platform/runtime/gl_math.h"
#include "platform/runtime/patient_force.h"
#include "sim/breathing/pv_curve.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/breath_share.h"
#include "sim/force/gravity.h"

namespace lungar::platform {

namespace {

using drivers::PoseSample;
using drivers::Role;

constexpr std::int64_t kStatusLinePeriodNs = 250'000'000;  // the status line changes four times a second

/// The head sensor looks along its +y with +z up (drivers/mock, the HID layouts); the renderer's head frame is
/// OpenGL's camera (+y up, looking down -z): a +90 degree turn about x takes one to the other.
Eigen::Isometry3d head_to_world(const PoseSample& head, const std::array<double, 3>& eye_offset_mm) {
  Eigen::Isometry3d m = pose_isometry(head);
  m.translate(Eigen::Vector3d(eye_offset_mm[0], eye_offset_mm[1], eye_offset_mm[2]));
  m.rotate(Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitX()));
  return m;
}

render::PositionSource position_source(Deform d) {
  switch (d) {
    case Deform::Gpu:
      return render::PositionSource::Shader;
    case Deform::None:
      return render::PositionSource::Rest;
    case Deform::Cpu7:
    case Deform::Cpu1:
      return render::PositionSource::Uploaded;
  }
  return render::PositionSource::Shader;
}

double ms_between(std::int64_t from_ns, std::int64_t to_ns) { return static_cast<double>(to_ns - from_ns) * 1e-6; }

}  // namespace

Runtime::Runtime(const RuntimeConfig& config, RuntimeParts parts)
    : config_(config),
      parts_(std::move(parts)),
      asset_(parts_.scene->asset()),
      patient_(parts_.scene->patient_at_load()) {}

Result<std::unique_ptr<Runtime>> Runtime::create(const RuntimeConfig& config, RuntimeParts parts) {
  const sim::BakedAsset& asset = parts.scene->asset();
  if (config.deform == Deform::Cpu1 && !asset.has_transfer_rows()) {
    return fail(parts.scene->name() + ": --deform cpu1 expected an asset baked with explicit transfer rows, got none");
  }
  if (config.mode == render::DrawMode::Mesh && !parts.scene->drawable().has_triangles()) {
    return fail(parts.scene->name() + ": mesh mode expected an asset with triangles, got none");
  }
  if (config.ventilation_map && position_source(config.deform) != render::PositionSource::Shader) {
    return fail(std::string("ventilation map: it is drawn by the vertex shader, which knows each point's sweep: "
                            "expected --deform gpu, got ") + to_string(config.deform));
  }
  std::unique_ptr<Runtime> r(new Runtime(config, std::move(parts)));
  r->ventilation_ = config.ventilation_map;
  r->max_ahead_ns_ = static_cast<std::int64_t>(config.prediction_max_ms * 1e6);
  const std::uint32_t c = asset.coefficients();
  r->force_.assign(asset.lungs.size() * c, 0.f);
  r->source_ = position_source(config.deform);
  if (r->source_ == render::PositionSource::Uploaded) r->cpu_positions_.assign(asset.positions.size(), 0.f);
  if (config.deform == Deform::Cpu1) r->eq1_.emplace(asset);
  r->ventral_.emplace(asset);
  r->lung_frames_.resize(asset.lungs.size());
  for (std::size_t l = 0; l < r->lung_frames_.size(); ++l) {
    r->lung_frames_[l].force = std::span<const float>(r->force_.data() + l * c, c);
    // LPS: +x is the patient's left, so the lung whose centre has the larger x is the left one.
    r->lung_frames_[l].color = asset.lungs[l].centre[0] >= 0 ? config.color_left : config.color_right;
  }
  if (!r->parts_.lesions.empty()) {
    Result<render::LesionDrawable> drawable = render::LesionDrawable::create();
    if (!drawable) return drawable.with_context("lesion: ");
    r->lesion_drawable_.emplace(drawable.take());
    for (const sim::LesionRows& lesion : r->parts_.lesions) {
      if (lesion.placed.lung >= asset.lungs.size() || lesion.sh.size() != 3 * std::size_t{c})
        return fail("lesion " + lesion.placed.lesion.name + ": expected rows for this asset's lungs and " +
                    std::to_string(c) + " coefficients");
      render::LesionFrame frame;
      frame.radius_mm = static_cast<float>(lesion.placed.lesion.radius_mm);
      frame.color = config.color_lesion;
      r->lesion_frames_.push_back(frame);
    }
    r->lesion_excursions_.resize(r->parts_.lesions.size());
  }
  std::vector<std::string> names;
  for (const sim::BakedLung& lung : asset.lungs) names.push_back(lung.name);
  r->stats_.name_lungs(names);
  if (config.hud) {
    r->hud_.emplace();
    r->lesson_hud_.emplace();
  }
  r->last_patient_ = config.initial_patient;
  r->last_head_ = config.initial_head;
  r->previous_submit_ns_ = r->parts_.clock();
  return r;
}

Status Runtime::frame() { return draw_frame(nullptr); }

Status Runtime::final_frame(const std::string& png_path) { return draw_frame(&png_path); }

bool Runtime::keep_running() {
  if (!parts_.output->poll_events()) return false;
  take_keys();
  return !(frames_ > 0 && parts_.poses->finished());
}

/// docs/design.md, "One frame". The final frame (a snapshot) is drawn the same way but not recorded.
Status Runtime::draw_frame(const std::string* snapshot_png) {
  Result<FrameTiming> timing = parts_.output->begin_frame(parts_.clock());
  if (!timing) return timing.with_context("output: ");
  const std::int64_t now = parts_.clock();  // after the output's pacing, which may block (xrWaitFrame)
  const std::int64_t display_ns =
      timing->display_ns != 0 ? timing->display_ns : now + static_cast<std::int64_t>(frame_estimate_ms_ * 1e6);
  FrameState state;
  state.now_ns = now;
  state.breath = breathe(now);                            // 1. t -> P(t) -> V(t) -> dV(t)
  force_sh(now, state);                                   // 2. patient pose -> g in the lung frame -> f_lm
  const FrameViews& views = head_views(now, display_ns);  // 3. head pose at display time -> eye views
  if (timing->should_render) {
    if (Status drawn = deform_and_draw(state, views); !drawn) return drawn;  // 4. f_lm, dV -> shader -> points
  }
  if (snapshot_png != nullptr) {
    if (Status shot = parts_.output->snapshot(*snapshot_png); !shot) return shot.with_context("snapshot: ");
    return parts_.output->end_frame();
  }
  return present_and_record(state);  // 5. swap or finish; timing and pose age
}

sim::BreathingSample Runtime::breathe(std::int64_t now_ns) const { return parts_.breathing->at(now_ns); }

/// A scenario's pathology events: each lung's figures (its weight in the split, its volumes) into the patient the
/// force and the split read, and its shape's map into its draw. Copied in place: a frame allocates nothing.
void Runtime::follow_course(std::int64_t now_ns) {
  if (!parts_.course) return;
  const std::vector<sim::LungShape>& shapes = parts_.course->at(now_ns);
  for (std::size_t l = 0; l < lung_frames_.size() && l < shapes.size(); ++l) {
    patient_.lungs[l] = shapes[l].figures;
    lung_frames_[l].rest_transform = to_glm(shapes[l].from_loaded.matrix());
  }
}

void Runtime::force_sh(std::int64_t now_ns, FrameState& state) {
  follow_course(now_ns);
  const PoseSample patient = parts_.poses->latest(Role::Patient, now_ns);
  if (patient.valid()) last_patient_ = patient;
  const Eigen::Isometry3d lung = lung_to_world(pose_isometry(last_patient_), config_.registration);
  state.patient = last_patient_;
  state.lung_in_world = Eigen::Quaterniond(lung.rotation()).normalized();
  state.lung_origin_mm = lung.translation();
  state.gravity_lung = sim::gravity_in_lung_frame(state.lung_in_world);
  patient_force_sh(asset_, patient_, config_.orientation, state.lung_in_world, force_);
  for (std::size_t l = 0; l < lung_frames_.size(); ++l) {
    lung_frames_[l].linear = sim::linear_weights(asset_, patient_.lungs[l], state.gravity_lung);
  }
}

const FrameViews& Runtime::head_views(std::int64_t now_ns, std::int64_t display_ns) {
  const PoseSample head = parts_.poses->predicted(Role::Head, display_ns, max_ahead_ns_);
  if (head.valid()) last_head_ = head;
  measured_head_ = parts_.poses->latest(Role::Head, now_ns);  // its arrival dates the pose age
  return parts_.output->views(to_glm(head_to_world(last_head_, config_.head_to_eye_mm)));
}

Status Runtime::deform_and_draw(const FrameState& state, const FrameViews& views) {
  if (source_ == render::PositionSource::Uploaded) {
    deform_on_cpu(state);
    if (Status up = parts_.scene->drawable().upload_positions(cpu_positions_); !up) return up;
  }
  // Each lung sweeps its posture's share of the breath (lying on a side, the lower lung takes more), and of the
  // last breath's swing for the ventilation map.
  swing_.add(state.now_ns, state.breath.dv_ml);
  const double swing_ml = swing_.swing_ml();
  for (std::size_t l = 0; l < lung_frames_.size(); ++l) {
    const double share = sim::breath_share(asset_, patient_, l, state.gravity_lung);
    // A source that measures each lung (a mannequin's physiology engine) gives each its own dV.
    const double own = state.breath.lung_dv_ml[asset_.lungs[l].centre[0] >= 0 ? 0 : 1];
    lung_frames_[l].volume_change_ml = static_cast<float>(std::isfinite(own) ? own : state.breath.dv_ml * share);
    lung_frames_[l].sweep_ml = static_cast<float>(swing_ml * share);
  }
  move_lesions();
  if (Status drawn = draw_views(frame_inputs(state, views), views); !drawn) return drawn;
  draw_status_line(state.now_ns, state.breath.dv_ml, views);
  draw_legend(views);
  FrameState told = state;  // with each lung's dV as drawn, for the listeners (a session record keeps it)
  for (std::size_t l = 0; l < told.lung_dv_ml.size() && l < lung_frames_.size(); ++l)
    told.lung_dv_ml[l] = lung_frames_[l].volume_change_ml;
  for (const auto& listener : parts_.listeners) listener->on_frame(told);
  return ok();
}

/// Each lesion where the interior field puts it: its rows' dot product with its lung's force SH and linear weights,
/// times its lung's dV, as the shader moves a surface vertex (none for the rest shape); its lung's rest transform
/// too, so it stays in a lung a pathology reshapes. The path goes into its excursion.
void Runtime::move_lesions() {
  for (std::size_t k = 0; k < lesion_frames_.size(); ++k) {
    const sim::LesionRows& lesion = parts_.lesions[k];
    const render::LungFrame& lung = lung_frames_[lesion.placed.lung];
    const Eigen::Vector3d d = source_ == render::PositionSource::Rest
                                  ? Eigen::Vector3d::Zero()
                                  : lesion.displacement(lung.force, lung.linear, lung.volume_change_ml);
    const Eigen::Vector3d at = lesion.placed.lesion.centre_mm + d;
    lesion_frames_[k].centre_mm = glm::vec3(at.x(), at.y(), at.z());
    lesion_frames_[k].rest_transform = lung.rest_transform;
    lesion_excursions_[k].add(d);
  }
}

/// The paper's CPU baselines: eq. (7) from the same force SH, or eq. (1) from the transfer rows.
void Runtime::deform_on_cpu(const FrameState& state) {
  if (config_.deform == Deform::Cpu7) {
    sim::deform_eq7(asset_, patient_, force_, state.gravity_lung, state.breath.dv_ml, cpu_positions_);
  } else {
    eq1_->deform(patient_, state.gravity_lung, state.breath.dv_ml, cpu_positions_);
  }
}

render::FrameInputs Runtime::frame_inputs(const FrameState& state, const FrameViews& views) const {
  render::FrameInputs in;
  in.lungs = lung_frames_;
  in.eyes = views.span();
  in.model = to_glm(lung_to_world(pose_isometry(state.patient), config_.registration));
  in.mode = config_.mode;
  in.source = source_;
  in.strategy = config_.stereo_strategy;
  in.overlay_rest = config_.overlay_rest;
  in.point_size_px = config_.point_size_px;
  in.level_of_detail = config_.level_of_detail;
  in.background = config_.background;
  in.ventilation_full_scale_mm = ventilation_ ? config_.ventilation_full_scale_mm : 0.f;
  return in;
}

/// Side-by-side views are drawn in one call, views with their own targets one by one; then the output finishes
/// the scene (an output with a lens pass warps it) before the status line goes on top.
Status Runtime::draw_views(const render::FrameInputs& in, const FrameViews& views) {
  render::Renderer& renderer = parts_.scene->renderer();
  render::LungDrawable& drawable = parts_.scene->drawable();
  render::FrameInputs one = in;
  const std::size_t calls = views.shared_target ? 1 : views.count;
  for (std::size_t i = 0; i < calls; ++i) {
    parts_.output->bind_target(i);
    if (!views.shared_target) one.eyes = std::span<const render::EyeView>(&views.eyes[i], 1);
    if (Status drawn = renderer.draw(drawable, one, &last_draw_); !drawn) return drawn.with_context("draw: ");
    if (lesion_drawable_) lesion_drawable_->draw(lesion_frames_, one.model, one.eyes, one.ambient);
  }
  return parts_.output->finish_scene(views);
}

/// The on-screen lines: frame rate, pose age, source state, dV; under them the breathing and the pathologies in
/// force. Re-rasterised four times a second.
void Runtime::draw_status_line(std::int64_t now_ns, double dv_ml, const FrameViews& views) {
  if (now_ns - hud_updated_ns_ >= kStatusLinePeriodNs) {
    hud_updated_ns_ = now_ns;
    follow_lesson(now_ns);
    char text[render::HudLine::kMaxChars + 1];
    const double fps = frame_estimate_ms_ > 0 ? 1000.0 / frame_estimate_ms_ : 0.0;
    if (measured_head_.valid()) {
      std::snprintf(text, sizeof text, "%.0f FPS  POSE AGE %.0f MS  TRACKER %s%s  DV %.0f ML", fps,
                    ms_between(measured_head_.t_arrival_ns, now_ns), parts_.poses->state(),
                    measured_head_.stale() ? " (STALE POSE)" : "", dv_ml);
    } else {  // no pose has come yet: there is no age to give
      std::snprintf(text, sizeof text, "%.0f FPS  NO POSE YET  TRACKER %s  DV %.0f ML", fps, parts_.poses->state(),
                    dv_ml);
    }
    if (hud_) hud_->set_text(text);
  }
  if (!hud_) return;
  for (std::size_t i = 0; i < views.count; ++i) {
    if (!views.shared_target) parts_.output->bind_target(i);
    hud_->draw(views.eyes[i].viewport);
    lesson_hud_->draw_at(views.eyes[i].viewport, 4, views.eyes[i].viewport.height - 4 - 2 * render::HudLine::kCellH);
  }
}

/// What the lesson has in force now, from the breathing clock's pattern and the lungs' course (or the run's own
/// pathologies); said in the log each time it changes (a scenario's event), so a trainer reading the log later
/// sees when each change came. Allocates only on a change.
void Runtime::follow_lesson(std::int64_t now_ns) {
  char text[320];
  const std::string* course = parts_.course ? parts_.course->pathologies_now() : nullptr;
  const char* pathologies = course ? course->c_str() : config_.pathologies.c_str();
  if (const sim::Pattern* p = parts_.breathing->pattern_at(now_ns)) {
    const std::string_view preset = sim::to_string(p->params.preset);
    std::snprintf(text, sizeof text, "breathing %.*s %.0f/min %.0f mL%s%s, pathologies %s",
                  static_cast<int>(preset.size()), preset.data(), p->params.rate_bpm, p->params.tidal_volume_ml,
                  p->params.mode == sim::Mode::Ventilator ? " on the ventilator" : "",
                  p->apnoea ? " (apnoea)" : (p->held ? " (hold)" : ""), pathologies);
  } else {
    std::snprintf(text, sizeof text, "breathing followed, pathologies %s", pathologies);
  }
  if (lesson_ == text) return;
  lesson_ = text;
  log_line("lungar", "in force: " + lesson_);
  if (lesson_hud_) lesson_hud_->set_text(lesson_);
}

/// The ventilation map's legend in each view's bottom-left corner, while the map is shown.
void Runtime::draw_legend(const FrameViews& views) {
  if (!ventilation_) return;
  if (!legend_) legend_.emplace(config_.ventilation_full_scale_mm);
  for (std::size_t i = 0; i < views.count; ++i) {
    if (!views.shared_target) parts_.output->bind_target(i);
    legend_->draw(views.eyes[i].viewport);
  }
}

/// V toggles the ventilation map; the class (the instructor's console) may ask for it on or off.
void Runtime::take_keys() {
  for (char key : parts_.output->take_keys())
    if (key == 'v') show_ventilation(!ventilation_, "");
  bool asked = false;
  if (parts_.display && parts_.display->ventilation_map_since(display_version_, asked))
    show_ventilation(asked, " (the instructor's console)");
}

void Runtime::show_ventilation(bool on, const char* why) {
  if (source_ != render::PositionSource::Shader) {
    log_line("lungar", std::string("ventilation map: drawn by the vertex shader; not with --deform ") +
                           std::string(to_string(config_.deform)) + why);
    return;
  }
  if (on == ventilation_) return;
  ventilation_ = on;
  log_line("lungar", std::string(ventilation_ ? "ventilation map: on (V hides it)" : "ventilation map: off") + why);
}

Status Runtime::present_and_record(const FrameState& state) {
  if (Status shown = parts_.output->end_frame(); !shown) return shown.with_context("output: ");
  const std::int64_t submitted = parts_.clock();
  const double frame_ms = ms_between(previous_submit_ns_, submitted);
  previous_submit_ns_ = submitted;
  frame_estimate_ms_ = 0.9 * frame_estimate_ms_ + 0.1 * frame_ms;
  const double age_ms = measured_head_.valid() ? ms_between(measured_head_.t_arrival_ns, submitted) : -1.0;
  const Eigen::Vector3d& g = state.gravity_lung;
  stats_.record(frame_ms, age_ms, state.breath.dv_ml, {g.x(), g.y(), g.z()});
  std::array<double, kMaxStatsLungs> lung_ml{}, rest_ml{};
  const std::size_t lungs = std::min(lung_frames_.size(), kMaxStatsLungs);
  for (std::size_t l = 0; l < lungs; ++l) {
    lung_ml[l] = lung_frames_[l].volume_change_ml;
    rest_ml[l] = patient_.lungs[l].rest_volume_ml;
  }
  stats_.record_lungs(std::span<const double>(lung_ml.data(), lungs), std::span<const double>(rest_ml.data(), lungs));
  stats_.record_ventral_share(ventral_->share(asset_, patient_, force_, state.gravity_lung));
  ++frames_;
  return ok();
}

nlohmann::ordered_json Runtime::stats_json(double wall_s) const {
  nlohmann::ordered_json j = stats_.to_json();
  j["nodes"] = asset_.vertex_count();
  j["view"] = config_.stereo ? "stereo" : "mono";
  j["deform"] = to_string(config_.deform);
  j["ventilation_map"] = ventilation_;
  j["asset"] = parts_.scene->name();
  nlohmann::json parts = nlohmann::json::object();
  parts_.poses->add_stats(parts, wall_s);
  parts_.breathing->add_stats(parts);
  parts_.output->add_stats(parts);
  if (parts_.course) parts_.course->add_stats(parts);
  if (!parts_.lesions.empty()) {
    nlohmann::json lesions = nlohmann::json::array();
    for (std::size_t k = 0; k < parts_.lesions.size(); ++k) {
      const sim::PlacedLesion& p = parts_.lesions[k].placed;
      const Eigen::Vector3d& c = p.lesion.centre_mm;
      lesions.push_back({{"name", p.lesion.name},
                         {"lung", asset_.lungs[p.lung].name},
                         {"centre_mm", {c.x(), c.y(), c.z()}},
                         {"radius_mm", p.lesion.radius_mm},
                         {"peak_to_peak_mm", lesion_excursions_[k].peak_to_peak_mm()},
                         {"si_mm", lesion_excursions_[k].si_mm()}});
    }
    parts["lesions"] = lesions;
  }
  for (const auto& [key, value] : parts.items()) j[key] = value;
  j["wall_s"] = wall_s;
  return j;
}

std::string Runtime::summary(double wall_s) const {
  const SourceCounters c = parts_.poses->counters(wall_s);
  char line[320];
  std::snprintf(line, sizeof line, "%s; tracker %s: %llu reports at %.1f Hz, %llu malformed, %llu reconnects",
                stats_.summary().c_str(), c.state, static_cast<unsigned long long>(c.reports), c.rate_hz,
                static_cast<unsigned long long>(c.malformed), static_cast<unsigned long long>(c.reconnects));
  return line;
}

}  // namespace lungar::platform
