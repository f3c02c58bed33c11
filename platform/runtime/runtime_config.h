/// @file runtime_config.h
/// @brief What a Runtime is told, and nothing more (as Filament's Engine takes its own small Engine::Config):
/// how to deform and draw, where the lungs sit on the patient sensor, how far to predict the head, and the poses
/// to use before a source has delivered one. platform/app/ fills it from the settings.
/// @ingroup platform
#pragma once

#include <array>
#include <string>

#include <Eigen/Geometry>
#include <glm/vec3.hpp>

#include "config/base/enum_names.h"
#include "drivers/pose/pose_sample.h"
#include "render/draw_modes.h"
#include "sim/force/force_sh.h"

namespace lungar::platform {

/// Where the deformation is evaluated: the vertex shader (eq. 7), the CPU by eq. (7) or eq. (1); or None, the
/// rest shape undeformed (what the deformation is compared with, and what the bench measures it against).
enum class Deform { Gpu, Cpu7, Cpu1, None };
inline constexpr EnumNames<Deform, 4> kDeformNames{
    {{{Deform::Gpu, "gpu"}, {Deform::Cpu7, "cpu7"}, {Deform::Cpu1, "cpu1"}, {Deform::None, "none"}}}};
inline const char* to_string(Deform v) { return kDeformNames.name(v); }

struct RuntimeConfig {
  Deform deform = Deform::Gpu;
  sim::ForceMode orientation = sim::ForceMode::Exact;  ///< orientation -> force SH (docs/design.md, Orientation)
  render::DrawMode mode = render::DrawMode::Points;
  render::StereoStrategy stereo_strategy = render::StereoStrategy::PerEye;
  bool stereo = true;  ///< what the stats JSON's "view" says; the output places the eyes
  bool overlay_rest = false;
  float point_size_px = 5.0f;
  bool level_of_detail = true;
  bool hud = true;  ///< the status line
  /// The run's pathologies for the status line ("none", or "pneumothorax:right:30, ..."), when no course of them
  /// says what is in force.
  std::string pathologies = "none";
  /// The ventilation map from the first frame (the V key toggles it), with this sweep at the ramp's top.
  bool ventilation_map = false;
  float ventilation_full_scale_mm = 20.0f;
  glm::vec3 color_left{0.90f, 0.45f, 0.45f};
  glm::vec3 color_right{0.45f, 0.60f, 0.95f};
  glm::vec3 color_lesion{1.00f, 0.85f, 0.10f};  ///< lesions (RuntimeParts::lesions)
  glm::vec3 background{0.0f, 0.0f, 0.0f};
  Eigen::Isometry3d registration = Eigen::Isometry3d::Identity();  ///< lung model -> patient sensor
  std::array<double, 3> head_to_eye_mm = {0.0, -80.0, -70.0};      ///< centre of the eyes in the head sensor's frame
  double prediction_max_ms = 50.0;                                 ///< bound on constant-velocity head prediction
  /// The poses drawn until the pose source delivers one (the app passes the demo's static scene).
  drivers::PoseSample initial_patient;
  drivers::PoseSample initial_head;
};

}  // namespace lungar::platform
