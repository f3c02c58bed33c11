/// @file bench_run.cpp
/// @brief The run plan (which asset, which configurations) and the JSON it writes. What is timed is the shipped
/// Runtime's frame (bench_frame.h), assets come from bench_assets; this file only decides what to measure and
/// records it with the conditions.
#include "platform/bench/bench_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "config/base/atomic_file.h"
#include "platform/bench/bench_assets.h"
#include "platform/bench/bench_frame.h"
#include "platform/bench/bench_targets.h"
#include "platform/bench/scripted_inputs.h"
#include "platform/bench/system_info.h"
#include "platform/app/log.h"
#include "platform/egl/egl_context.h"
#include "platform/runtime/runtime.h"
#include "sim/bake/bake.h"

namespace lungar::platform::bench {

namespace {

using render::DrawMode;
using render::StereoStrategy;
using nlohmann::json;

constexpr int kEyeWidthPx = 640, kEyeHeightPx = 720;
const std::vector<double> kScales = {0.25, 0.5, 1.0, 2.0, 4.0};      // Fig. 4
const std::vector<std::uint32_t> kBands = {2, 3, 4, 5, 6, 7, 8};     // Fig. 6: 4 .. 64 coefficients
const std::vector<float> kPointSizes = {1, 2, 3, 4, 5, 6, 7, 8, 9};  // Fig. 7
const std::vector<float> kQuickPointSizes = {1, 3, 5, 7, 9};
constexpr std::uint32_t kBaseBands = 4;    // the paper's 16 coefficients
constexpr double kDenserEpsilon = 0.0065;  // eq. (1) rows of 191 entries at 400k nodes: the paper's 192

/// The paper's Table II (FPS), for the side-by-side columns.
json paper_table2() {
  return {{"gpu_eq7", {{"points", {{"mono", 148}, {"stereo", 75}}}, {"mesh", {{"mono", 46}, {"stereo", 23}}}}},
          {"cpu_eq1", {{"points", {{"mono", 10}, {"stereo", 7}}}, {"mesh", {{"mono", 8}, {"stereo", 6}}}}},
          {"cpu_eq7", {{"points", {{"mono", 76}, {"stereo", 56}}}, {"mesh", {{"mono", 28}, {"stereo", 19}}}}}};
}

json stats_json(const RepStats& s) {
  return {{"frame_ms_p50", s.median_ms},
          {"frame_ms_min", s.min_ms},
          {"frame_ms_max", s.max_ms},
          {"fps", s.fps()},
          {"reps_frame_ms", s.reps_ms}};
}

json config_json(const FrameConfig& c) {
  return {{"method", to_string(c.method)},
          {"view", c.stereo ? "stereo" : "mono"},
          {"mode", render::to_string(c.mode)},
          {"strategy", render::to_string(c.strategy)},
          {"lod", c.lod},
          {"point_size_px", c.point_size_px},
          {"lesions", c.lesions},
          {"console", c.console}};
}

json bake_json(const BakeRecord& r) {
  json j = {{"nodes", r.vertices},
            {"nodes_requested", r.key.nodes},
            {"bands", r.key.bands},
            {"transfer_rows", r.key.transfer_rows},
            {"measured_this_run", r.baked_this_run},
            {"known", r.known}};
  if (r.key.transfer_epsilon > 0) j["transfer_epsilon"] = r.key.transfer_epsilon;
  if (r.known) {
    j.update({{"bake_s", r.bake_s},
              {"factorise_s", r.factorise_s},
              {"solve_s", r.solve_s},
              {"transfer_rows_s", r.transfer_rows_s},
              {"transfer_nnz_per_row_mean", r.transfer_nnz_per_row},
              {"load_1min", r.load_1min},
              {"baked_at_utc", r.baked_at_utc}});
  }
  return j;
}

void bench_say(const std::string& line) { log_line("bench: " + line); }

/// One run's state: the output context, the options, the typed targets and the JSON being filled.
class Run {
 public:
  explicit Run(const BenchOptions& o) : o_(o) {}

  int go() {
    if (o_.bake_only) return bake_all();
    auto context = EglContext::headless();
    if (!context) return error("EGL: " + context.error());
    context_ = context.take();
    record_conditions();
    if (int rc = base_asset(); rc) return rc;
    if (on("fig4") && (rc_ = model_sizes())) return rc_;
    if (on("fig6") && (rc_ = coefficients())) return rc_;
    out_["targets"] = targets_.to_json();
    for (const auto& [name, t] : out_["targets"].items()) {
      bench_say("target " + name + ": " + std::to_string(t["value"].get<double>()) +
                (t["met"].get<bool>() ? " (met)" : " (NOT met)"));
    }
    const SystemInfo end = read_system_info();
    out_["system"]["load_avg_end"] = end.load_avg;
    out_["system"]["utc_end"] = end.utc_time;
    if (Status written = write_file_atomically(o_.json_path, out_.dump(2) + "\n"); !written) {
      return error(written.error());
    }
    bench_say("wrote " + o_.json_path);
    return 0;
  }

  Timing timing_;

 private:
  bool on(const std::string& section) const { return o_.sections.empty() || o_.sections.count(section) > 0; }

  int error(const std::string& message) {
    std::fprintf(stderr, "lungar-bench: %s\n", message.c_str());
    return 1;
  }

  void record_conditions() {
    const SystemInfo sys = read_system_info();
    out_["schema"] = "lungar-bench/2";
    out_["quick"] = o_.quick;
    out_["frame"] = "the shipped Runtime frame (platform/runtime), scripted inputs, headless output, no status line";
    out_["system"] = {{"cpu_model", sys.cpu_model},
                      {"cores", sys.cores},
                      {"load_avg_start", sys.load_avg},
                      {"utc_start", sys.utc_time},
                      {"renderer", context_->describe()}};
    out_["settings"] = {{"nodes_1x", o_.nodes},        {"reps", timing_.reps},
                        {"rep_s", timing_.rep_s},      {"warmup_s", timing_.warmup_s},
                        {"eye_width_px", kEyeWidthPx}, {"eye_height_px", kEyeHeightPx},
                        {"default_point_size_px", 5},  {"head_distance_mm", kHeadDistanceMm},
                        {"coeff_storage", render::to_string(o_.storage)}};
    out_["paper_table2_fps"] = paper_table2();
    bench_say("renderer: " + context_->describe());
    bench_say("cpu: " + sys.cpu_model + ", " + std::to_string(sys.cores) + " cores, load " +
              std::to_string(sys.load_avg[0]));
  }

  /// Loads (or bakes) an asset, records its bake and uploads it as a scene; nullptr after printing the error.
  std::unique_ptr<BenchScene> scene(const AssetKey& key) {
    auto got = load_or_bake(key, o_.asset_dir, o_.rebake && !baked_.count(key_text(key)), bench_say);
    if (!got) {
      error(got.error());
      return nullptr;
    }
    if (baked_.insert(key_text(key)).second) out_["bake"].push_back(bake_json(got->record));
    bench_say("asset: " + std::to_string(got->asset.vertex_count()) + " nodes, " +
              std::to_string(got->asset.coefficients()) + " coefficients" +
              (got->record.known ? ", baked in " + std::to_string(got->record.bake_s) + " s" : ""));
    auto s = BenchScene::create(context_, std::move(got->asset), "bench " + key_text(key),
                                {.storage = o_.storage});
    if (!s) {
      error(s.error());
      return nullptr;
    }
    return s.take();
  }

  /// Measures one configuration and returns its JSON record (config, stats, conditions); null on error.
  json measure(BenchScene& scene, const FrameConfig& c, const std::string& label, double* median_ms = nullptr) {
    auto r = scene.measure(c, timing_);
    if (!r) {
      error(label + ": " + r.error());
      return {};
    }
    char line[200];
    std::snprintf(line, sizeof line, "%-34s %8.2f ms  %7.1f FPS  (reps %.2f..%.2f, load %.1f)", label.c_str(),
                  r->stats.median_ms, r->stats.fps(), r->stats.min_ms, r->stats.max_ms, r->load_1min);
    bench_say(line);
    if (median_ms) *median_ms = r->stats.median_ms;
    json j = config_json(c);
    j.update(stats_json(r->stats));
    j["points_per_eye"] = r->points_per_eye;
    j["frames"] = r->frames;
    j["load_1min"] = r->load_1min;
    return j;
  }

  /// The 1x asset with transfer rows: Table II, the CPU step alone, the strategies and Fig. 7.
  int base_asset() {
    if (!on("table2") && !on("cpu") && !on("strategies") && !on("fig7")) return 0;
    base_ = scene({o_.nodes, kBaseBands, /*transfer_rows=*/true});
    if (!base_) return 1;
    if (!o_.snapshot_dir.empty()) snapshots(*base_);
    if (on("table2") && table2(*base_)) return 1;
    if (on("cpu") && cpu_step(*base_)) return 1;
    if (on("strategies") && (strategies(*base_) || paired(*base_))) return 1;
    if (on("fig7") && point_sizes(*base_)) return 1;
    return 0;
  }

  int table2(BenchScene& s) {
    for (DrawMode mode : {DrawMode::Points, DrawMode::Mesh}) {
      for (Method m : {Method::Gpu7, Method::Cpu1, Method::Cpu7}) {
        for (bool stereo : {false, true}) {
          double ms = 0;
          json j = measure(
              s, {m, stereo, mode},
              std::string("table2 ") + to_string(m) + (stereo ? " stereo " : " mono ") + render::to_string(mode), &ms);
          if (j.is_null()) return 1;
          j["nodes"] = s.asset().vertex_count();
          out_["table2"].push_back(j);
          if (m == Method::Gpu7 && mode == DrawMode::Points) (stereo ? targets_.stereo_ms : targets_.mono_ms) = ms;
        }
      }
    }
    return 0;
  }

  int cpu_step(BenchScene& s) {
    const std::uint32_t nodes = s.asset().vertex_count();
    json j = {{"nodes", nodes},
              {"coefficients", s.asset().coefficients()},
              {"transfer_nnz_per_row_mean", nodes ? static_cast<double>(s.asset().transfer_cols.size()) / nodes : 0.0}};
    double eq7 = 0, eq1 = 0;
    for (auto [work, key] :
         {std::pair{CpuWork::ForceSh, "force_sh"}, std::pair{CpuWork::ForceShArds, "force_sh_ards"},
          std::pair{CpuWork::Eq7, "eq7"}, std::pair{CpuWork::Eq1, "eq1"}}) {
      const RepStats st = s.measure_cpu(work, timing_);
      j[key] = stats_json(st);
      j[key].erase("fps");
      if (work == CpuWork::Eq7) eq7 = st.median_ms;
      if (work == CpuWork::Eq1) eq1 = st.median_ms;
      bench_say(std::string("cpu ") + key + ": " + std::to_string(st.median_ms) + " ms");
    }
    j["eq1_over_eq7"] = eq7 > 0 ? eq1 / eq7 : 0.0;
    targets_.eq1_over_eq7 = j["eq1_over_eq7"].get<double>();
    j["load_1min"] = load_average_1min();
    out_["cpu_deform"] = j;
    return *o_.eq1_epsilon > 0 ? eq1_denser(eq7) : 0;
  }

  int strategies(BenchScene& s) {
    for (StereoStrategy strategy : {StereoStrategy::PerEye, StereoStrategy::DeformOnce}) {
      for (bool lod : {true, false}) {
        for (bool stereo : {false, true}) {
          FrameConfig c{Method::Gpu7, stereo, DrawMode::Points, strategy, lod};
          json j = measure(s, c,
                           std::string("strategy ") + render::to_string(strategy) + (lod ? " lod " : " no-lod ") +
                               (stereo ? "stereo" : "mono"));
          if (j.is_null()) return 1;
          out_["stereo_strategies"].push_back(j);
        }
      }
    }
    // The same frames without the deformation: what eq. (7) in the shader adds over drawing points.
    for (bool stereo : {false, true}) {
      json j = measure(s, {Method::Rest, stereo}, std::string("undeformed lod ") + (stereo ? "stereo" : "mono"));
      if (j.is_null()) return 1;
      out_["undeformed"].push_back(j);
    }
    return 0;
  }

  int point_sizes(BenchScene& s) {
    for (double size : o_.quick ? kQuickPointSizes : kPointSizes) {
      for (auto [m, lod] :
           {std::pair{Method::Gpu7, true}, std::pair{Method::Cpu7, true}, std::pair{Method::Gpu7, false}}) {
        FrameConfig c{m, true, DrawMode::Points, FrameConfig{}.strategy, lod, size};
        char label[64];
        std::snprintf(label, sizeof label, "fig7 point %g %s%s", size, to_string(m), lod ? "" : " no-lod");
        json j = measure(s, c, label);
        if (j.is_null()) return 1;
        out_["fig7_point_size"].push_back(j);
      }
    }
    return 0;
  }

  /// The two ratio targets of the default frame (GPU eq. 7, stereo points, LOD, the default strategy), each from
  /// interleaved repetitions so that a drift in the load falls on both sides: stereo over mono, and deformed over
  /// undeformed points; and the two stereo strategies against each other, which decides the default.
  int paired(BenchScene& s) {
    const FrameConfig stereo{Method::Gpu7, true, DrawMode::Points};
    FrameConfig mono = stereo, plain = stereo, per_eye = stereo, once = stereo;
    mono.stereo = false;
    plain.method = Method::Rest;
    FrameConfig plain_mono = plain;  // what a second eye costs with no deformation at all: the floor of the ratio
    plain_mono.stereo = false;
    FrameConfig lesion = stereo;  // the same frame with one lesion in the lungs: what a lesion costs
    lesion.lesions = 1;
    FrameConfig console = stereo;  // the same frame with the instructor's console open and a page watching
    console.console = true;
    per_eye.strategy = StereoStrategy::PerEye;
    once.strategy = StereoStrategy::DeformOnce;
    const std::pair<const char*, std::pair<FrameConfig, FrameConfig>> pairs[] = {
        {"stereo_over_mono", {mono, stereo}},          {"deformed_over_undeformed", {plain, stereo}},
        {"deform_once_over_per_eye", {per_eye, once}}, {"undeformed_stereo_over_mono", {plain_mono, plain}},
        {"one_lesion_over_none", {stereo, lesion}},    {"console_watched_over_closed", {stereo, console}}};
    for (const auto& [key, ab] : pairs) {
      auto ratio = measure_pair(s, key, ab.first, ab.second);
      if (!ratio) return 1;
      if (std::string(key) == "stereo_over_mono") targets_.stereo_over_mono_paired = *ratio;
      if (std::string(key) == "deformed_over_undeformed") targets_.deformed_over_undeformed = *ratio;
    }
    return 0;
  }

  /// Frame time of `b` over `a` on `s`: the median of at least 11 interleaved ratios, printed and kept under
  /// bench.json's "paired"; nothing after printing an error.
  std::optional<double> measure_pair(BenchScene& s, const std::string& key, const FrameConfig& a,
                                     const FrameConfig& b) {
    // Ratios of a few percent need more repetitions than the tables' medians: at least 11 pairs.
    Timing timing = timing_;
    timing.reps = std::max(timing.reps, 11);
    auto r = s.measure_pair(a, b, timing);
    if (!r) {
      error("paired " + key + ": " + r.error());
      return std::nullopt;
    }
    char line[200];
    std::snprintf(line, sizeof line, "paired %-26s %8.2f / %.2f ms = %.3f (median of %zu interleaved ratios)",
                  key.c_str(), r->b.median_ms, r->a.median_ms, r->ratio_median, r->ratios.size());
    bench_say(line);
    out_["paired"][key] = {{"a", config_json(a)},
                           {"b", config_json(b)},
                           {"a_ms_p50", r->a.median_ms},
                           {"b_ms_p50", r->b.median_ms},
                           {"ratio_p50", r->ratio_median},
                           {"ratios", r->ratios},
                           {"load_1min", load_average_1min()}};
    return r->ratio_median;
  }

  /// CPU eq. (1) again with rows kept down to a smaller fraction of T_II (denser: at 0.0065, the paper's 192 a row):
  /// the step alone against `eq7_ms`, and Table II's points frames. Non-zero after printing an error.
  int eq1_denser(double eq7_ms) {
    auto s = scene({o_.nodes, kBaseBands, true, *o_.eq1_epsilon});
    if (!s) return 1;
    const std::uint32_t nodes = s->asset().vertex_count();
    const RepStats st = s->measure_cpu(CpuWork::Eq1, timing_);
    const double nnz = nodes ? static_cast<double>(s->asset().transfer_cols.size()) / nodes : 0.0;
    json j = {{"transfer_epsilon", *o_.eq1_epsilon},
              {"transfer_nnz_per_row_mean", nnz},
              {"eq1", stats_json(st)},
              {"eq1_over_eq7", eq7_ms > 0 ? st.median_ms / eq7_ms : 0.0}};
    j["eq1"].erase("fps");
    targets_.eq1_over_eq7_denser = j["eq1_over_eq7"].get<double>();
    targets_.denser_nnz_per_row = nnz;
    bench_say("cpu eq1 (epsilon " + std::to_string(*o_.eq1_epsilon) + "): " + std::to_string(st.median_ms) + " ms");
    for (bool stereo : {false, true}) {
      json f = measure(*s, {Method::Cpu1, stereo}, std::string("table2 cpu_eq1 dense ") + (stereo ? "stereo" : "mono"));
      if (f.is_null()) return 1;
      j["frames"].push_back(f);
    }
    out_["cpu_deform"]["eq1_denser"] = j;
    return 0;
  }

  /// Fig. 4: stereo points at 0.25x .. 4x nodes, GPU eq. (7) with and without LOD, CPU eq. (7) with LOD.
  int model_sizes() {
    for (double scale : kScales) {
      const auto n = static_cast<std::uint32_t>(std::lround(scale * o_.nodes));
      std::unique_ptr<BenchScene> own;
      if (!acquire({n, kBaseBands, false}, own)) return 1;
      BenchScene& s = own ? *own : *base_;
      for (auto [m, lod] :
           {std::pair{Method::Gpu7, true}, std::pair{Method::Gpu7, false}, std::pair{Method::Cpu7, true}}) {
        char label[64];
        std::snprintf(label, sizeof label, "fig4 %gx %s%s", scale, to_string(m), lod ? "" : " no-lod");
        double ms = 0;
        json j = measure(s, {m, true, DrawMode::Points, FrameConfig{}.strategy, lod}, label, &ms);
        if (j.is_null()) return 1;
        j["scale"] = scale;
        j["nodes"] = s.asset().vertex_count();
        out_["fig4_model_size"].push_back(j);
        if (m == Method::Gpu7 && lod && scale == kScales.front()) targets_.small_ms = ms;
        if (m == Method::Gpu7 && lod && scale == kScales.back()) targets_.large_ms = ms;
      }
    }
    return 0;
  }

  /// Fig. 6: stereo points at 1x nodes, 2 .. 8 bands (4 .. 64 coefficients), GPU eq. (7) and CPU eq. (7).
  int coefficients() {
    for (std::uint32_t bands : o_.fig6_bands.empty() ? kBands : o_.fig6_bands) {
      std::unique_ptr<BenchScene> own;
      if (!acquire({o_.nodes, bands, false}, own)) return 1;
      BenchScene& s = own ? *own : *base_;
      for (Method m : {Method::Gpu7, Method::Cpu7}) {
        json j = measure(s, {m, true}, "fig6 " + std::to_string(bands * bands) + " coeff " + to_string(m));
        if (j.is_null()) return 1;
        j["bands"] = bands;
        j["coefficients"] = bands * bands;
        j["coeff_storage"] = s.uses_texture() ? "texture" : "attributes";
        out_["fig6_coefficients"].push_back(j);
      }
      if (bands == sim::kDefaultBands) {
        // The bake's default (36 coefficients, where the paper had 16) must keep the deformation within the
        // render target too: the same interleaved pair as the strategies' deformed / undeformed.
        FrameConfig deformed{Method::Gpu7, true, DrawMode::Points}, plain = deformed;
        plain.method = Method::Rest;
        auto ratio = measure_pair(s, "deformed_over_undeformed_default_coefficients", plain, deformed);
        if (!ratio) return 1;
        targets_.deformed_over_undeformed_default_coefficients = *ratio;
      }
    }
    return 0;
  }

  /// --bake-only: every asset the selected sections draw, loaded or baked, one at a time; no GL.
  int bake_all() {
    std::vector<AssetKey> keys;
    if (on("table2") || on("cpu") || on("strategies") || on("fig7")) keys.push_back({o_.nodes, kBaseBands, true});
    if (on("cpu") && *o_.eq1_epsilon > 0) keys.push_back({o_.nodes, kBaseBands, true, *o_.eq1_epsilon});
    for (double scale : kScales) {
      if (on("fig4")) keys.push_back({static_cast<std::uint32_t>(std::lround(scale * o_.nodes)), kBaseBands, false});
    }
    for (std::uint32_t bands : o_.fig6_bands.empty() ? kBands : o_.fig6_bands) {
      if (on("fig6")) keys.push_back({o_.nodes, bands, false});
    }
    const bool has_base = !keys.empty() && keys.front().transfer_rows;
    for (const AssetKey& k : keys) {
      if (has_base && k.nodes == o_.nodes && k.bands == kBaseBands && !k.transfer_rows) continue;  // see acquire()
      auto got = load_or_bake(k, o_.asset_dir, o_.rebake, bench_say);
      if (!got) return error(got.error());
    }
    return 0;
  }

  /// The scene for `key`, left empty when the 1x Table II scene already loaded serves (its transfer rows change
  /// nothing drawn). False after printing an error.
  bool acquire(const AssetKey& key, std::unique_ptr<BenchScene>& s) {
    if (base_ && key.nodes == o_.nodes && key.bands == kBaseBands) return true;
    s = scene(key);
    return s != nullptr;
  }

  void snapshots(BenchScene& s) {
    for (DrawMode mode : {DrawMode::Points, DrawMode::Mesh}) {
      const std::string path = o_.snapshot_dir + "/bench-frame-" + render::to_string(mode) + ".png";
      if (auto st = s.snapshot({Method::Gpu7, true, mode}, path); !st) bench_say("snapshot: " + st.error());
    }
  }

  static std::string key_text(const AssetKey& k) {
    return std::to_string(k.nodes) + "/" + std::to_string(k.bands) + (k.transfer_rows ? "/rows" : "") + "/" +
           std::to_string(k.transfer_epsilon);
  }

  const BenchOptions& o_;
  std::set<std::string> baked_;  ///< assets already recorded (and, with --rebake, already baked afresh)
  std::shared_ptr<EglContext> context_;
  std::unique_ptr<BenchScene> base_;  ///< the 1x asset with transfer rows, kept for Figs. 4 and 6
  BenchTargets targets_;
  json out_ = json::object();
  int rc_ = 0;
};

}  // namespace

int run_bench(const BenchOptions& options) {
  BenchOptions o = options;
  if (o.nodes == 0) o.nodes = o.quick ? 50000 : 400000;
  if (!o.eq1_epsilon) o.eq1_epsilon = o.quick ? 0.0 : kDenserEpsilon;
  Run run(o);
  run.timing_.reps = o.reps;
  run.timing_.rep_s = o.rep_s > 0 ? o.rep_s : (o.quick ? 0.1 : 0.3);
  run.timing_.warmup_s = o.warmup_s > 0 ? o.warmup_s : (o.quick ? 0.15 : 0.5);
  return run.go();
}

}  // namespace lungar::platform::bench
