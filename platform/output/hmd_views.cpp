/// @file hmd_views.cpp
/// @brief Side-by-side eye views from the HMD geometry.
#include "platform/output/hmd_views.h"

#include <Eigen/Geometry>

#include "platform/registration/display_calibration.h"
#include "platform/runtime/gl_math.h"

namespace lungar::platform {

render::HmdGeometry::CalibratedEye calibrated_eye(const std::array<double, 12>& p_sensor, const HmdSettings& s) {
  // The runtime's head frame (OpenGL: +y up, -z forward) sits at head_to_eye_mm in the sensor's frame, turned
  // +90 degrees about x (platform/runtime/runtime.cpp, head_to_world): X_sensor = T(e) Rx(90) X_head.
  Eigen::Affine3d sensor_from_head = Eigen::Affine3d::Identity();
  sensor_from_head.translate(Eigen::Vector3d(s.head_to_eye_mm[0], s.head_to_eye_mm[1], s.head_to_eye_mm[2]));
  sensor_from_head.rotate(Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitX()));
  const Eigen::Matrix<double, 3, 4, Eigen::RowMajor> p(p_sensor.data());
  const Eigen::Matrix<double, 3, 4> p_head = p * sensor_from_head.matrix();
  const Result<EyeCalibration> d = decompose_projection(p_head);  // validated when the settings were read
  const Eigen::Matrix3d k = d ? d->intrinsics : Eigen::Matrix3d::Identity();
  Eigen::Matrix4d cam_from_head = Eigen::Matrix4d::Identity();  // the eye camera: x right, y down, z forward
  if (d) {
    cam_from_head.topLeftCorner<3, 3>() = d->rotation;
    cam_from_head.topRightCorner<3, 1>() = -d->rotation * d->centre_mm;
  }
  const Eigen::Matrix4d gl_from_cam = Eigen::Vector4d(1, -1, -1, 1).asDiagonal();
  // K to an OpenGL projection of the eye's viewport (pixels from its top-left corner), with the config's planes.
  const double w = s.eye_width_px, h = s.eye_height_px, n = s.near_mm, f = s.far_mm;
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj.row(0) << 2 * k(0, 0) / w, -2 * k(0, 1) / w, 1 - 2 * k(0, 2) / w, 0;
  proj.row(1) << 0, 2 * k(1, 1) / h, 2 * k(1, 2) / h - 1, 0;
  proj.row(2) << 0, 0, -(f + n) / (f - n), -2 * f * n / (f - n);
  proj.row(3) << 0, 0, -1, 0;
  return {to_glm(gl_from_cam * cam_from_head), to_glm(proj)};
}

render::HmdGeometry hmd_geometry(const HmdSettings& s) {
  render::HmdGeometry g{s.ipd_mm,       s.fov_inner_deg, s.fov_outer_deg, s.fov_up_deg, s.fov_down_deg,
                        s.eye_width_px, s.eye_height_px, s.near_mm,       s.far_mm,     std::nullopt};
  if (s.display_calibration) {
    g.calibrated = {calibrated_eye((*s.display_calibration)[0], s), calibrated_eye((*s.display_calibration)[1], s)};
  }
  return g;
}

std::array<int, 2> HmdViews::target_size(const HmdSettings& hmd) {
  const int eyes = hmd.view == View::Stereo ? 2 : 1;
  return {eyes * hmd.eye_width_px, hmd.eye_height_px};
}

const FrameViews& HmdViews::views(const glm::mat4& head_to_world) {
  views_.shared_target = true;
  if (stereo_) {
    views_.eyes = view_.eyes(head_to_world);
    views_.count = 2;
  } else {
    views_.eyes[0] = view_.mono(head_to_world, width_, height_);
    views_.count = 1;
  }
  // The eyes fill the target side by side whatever its size (a window may not be two eyes wide).
  const int n = static_cast<int>(views_.count);
  for (int e = 0; e < n; ++e) views_.eyes[e].viewport = {e * width_ / n, 0, width_ / n, height_};
  return views_;
}

}  // namespace lungar::platform
