/// @file render_bench.cpp
/// @brief Stereo point rendering on llvmpipe: the naive per-eye draw against level of detail, back-face culling and
/// deform-once; mono against stereo; deformed against undeformed; coefficient storage. 400k points, point size 5,
/// 2 x 640x720 side by side, the head 450 mm in front of the procedural lungs (sim's bake). Each iteration draws one frame and waits for it
/// (glFinish). Counters: points drawn per eye and the lit fraction of the frame ("coverage", measured once).
///
///   build-render/tests/bench/lungar-bench-render --benchmark_min_time=2s   (EGL_PLATFORM=surfaceless if no $DISPLAY)
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <memory>
#include <optional>

#include "platform/egl/egl_context.h"
#include "render/frame_target.h"
#include "render/png_snapshot.h"
#include "render/renderer.h"
#include "sim/asset/asset_io.h"
#include "sim/bake/bake.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/force_sh.h"

namespace {

using namespace lungar::render;

constexpr std::uint32_t kPointsPerLung = 200000;  // 400k nodes in the pair
constexpr int kEyeW = 640, kEyeH = 720;

// Everything a frame needs, built once per process (400k points take a while to synthesise and upload).
struct Scene {
  std::unique_ptr<lungar::platform::EglContext> context;
  lungar::sim::BakedAsset asset;
  std::optional<LungDrawable> drawable, texture_drawable, half_drawable;
  std::optional<Renderer> renderer, texture_renderer, half_renderer;
  std::optional<FrameTarget> target;
  std::array<EyeView, 2> eyes;
  std::vector<float> force;
  LungFrame lungs[2];
  std::vector<float> cpu_positions;

  static Scene& get() {
    static Scene* scene = [] {
      auto* s = new Scene();
      s->init();
      return s;
    }();
    return *scene;
  }

  void init() {
    auto c = lungar::platform::EglContext::headless();
    if (!c) {
      std::fprintf(stderr, "render bench: %s\n", c.error().c_str());
      std::exit(1);
    }
    context = c.take();
    // The 400k-node procedural asset of the runtime's demo (sim's bake, L = 4). Baking takes a minute or more, so
    // the bake is cached: $LUNGAR_BENCH_ASSET, else <build>/render-bench-procedural-400k.lungbake.
    const char* env = std::getenv("LUNGAR_BENCH_ASSET");
    const std::string path = env ? env : std::string(LUNGAR_BINARY_DIR) + "/render-bench-procedural-400k.lungbake";
    if (auto loaded = lungar::sim::load_asset(path)) {
      asset = loaded.take();
    } else {
      const auto t0 = std::chrono::steady_clock::now();
      lungar::sim::BakeOptions options;
      options.transfer_rows = false;
      options.evaluate = false;
      auto baked = lungar::sim::bake_procedural(2 * kPointsPerLung, 1, options, nullptr);
      if (!baked) {
        std::fprintf(stderr, "render bench: %s\n", baked.error().c_str());
        std::exit(1);
      }
      asset = std::move(baked->asset);
      std::fprintf(stderr, "render bench: baked %u nodes in %.1f s\n", asset.vertex_count(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (auto written = lungar::sim::write_asset(asset, path); !written.ok()) {
        std::fprintf(stderr, "render bench: %s (not cached)\n", written.error().c_str());
      }
    }
    auto make = [&](DrawableOptions o, std::optional<LungDrawable>& d, std::optional<Renderer>& r) {
      auto dd = LungDrawable::create(asset, o);
      if (!dd) {
        std::fprintf(stderr, "render bench: %s\n", dd.error().c_str());
        std::exit(1);
      }
      d.emplace(dd.take());
      auto rr = Renderer::create(*d);
      if (!rr) {
        std::fprintf(stderr, "render bench: %s\n", rr.error().c_str());
        std::exit(1);
      }
      r.emplace(rr.take());
    };
    make({}, drawable, renderer);
    DrawableOptions tex;
    tex.storage = CoeffStorage::Texture;
    make(tex, texture_drawable, texture_renderer);
    DrawableOptions half;
    half.half_float = true;
    make(half, half_drawable, half_renderer);
    target.emplace(FrameTarget::create(2 * kEyeW, kEyeH).take());
    HmdGeometry hmd;
    hmd.eye_width_px = kEyeW;
    hmd.eye_height_px = kEyeH;
    eyes = StereoView(hmd).eyes(look_from({0.f, -450.f, 0.f}, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}));
    // Upright at end-inspiration (500 mL), the physical force per lung.
    const std::uint32_t nc = asset.coefficients();
    force.assign(asset.lungs.size() * nc, 0.f);
    lungar::sim::force_sh(asset, lungar::sim::ForceMode::exact, Eigen::Quaterniond::Identity(), force.data());
    lungs[0] = {std::span<const float>(force).subspan(0, nc), static_cast<float>(500.0 * asset.lungs[0].volume_share),
                {0.45f, 0.6f, 0.95f}};
    lungs[1] = {std::span<const float>(force).subspan(nc, nc), static_cast<float>(500.0 * asset.lungs[1].volume_share),
                {0.9f, 0.45f, 0.45f}};
    cpu_positions.resize(asset.positions.size());
    lungar::sim::deform_eq7(asset, force, 500.0, cpu_positions);
  }

  FrameInputs frame(int eye_count) const {
    FrameInputs f;
    f.lungs = lungs;
    f.eyes = std::span<const EyeView>(eyes.data(), static_cast<std::size_t>(eye_count));
    f.point_size_px = 5.f;
    return f;
  }
};

double lit_fraction(int width) {
  std::vector<std::uint8_t> rgba;
  read_pixels_top_down(0, 0, width, kEyeH, rgba);
  std::size_t lit = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) lit += (rgba[i] + rgba[i + 1] + rgba[i + 2]) > 0;
  return static_cast<double>(lit) / static_cast<double>(rgba.size() / 4);
}

enum Variant { kNaivePerEye, kLodPerEye, kLodDeformOnce, kNaiveDeformOnce, kUndeformed, kCpuUploaded, kTexture, kHalf };

void run(benchmark::State& state, Variant v, int eye_count, float lod_coverage = FrameInputs{}.lod_coverage) {
  Scene& s = Scene::get();
  FrameInputs f = s.frame(eye_count);
  LungDrawable* drawable = &*s.drawable;
  Renderer* renderer = &*s.renderer;
  const bool naive = v == kNaivePerEye || v == kNaiveDeformOnce;
  f.level_of_detail = !naive;
  f.lod_coverage = lod_coverage;
  f.cull_back_facing = !naive;
  f.strategy = (v == kNaivePerEye || v == kLodPerEye) ? StereoStrategy::PerEye : StereoStrategy::DeformOnce;
  if (v == kUndeformed) f.source = PositionSource::Rest;
  if (v == kCpuUploaded) f.source = PositionSource::Uploaded;
  if (v == kTexture) drawable = &*s.texture_drawable, renderer = &*s.texture_renderer;
  if (v == kHalf) drawable = &*s.half_drawable, renderer = &*s.half_renderer;
  s.target->bind();
  FrameStats stats;
  for (auto _ : state) {
    if (v == kCpuUploaded) (void)drawable->upload_positions(s.cpu_positions);
    lungar::Status st = renderer->draw(*drawable, f, &stats);
    if (!st) state.SkipWithError(st.error().c_str());
    glFinish();
  }
  state.counters["points_per_eye"] = stats.points_drawn[0];
  state.counters["coverage"] = lit_fraction(eye_count * kEyeW);
  // The frame, for looking at: build-dir/render-bench-variant<V>-eyes<E>-lod<10 x coverage>.png.
  char name[64];
  std::snprintf(name, sizeof name, "variant%d-eyes%d-lod%02d", static_cast<int>(v), eye_count,
                static_cast<int>(lod_coverage * 10.f));
  std::vector<std::uint8_t> rgba;
  read_pixels_top_down(0, 0, eye_count * kEyeW, kEyeH, rgba);
  (void)write_png(std::string(LUNGAR_BINARY_DIR) + "/render-bench-" + name + ".png", eye_count * kEyeW, kEyeH, rgba);
}

void BM_StereoNaivePerEye(benchmark::State& s) { run(s, kNaivePerEye, 2); }
void BM_StereoNaiveDeformOnce(benchmark::State& s) { run(s, kNaiveDeformOnce, 2); }
void BM_StereoLodPerEye(benchmark::State& s) { run(s, kLodPerEye, 2); }
void BM_StereoLodDeformOnce(benchmark::State& s) { run(s, kLodDeformOnce, 2); }
void BM_MonoLodDeformOnce(benchmark::State& s) { run(s, kLodDeformOnce, 1); }
void BM_MonoLodPerEye(benchmark::State& s) { run(s, kLodPerEye, 1); }
void BM_StereoLodUndeformed(benchmark::State& s) { run(s, kUndeformed, 2); }
void BM_StereoLodCpuUploaded(benchmark::State& s) { run(s, kCpuUploaded, 2); }
void BM_StereoLodDeformOnceTexture(benchmark::State& s) { run(s, kTexture, 2); }
void BM_StereoLodDeformOnceHalf(benchmark::State& s) { run(s, kHalf, 2); }

// The level-of-detail safety factor against coverage and time (argument: factor x 10).
void BM_StereoLodCoverageSweep(benchmark::State& s) {
  run(s, kLodDeformOnce, 2, static_cast<float>(s.range(0)) / 10.f);
}
// The fixed cost of a frame: clear colour and depth of both eyes and wait.
void BM_StereoClearOnly(benchmark::State& state) {
  Scene::get().target->bind();
  for (auto _ : state) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFinish();
  }
}

#define LUNGAR_RENDER_BENCH(fn) BENCHMARK(fn)->Unit(benchmark::kMillisecond)->UseRealTime()
LUNGAR_RENDER_BENCH(BM_StereoNaivePerEye);
LUNGAR_RENDER_BENCH(BM_StereoNaiveDeformOnce);
LUNGAR_RENDER_BENCH(BM_StereoLodPerEye);
LUNGAR_RENDER_BENCH(BM_StereoLodDeformOnce);
LUNGAR_RENDER_BENCH(BM_MonoLodPerEye);
LUNGAR_RENDER_BENCH(BM_MonoLodDeformOnce);
LUNGAR_RENDER_BENCH(BM_StereoLodUndeformed);
LUNGAR_RENDER_BENCH(BM_StereoLodCpuUploaded);
LUNGAR_RENDER_BENCH(BM_StereoLodDeformOnceTexture);
LUNGAR_RENDER_BENCH(BM_StereoLodDeformOnceHalf);
LUNGAR_RENDER_BENCH(BM_StereoLodCoverageSweep)->Arg(10)->Arg(15)->Arg(20)->Arg(30)->Arg(40)->Arg(60);
LUNGAR_RENDER_BENCH(BM_StereoClearOnly);

}  // namespace

BENCHMARK_MAIN();
