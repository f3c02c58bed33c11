/// @file runtime_settings.cpp
/// @brief Settings -> RuntimeConfig.
#include "platform/app/runtime_settings.h"

#include "drivers/mock/mock_trajectory.h"
#include "platform/runtime/gl_math.h"
#include "platform/runtime/patient_force.h"

namespace lungar::platform {

namespace {

drivers::PoseSample static_scene_pose(drivers::Role role) {
  return drivers::mock_pose("static", role, 0.0).value_or(drivers::PoseSample{});
}

}  // namespace

RuntimeConfig runtime_config(const Settings& s) {
  const RenderSettings& r = s.render;
  RuntimeConfig c;
  c.deform = r.deform;
  c.orientation = s.sim.orientation_mode;
  c.mode = r.mode;
  c.stereo_strategy = r.stereo_strategy;
  c.stereo = s.hmd.view == View::Stereo;
  c.overlay_rest = r.overlay_rest;
  c.point_size_px = static_cast<float>(r.point_size_px);
  c.level_of_detail = r.lod;
  c.hud = r.hud;
  c.pathologies.clear();
  for (const std::string& spec : s.sim.pathologies) c.pathologies += (c.pathologies.empty() ? "" : ", ") + spec;
  if (c.pathologies.empty()) c.pathologies = "none";
  c.ventilation_map = r.ventilation_map;
  c.ventilation_full_scale_mm = static_cast<float>(r.ventilation_full_scale_mm);
  c.color_left = to_glm(r.color_left);
  c.color_lesion = to_glm(r.color_lesion);
  c.color_right = to_glm(r.color_right);
  c.background = to_glm(r.background);
  c.registration = registration_isometry(s.registration.translation_mm, s.registration.rotation_wxyz);
  c.head_to_eye_mm = s.hmd.head_to_eye_mm;
  c.prediction_max_ms = s.hmd.prediction_max_ms;
  c.initial_patient = static_scene_pose(drivers::Role::Patient);
  c.initial_head = static_scene_pose(drivers::Role::Head);
  return c;
}

}  // namespace lungar::platform
