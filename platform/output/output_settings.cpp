/// @file output_settings.cpp
/// @brief The [display] and [hmd] keys: types, ranges and units.
#include "platform/output/output_settings.h"

#include <cmath>
#include <limits>

#include "platform/registration/display_calibration.h"

namespace lungar::platform {

void read_display_settings(config::TomlSection s, DisplaySettings& d) {
  s.choice("output", d.output, kOutputNames);
  s.integer("width_px", d.width_px, 16, 16384, "pixels");
  s.integer("height_px", d.height_px, 16, 16384, "pixels");
  s.integer("x_px", d.x_px, -65536, 65536, "pixels");
  s.integer("y_px", d.y_px, -65536, 65536, "pixels");
  s.text("x11_output", d.x11_output);
  s.boolean("vsync", d.vsync);
  s.number("max_fps", d.max_fps, 0.0, 1000.0, "frames/s");
  config::TomlSection xr = s.section("openxr");
  xr.choice("head", d.openxr.head, kXrHeadNames);
  xr.choice("reference_space", d.openxr.reference_space, kXrReferenceSpaceNames);
  xr.finish();
  s.finish();
}

void read_hmd_settings(config::TomlSection s, HmdSettings& h) {
  s.choice("view", h.view, kViewNames);
  s.choice("layout", h.layout, {"side_by_side"});
  s.integer("eye_width_px", h.eye_width_px, 16, 8192, "pixels");
  s.integer("eye_height_px", h.eye_height_px, 16, 8192, "pixels");
  s.number("ipd_mm", h.ipd_mm, 40.0, 90.0, "mm");
  s.number("fov_inner_deg", h.fov_inner_deg, 1.0, 89.0, "degrees");
  s.number("fov_outer_deg", h.fov_outer_deg, 1.0, 89.0, "degrees");
  s.number("fov_up_deg", h.fov_up_deg, 1.0, 89.0, "degrees");
  s.number("fov_down_deg", h.fov_down_deg, 1.0, 89.0, "degrees");
  s.numbers("head_to_eye_mm", h.head_to_eye_mm, -500.0, 500.0, "mm");
  s.number("near_mm", h.near_mm, 1.0, 1e5, "mm");
  s.number("far_mm", h.far_mm, 1.0, 1e6, "mm");
  s.number("prediction_max_ms", h.prediction_max_ms, 0.0, 200.0, "ms");
  if (h.far_mm <= h.near_mm) {
    s.fail("far_mm", "expected far_mm greater than near_mm (" + std::to_string(h.near_mm) + " mm)");
  }
  config::TomlSection lens = s.section("lens");
  lens.boolean("enabled", h.lens.enabled);
  lens.numbers("k1", h.lens.k1, -1.0, 1.0, "");
  lens.numbers("k2", h.lens.k2, -1.0, 1.0, "");
  lens.finish();
  config::TomlSection cal = s.section("display_calibration");
  constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
  std::array<std::array<double, 12>, 2> p;
  for (auto& eye : p) eye.fill(kUnset);
  cal.numbers("left_projection_3x4", p[0], -1e9, 1e9, "(homogeneous, mm -> pixels)");
  cal.numbers("right_projection_3x4", p[1], -1e9, 1e9, "(homogeneous, mm -> pixels)");
  const bool left = !std::isnan(p[0][0]), right = !std::isnan(p[1][0]);
  if (left != right) {
    cal.fail(left ? "right_projection_3x4" : "left_projection_3x4",
             "expected both eyes' projections (lungar calibrate-display writes both), got one");
  }
  for (int e = 0; left && e < 2; ++e) {
    const Eigen::Matrix<double, 3, 4, Eigen::RowMajor> m(p[static_cast<std::size_t>(e)].data());
    if (auto d = decompose_projection(m); !d) cal.fail(e == 0 ? "left_projection_3x4" : "right_projection_3x4", d.error());
  }
  if (left) h.display_calibration = p;
  cal.finish();
  s.finish();
}

}  // namespace lungar::platform
