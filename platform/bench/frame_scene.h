/// @file frame_scene.h
/// @brief One asset on the GPU, drawn frame after frame as the runtime draws it, for timing: force SH, the
/// deformation (eq. 7 in the shader, or eq. 7 / eq. 1 on the CPU and uploaded), the draw into a headless
/// FrameTarget (640x720 mono, 2 x 640x720 stereo side by side) and glFinish.
///
/// The scene is fixed so that runs compare: the head 450 mm in front of the lungs' centre (the render bench's
/// scene), the patient turning slowly between upright and supine, breathing 0..500 mL every 4 s of frame time.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "platform/bench/rep_timer.h"
#include "render/frame_target.h"
#include "render/lung_drawable.h"
#include "render/renderer.h"
#include "render/stereo_view.h"
#include "sim/asset/baked_asset.h"
#include "sim/deform/deform_eq1.h"

namespace lungar::platform::bench {

/// Where eq. (7) or eq. (1) is evaluated (the rows of the paper's Table II), or Rest: the undeformed points, no
/// force and no deformation, against which the deformation's cost is measured.
enum class Method { Gpu7, Cpu7, Cpu1, Rest };
const char* to_string(Method m);

struct FrameConfig {
  Method method = Method::Gpu7;
  bool stereo = true;
  render::DrawMode mode = render::DrawMode::Points;
  render::StereoStrategy strategy = render::FrameInputs{}.strategy;  ///< the renderer's default
  bool lod = true;
  float point_size_px = 5.f;
};

struct FrameResult {
  RepStats stats;
  std::uint32_t points_per_eye = 0;  ///< drawn for the first eye in the last frame (0 for a mesh)
  long frames = 0;                   ///< including the warm-up
  double load_1min = -1;             ///< load average right after the measurement
};

/// The CPU work of a frame alone, without drawing: what the "CPU eq. (7) >= 20x faster than eq. (1)" target means.
enum class CpuWork { ForceSh, Eq7, Eq1 };

/// The two off-screen targets; one per process (creating GL targets per asset would only add noise).
struct Targets {
  render::FrameTarget mono, stereo;
  static Result<Targets> create(int eye_width_px, int eye_height_px);
};

class FrameScene {
 public:
  /// Uploads `asset` (which must outlive the scene) with `options`; needs a current GLES 3 context.
  static Result<std::unique_ptr<FrameScene>> create(const sim::BakedAsset& asset, Targets& targets,
                                                              const render::DrawableOptions& options = {});

  /// Times `config` (an error when it does not fit: CPU eq. 1 without transfer rows, a mesh without triangles).
  Result<FrameResult> measure(const FrameConfig& config, const Timing& timing);
  /// Times `a` and `b` interleaved (rep_timer.h), for the ratio b / a.
  Result<PairedStats> measure_pair(const FrameConfig& a, const FrameConfig& b, const Timing& timing);
  /// Times the CPU deformation step alone.
  RepStats measure_cpu(CpuWork work, const Timing& timing);
  /// Draws one frame of `config` and writes the target to a PNG, for looking at what was timed.
  Status snapshot(const FrameConfig& config, const std::string& png_path);

  const render::LungDrawable& drawable() const { return *drawable_; }

 private:
  FrameScene(const sim::BakedAsset& asset, Targets& targets) : asset_(asset), targets_(targets) {}
  Status fits(const FrameConfig& config) const;  ///< whether the asset can draw `config`
  Status frame(const FrameConfig& config, long k, render::FrameStats* stats);
  void breathe(long k, double& dv_ml, Eigen::Quaterniond& lung_in_world) const;

  const sim::BakedAsset& asset_;
  Targets& targets_;
  std::optional<render::LungDrawable> drawable_;
  std::optional<render::Renderer> renderer_;
  std::optional<sim::Eq1Deformer> eq1_;
  std::vector<float> force_, cpu_positions_;
  std::vector<render::LungFrame> lungs_;
  render::EyeView mono_;
  std::array<render::EyeView, 2> stereo_;
};

}  // namespace lungar::platform::bench
