/// @file bench_frame.h
/// @brief What the bench times: the shipped Runtime's frame (platform/runtime/runtime.h), built over one lung
/// scene per asset with scripted inputs (scripted_inputs.h) and a headless output, one Runtime per measured
/// configuration (deformation method, mono or stereo, points or mesh, stereo strategy, LOD, point size).
/// @ingroup bench
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "platform/app/settings.h"
#include "platform/bench/rep_timer.h"
#include "platform/egl/egl_context.h"
#include "platform/runtime/lung_scene.h"
#include "platform/runtime/runtime.h"
#include "sim/motion/interior_displacement.h"

namespace lungar::platform::bench {

class BenchConsole;

/// Where eq. (7) or eq. (1) is evaluated (the rows of the paper's Table II), or Rest: the undeformed points, no
/// force and no deformation, against which the deformation's cost is measured.
enum class Method { Gpu7, Cpu7, Cpu1, Rest };
const char* to_string(Method m);

struct FrameConfig {
  Method method = Method::Gpu7;
  bool stereo = true;
  render::DrawMode mode = render::DrawMode::Points;
  render::StereoStrategy strategy = RenderSettings{}.stereo_strategy;  ///< the shipped default
  bool lod = true;
  double point_size_px = 5.0;
  /// Lesions drawn inside the lungs (RuntimeParts::lesions): what one costs a frame. 5 mm balls at points sampled
  /// inside the lungs (lesion_rows()).
  int lesions = 0;
  /// The instructor's console open, its class control hearing each frame, and a page watching its live view
  /// while these frames run (bench_console.h).
  bool console = false;
};

/// The settings a configuration runs with: the defaults, the configuration, no status line (it times the lungs),
/// and the eyes at the head sensor (the script places the head).
Settings bench_settings(const FrameConfig& c);

struct FrameResult {
  RepStats stats;
  std::uint32_t points_per_eye = 0;  ///< drawn for the first eye in the last frame (0 for a mesh)
  long frames = 0;                   ///< including the warm-up
  double load_1min = -1;             ///< load average right after the measurement
};

/// The CPU work of a frame alone, without drawing: what the "CPU eq. (7) >= 20x faster than eq. (1)" target means.
/// ForceShArds: the force SH with ARDS (sim/force/dependent_collapse.h), the posture changing every frame, so
/// that the collapse plane and the pattern's fits are redone each time (the worst case).
enum class CpuWork { ForceSh, ForceShArds, Eq7, Eq1 };

class BenchScene {
 public:
  /// Uploads `asset` once on `context` (current on this thread).
  static Result<std::unique_ptr<BenchScene>> create(std::shared_ptr<EglContext> context, sim::BakedAsset asset,
                                                    std::string name, const render::DrawableOptions& options = {});
  ~BenchScene();

  /// Times `config`'s frames (an error when it does not fit: CPU eq. 1 without transfer rows, a mesh without
  /// triangles).
  Result<FrameResult> measure(const FrameConfig& config, const Timing& timing);
  /// Times `a` and `b` interleaved (rep_timer.h), for the ratio b / a.
  Result<PairedStats> measure_pair(const FrameConfig& a, const FrameConfig& b, const Timing& timing);
  /// Times the CPU deformation step alone (sim/, no Runtime: nothing is drawn).
  RepStats measure_cpu(CpuWork work, const Timing& timing);
  /// Draws frame 60 (1 s in, mid-inhalation) of `config` and writes it to a PNG.
  Status snapshot(const FrameConfig& config, const std::string& png_path);

  const sim::BakedAsset& asset() const { return scene_->asset(); }
  bool uses_texture() const { return scene_->drawable().uses_texture(); }

 private:
  BenchScene() = default;
  Result<std::unique_ptr<Runtime>> runtime_for(const FrameConfig& config);
  /// `count` lesions placed in the scene's lungs, with their rows; the interior field is built on first use.
  Result<std::vector<sim::LesionRows>> lesion_rows(int count);

  std::shared_ptr<EglContext> context_;
  std::shared_ptr<LungScene> scene_;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  std::unique_ptr<sim::InteriorDisplacement> interior_;
  std::unique_ptr<BenchConsole> console_;  ///< started by the first configuration with the console
  std::int64_t now_ns_ = 0;  ///< the scripted clock every Runtime of this scene reads
};

}  // namespace lungar::platform::bench
