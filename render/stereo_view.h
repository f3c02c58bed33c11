/// @file stereo_view.h
/// @brief Per-eye views and asymmetric projections of an HMD (IPD, per-eye field of view, resolution, layout).
///
/// Plain numbers in, glm matrices out: render/ does not read config/ (platform/ copies HmdSettings over).
/// Head frame: the OpenGL camera convention, +x right, +y up, looking down -z, origin midway between the eyes, mm.
#pragma once

#include <array>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace lungar::render {

/// A pixel rectangle of the target framebuffer.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
};

/// One eye (or the single mono view) of a frame.
struct EyeView {
  glm::mat4 view{1.f};        ///< world -> eye
  glm::mat4 projection{1.f};  ///< eye -> clip, possibly off-axis
  Viewport viewport;
};

/// HMD optics and panel, per eye. Field-of-view angles are measured from the eye's optical axis.
struct HmdGeometry {
  double ipd_mm = 63.0;
  double fov_inner_deg = 40.0;  ///< toward the nose
  double fov_outer_deg = 50.0;  ///< toward the temple
  double fov_up_deg = 45.0;
  double fov_down_deg = 45.0;
  int eye_width_px = 640;
  int eye_height_px = 720;
  double near_mm = 50.0;
  double far_mm = 5000.0;
  /// A display calibration per eye (SPAAM), in place of the IPD and fields of view: each eye's view relative to
  /// the head frame and its projection, in OpenGL's conventions (platform/output/hmd_views.cpp builds them).
  struct CalibratedEye {
    glm::mat4 eye_from_head{1.f};
    glm::mat4 projection{1.f};
  };
  std::optional<std::array<CalibratedEye, 2>> calibrated;
};

class StereoView {
 public:
  explicit StereoView(const HmdGeometry& hmd) : hmd_(hmd) {}

  /// Left then right eye for a head pose (head -> world); side by side: left eye in the left half of the target.
  std::array<EyeView, 2> eyes(const glm::mat4& head_to_world) const;
  /// A single symmetric view from the head centre filling a width x height target, with the HMD's vertical field.
  EyeView mono(const glm::mat4& head_to_world, int width_px, int height_px) const;

  /// The side-by-side target size.
  int target_width() const { return 2 * hmd_.eye_width_px; }
  int target_height() const { return hmd_.eye_height_px; }
  const HmdGeometry& geometry() const { return hmd_; }

  /// The off-axis projection of one eye: left eye (left = true) has its temple on the left.
  glm::mat4 projection(bool left) const;

 private:
  HmdGeometry hmd_;
};

/// A head -> world pose looking from `eye` toward `target` with `up`: for tests, demos and benchmarks.
glm::mat4 look_from(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up);

}  // namespace lungar::render
