/// @file frame_scene.cpp
/// @brief The benchmark frame: the runtime's steps 2, 4 and 5 (platform/runtime/runtime.cpp) with a scripted
/// patient and breathing instead of a tracker, so that every configuration sees the same inputs.
#include "platform/bench/frame_scene.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/common.hpp>

#include "platform/bench/system_info.h"
#include "render/png_snapshot.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/force_sh.h"
#include "sim/force/gravity.h"

namespace lungar::platform::bench {

namespace {
constexpr double kFrameDtS = 1.0 / 60.0;     // scripted time per frame, whatever the real frame time
constexpr double kBreathPeriodS = 4.0;
constexpr double kTidalVolumeMl = 500.0;
constexpr double kTurnPeriodS = 20.0;
constexpr float kHeadDistanceMm = 450.f;      // the render bench's scene: LOD coverage 3 is hole-free there
}  // namespace

const char* to_string(Method m) {
  switch (m) {
    case Method::Gpu7: return "gpu_eq7";
    case Method::Cpu7: return "cpu_eq7";
    case Method::Cpu1: return "cpu_eq1";
    case Method::Rest: return "undeformed";
  }
  return "?";
}

Result<Targets> Targets::create(int eye_width_px, int eye_height_px) {
  auto mono = render::FrameTarget::create(eye_width_px, eye_height_px);
  if (!mono) return fail("mono target: " + mono.error());
  auto stereo = render::FrameTarget::create(2 * eye_width_px, eye_height_px);
  if (!stereo) return fail("stereo target: " + stereo.error());
  return Targets{mono.take(), stereo.take()};
}

Result<std::unique_ptr<FrameScene>> FrameScene::create(const sim::BakedAsset& asset, Targets& targets,
                                                                  const render::DrawableOptions& options) {
  using Out = Result<std::unique_ptr<FrameScene>>;
  std::unique_ptr<FrameScene> s(new FrameScene(asset, targets));
  auto drawable = render::LungDrawable::create(asset, options);
  if (!drawable) return fail("asset: " + drawable.error());
  s->drawable_.emplace(drawable.take());
  auto renderer = render::Renderer::create(*s->drawable_);
  if (!renderer) return fail("renderer: " + renderer.error());
  s->renderer_.emplace(renderer.take());
  if (asset.has_transfer_rows()) s->eq1_.emplace(asset);

  const std::uint32_t c = asset.coefficients();
  s->force_.assign(asset.lungs.size() * c, 0.f);
  s->cpu_positions_.assign(asset.positions.size(), 0.f);
  s->lungs_.resize(asset.lungs.size());
  for (std::size_t l = 0; l < s->lungs_.size(); ++l) {
    s->lungs_[l].force = std::span<const float>(s->force_.data() + l * c, c);
    s->lungs_[l].color = asset.lungs[l].centre[0] >= 0 ? glm::vec3(0.45f, 0.6f, 0.95f) : glm::vec3(0.9f, 0.45f, 0.45f);
  }

  // The head looks at the middle of the pair's bounding box from the front (LPS: anterior is -y), +z up.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (std::size_t i = 0; i + 2 < asset.positions.size(); i += 3) {
    const glm::vec3 p(asset.positions[i], asset.positions[i + 1], asset.positions[i + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  const glm::mat4 head = render::look_from(centre + glm::vec3(0.f, -kHeadDistanceMm, 0.f), centre, {0.f, 0.f, 1.f});
  render::HmdGeometry hmd;
  hmd.eye_width_px = targets.mono.width();
  hmd.eye_height_px = targets.mono.height();
  const render::StereoView view(hmd);
  s->stereo_ = view.eyes(head);
  s->mono_ = view.mono(head, hmd.eye_width_px, hmd.eye_height_px);
  return Out(std::move(s));
}

void FrameScene::breathe(long k, double& dv_ml, Eigen::Quaterniond& lung_in_world) const {
  const double t = static_cast<double>(k) * kFrameDtS;
  dv_ml = 0.5 * kTidalVolumeMl * (1.0 - std::cos(2.0 * std::numbers::pi * t / kBreathPeriodS));
  const double turn = 0.25 * std::numbers::pi * (1.0 - std::cos(2.0 * std::numbers::pi * t / kTurnPeriodS));
  lung_in_world = Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitX()));
}

Status FrameScene::frame(const FrameConfig& config, long k, render::FrameStats* stats) {
  double dv = 0;
  Eigen::Quaterniond q;
  breathe(k, dv, q);
  render::FrameInputs in;
  in.source = render::PositionSource::Shader;
  if (config.method == Method::Gpu7 || config.method == Method::Cpu7) {
    sim::force_sh(asset_, sim::ForceMode::exact, q, force_.data());
  }
  if (config.method == Method::Cpu7) {
    sim::deform_eq7(asset_, force_, dv, cpu_positions_);
  } else if (config.method == Method::Cpu1) {
    eq1_->deform(sim::gravity_in_lung_frame(q), dv, cpu_positions_);
  }
  if (config.method == Method::Cpu7 || config.method == Method::Cpu1) {
    if (auto up = drawable_->upload_positions(cpu_positions_); !up) return up;
    in.source = render::PositionSource::Uploaded;
  } else if (config.method == Method::Rest) {
    in.source = render::PositionSource::Rest;
  }
  for (std::size_t l = 0; l < lungs_.size(); ++l) {
    lungs_[l].volume_change_ml = static_cast<float>(dv * asset_.lungs[l].volume_share);
  }
  in.lungs = lungs_;
  in.eyes = config.stereo ? std::span<const render::EyeView>(stereo_.data(), 2)
                          : std::span<const render::EyeView>(&mono_, 1);
  in.mode = config.mode;
  in.strategy = config.strategy;
  in.level_of_detail = config.lod;
  in.point_size_px = config.point_size_px;
  (config.stereo ? targets_.stereo : targets_.mono).bind();
  if (auto drawn = renderer_->draw(*drawable_, in, stats); !drawn) return drawn;
  glFinish();  // the frame is done when the pixels are, as in the headless runtime
  return ok();
}

Status FrameScene::fits(const FrameConfig& config) const {
  if (config.method == Method::Cpu1 && !eq1_) return fail("CPU eq. (1) expected an asset with transfer rows, got none");
  if (config.mode == render::DrawMode::Mesh && !drawable_->has_triangles()) {
    return fail("mesh mode expected an asset with triangles, got none");
  }
  return ok();
}

Result<FrameResult> FrameScene::measure(const FrameConfig& config, const Timing& timing) {
  if (auto st = fits(config); !st) return fail(st.error());
  FrameResult r;
  render::FrameStats stats;
  std::string error;
  r.stats = time_reps(
      timing,
      [&](long k) {
        if (!error.empty()) return;  // an error stops the work; the timing is thrown away below
        if (auto st = frame(config, k, &stats); !st) error = st.error();
      },
      &r.frames);
  if (!error.empty()) return fail(error);
  r.points_per_eye = stats.points_drawn[0];
  r.load_1min = load_average_1min();
  return r;
}

Result<PairedStats> FrameScene::measure_pair(const FrameConfig& a, const FrameConfig& b,
                                                        const Timing& timing) {
  if (auto st = fits(a); !st) return fail(st.error());
  if (auto st = fits(b); !st) return fail(st.error());
  std::string error;
  auto frame_of = [&](const FrameConfig& c) {
    return [&, c](long k) {
      if (!error.empty()) return;
      if (auto st = frame(c, k, nullptr); !st) error = st.error();
    };
  };
  PairedStats p = time_reps_paired(timing, frame_of(a), frame_of(b));
  if (!error.empty()) return fail(error);
  return p;
}

RepStats FrameScene::measure_cpu(CpuWork work, const Timing& timing) {
  return time_reps(timing, [&](long k) {
    double dv = 0;
    Eigen::Quaterniond q;
    breathe(k, dv, q);
    switch (work) {
      case CpuWork::ForceSh: sim::force_sh(asset_, sim::ForceMode::exact, q, force_.data()); break;
      case CpuWork::Eq7:
        sim::force_sh(asset_, sim::ForceMode::exact, q, force_.data());
        sim::deform_eq7(asset_, force_, dv, cpu_positions_);
        break;
      case CpuWork::Eq1:
        if (eq1_) eq1_->deform(sim::gravity_in_lung_frame(q), dv, cpu_positions_);
        break;
    }
  });
}

Status FrameScene::snapshot(const FrameConfig& config, const std::string& png_path) {
  if (auto st = fits(config); !st) return st;
  if (auto st = frame(config, 60, nullptr); !st) return st;  // frame 60: 1 s in, mid-inhalation
  const render::FrameTarget& t = config.stereo ? targets_.stereo : targets_.mono;
  return render::snapshot_png(png_path, 0, 0, t.width(), t.height());
}

}  // namespace lungar::platform::bench
