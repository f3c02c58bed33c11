/// @file bench_frame.cpp
/// @brief One Runtime per configuration over a shared scene, driven by the scripted clock.
#include "platform/bench/bench_frame.h"

#include <algorithm>
#include <array>
#include <limits>

#include "platform/app/runtime_settings.h"
#include "platform/bench/bench_console.h"
#include "platform/bench/scripted_inputs.h"
#include "platform/bench/system_info.h"
#include "platform/output/headless_output.h"
#include "sim/deform/deform_eq1.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/force_sh.h"
#include "sim/force/gravity.h"
#include "sim/pathology/pathology.h"

namespace lungar::platform::bench {

namespace {

/// Each method's name in the bench's JSON, and the runtime's deformation that times it.
struct MethodInfo {
  Method method;
  const char* name;
  Deform deform;
};
constexpr std::array<MethodInfo, 4> kMethods{{{Method::Gpu7, "gpu_eq7", Deform::Gpu},
                                              {Method::Cpu7, "cpu_eq7", Deform::Cpu7},
                                              {Method::Cpu1, "cpu_eq1", Deform::Cpu1},
                                              {Method::Rest, "undeformed", Deform::None}}};

const MethodInfo& info(Method m) {
  return *std::find_if(kMethods.begin(), kMethods.end(), [m](const MethodInfo& i) { return i.method == m; });
}

}  // namespace

const char* to_string(Method m) { return info(m).name; }

Settings bench_settings(const FrameConfig& c) {
  Settings s;
  s.display.output = Output::Headless;
  s.hmd.view = c.stereo ? View::Stereo : View::Mono;
  s.hmd.head_to_eye_mm = {0.0, 0.0, 0.0};
  s.render.deform = info(c.method).deform;
  s.render.mode = c.mode;
  s.render.stereo_strategy = c.strategy;
  s.render.lod = c.lod;
  s.render.point_size_px = c.point_size_px;
  s.render.hud = false;
  return s;
}

Result<std::unique_ptr<BenchScene>> BenchScene::create(std::shared_ptr<EglContext> context, sim::BakedAsset asset,
                                                       std::string name, const render::DrawableOptions& options) {
  std::unique_ptr<BenchScene> b(new BenchScene());
  b->context_ = std::move(context);
  // The head looks at the middle of the pair's bounding box.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (std::size_t i = 0; i + 2 < asset.positions.size(); i += 3) {
    const Eigen::Vector3d p(asset.positions[i], asset.positions[i + 1], asset.positions[i + 2]);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  b->centre_ = 0.5 * (lo + hi);
  auto scene = LungScene::create(std::move(asset), std::move(name), options);
  if (!scene) return scene.with_context("");
  b->scene_ = scene.take();
  return b;
}

BenchScene::~BenchScene() = default;

Result<std::unique_ptr<Runtime>> BenchScene::runtime_for(const FrameConfig& config) {
  const Settings s = bench_settings(config);
  auto output = HeadlessOutput::create(s.hmd, context_);
  if (!output) return output.with_context("");
  RuntimeParts parts;
  parts.scene = scene_;
  parts.output = output.take();
  parts.poses = std::make_unique<ScriptedPoses>(centre_);
  parts.breathing = std::make_unique<ScriptedBreathing>();
  parts.clock = [this] { return now_ns_; };
  if (config.console) {
    if (!console_) {
      auto started = BenchConsole::start();
      if (!started) return started.with_context("");
      console_ = started.take();
    }
    parts.listeners.push_back(console_->listener());
  }
  if (config.lesions > 0) {
    auto lesions = lesion_rows(config.lesions);
    if (!lesions) return lesions.with_context("");
    parts.lesions = lesions.take();
  }
  return Runtime::create(runtime_config(s), std::move(parts));
}

Result<std::vector<sim::LesionRows>> BenchScene::lesion_rows(int count) {
  const sim::BakedAsset& a = scene_->asset();
  if (!interior_) interior_ = std::make_unique<sim::InteriorDisplacement>(a);
  // Points inside the lungs, in sampling order, keeping those with room for a 5 mm ball.
  const sim::InteriorPoints points = interior_->sample(static_cast<std::size_t>(50 * count));
  std::vector<sim::PlacedLesion> placed;
  for (std::size_t p = 0; p < points.size() && placed.size() < static_cast<std::size_t>(count); ++p) {
    const sim::Lesion l{
        "bench" + std::to_string(placed.size()),
        Eigen::Vector3d(points.positions[3 * p], points.positions[3 * p + 1], points.positions[3 * p + 2]), 5.0};
    if (auto one = sim::place_lesions(*interior_, {l}); one) placed.push_back(one->front());
  }
  if (placed.size() < static_cast<std::size_t>(count))
    return fail("bench: room for " + std::to_string(placed.size()) + " lesions of 5 mm in the lungs, expected " +
                std::to_string(count));
  return sim::lesion_rows(a, *interior_, placed);
}

Result<FrameResult> BenchScene::measure(const FrameConfig& config, const Timing& timing) {
  auto runtime = runtime_for(config);
  if (!runtime) return runtime.with_context("");
  Runtime& r = **runtime;
  FrameResult result;
  std::string error;
  result.stats = time_reps(
      timing,
      [&](long k) {
        if (!error.empty()) return;  // an error stops the work; the timing is thrown away below
        now_ns_ = k * kFrameStepNs;
        if (Status st = r.frame(); !st) error = st.error();
      },
      &result.frames);
  if (!error.empty()) return fail(error);
  result.points_per_eye = r.last_draw().points_drawn[0];
  result.load_1min = load_average_1min();
  return result;
}

Result<PairedStats> BenchScene::measure_pair(const FrameConfig& a, const FrameConfig& b, const Timing& timing) {
  auto ra = runtime_for(a);
  if (!ra) return ra.with_context("");
  auto rb = runtime_for(b);
  if (!rb) return rb.with_context("");
  std::string error;
  auto frame_of = [&](Runtime& r, bool watched) {
    return [&, watched](long k) {
      if (!error.empty()) return;
      if (console_) console_->watch(watched);  // a page watches while, and only while, its frames run
      now_ns_ = k * kFrameStepNs;
      if (Status st = r.frame(); !st) error = st.error();
    };
  };
  PairedStats p = time_reps_paired(timing, frame_of(**ra, a.console), frame_of(**rb, b.console));
  if (console_) console_->watch(false);
  if (!error.empty()) return fail(error);
  if (console_ && (a.console || b.console) && console_->bytes_read() == 0)
    return fail("bench console: the page never read the live view");
  return p;
}

RepStats BenchScene::measure_cpu(CpuWork work, const Timing& timing) {
  const sim::BakedAsset& a = scene_->asset();
  std::vector<float> force(a.lungs.size() * a.coefficients()), positions(a.positions.size());
  std::optional<sim::Eq1Deformer> eq1;
  if (a.has_transfer_rows()) eq1.emplace(a);
  const sim::PatientState healthy = sim::PatientState::of(a);
  sim::BakedAsset ards;
  sim::PatientState ards_patient;
  if (work == CpuWork::ForceShArds) {
    ards = a;
    ards_patient = healthy;
    if (Status s = sim::apply_pathologies(ards, ards_patient, {"ards:0.6"}); !s) return {};
  }
  return time_reps(timing, [&](long k) {
    const double t = static_cast<double>(k * kFrameStepNs) * 1e-9;
    const Eigen::Quaterniond q = scripted_turn(t);
    const double dv = scripted_volume_ml(t);
    switch (work) {
      case CpuWork::ForceSh:
        sim::force_sh(a, healthy, sim::ForceMode::Exact, q, force.data());
        break;
      case CpuWork::ForceShArds:
        sim::force_sh(ards, ards_patient, sim::ForceMode::Exact, q, force.data());
        break;
      case CpuWork::Eq7:
        sim::force_sh(a, healthy, sim::ForceMode::Exact, q, force.data());
        sim::deform_eq7(a, healthy, force, sim::gravity_in_lung_frame(q), dv, positions);
        break;
      case CpuWork::Eq1:
        if (eq1) eq1->deform(healthy, sim::gravity_in_lung_frame(q), dv, positions);
        break;
    }
  });
}

Status BenchScene::snapshot(const FrameConfig& config, const std::string& png_path) {
  auto runtime = runtime_for(config);
  if (!runtime) return runtime.with_context("");
  now_ns_ = 60 * kFrameStepNs;
  return (*runtime)->final_frame(png_path);
}

}  // namespace lungar::platform::bench
