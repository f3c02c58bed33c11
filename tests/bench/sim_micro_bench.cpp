/// @file sim_micro_bench.cpp
/// @brief The CPU side of one frame, without drawing: force SH (exact and the paper's eq. 8-9), CPU eq. (7) and
/// CPU eq. (1) with the asset's truncated transfer rows. Assets are the procedural pair baked once and cached
/// under <build>/bench-assets (the same cache as lungar-bench). Sizes: 50k and 200k nodes (4 bands, with rows).
///
///   build-release/tests/bench/lungar-bench-sim-micro --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "platform/bench/bench_assets.h"
#include "sim/deform/deform_eq1.h"
#include "sim/force/gravity.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/force_sh.h"
#include "sim/force/gravity.h"

namespace {

using lungar::sim::BakedAsset;

/// The cached asset of `nodes` nodes (4 bands, transfer rows), loaded once per process.
const BakedAsset& asset(std::uint32_t nodes) {
  static std::map<std::uint32_t, std::unique_ptr<BakedAsset>> assets;
  auto& slot = assets[nodes];
  if (!slot) {
    auto got = lungar::platform::bench::load_or_bake(
        {nodes, 4, true}, LUNGAR_BINARY_DIR "/bench-assets", false,
        [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
    if (!got) {
      std::fprintf(stderr, "sim micro bench: %s\n", got.error().c_str());
      std::exit(1);
    }
    slot = std::make_unique<BakedAsset>(std::move(got->asset));
  }
  return *slot;
}

/// A patient turning slowly (a new orientation every iteration, as every frame has).
Eigen::Quaterniond turn(long k) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(0.001 * static_cast<double>(k), Eigen::Vector3d::UnitX()));
}

void set_counters(benchmark::State& state, const BakedAsset& a) {
  state.counters["nodes"] = a.vertex_count();
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * a.vertex_count());
}

void BM_ForceShExact(benchmark::State& state) {
  const BakedAsset& a = asset(static_cast<std::uint32_t>(state.range(0)));
  std::vector<float> force(a.lungs.size() * a.coefficients());
  const lungar::sim::PatientState patient = lungar::sim::PatientState::of(a);
  long k = 0;
  for (auto _ : state) {
    lungar::sim::force_sh(a, patient, lungar::sim::ForceMode::Exact, turn(k++), force.data());
    benchmark::DoNotOptimize(force.data());
  }
}

void BM_ForceShPaper(benchmark::State& state) {
  const BakedAsset& a = asset(static_cast<std::uint32_t>(state.range(0)));
  std::vector<float> force(a.lungs.size() * a.coefficients());
  const lungar::sim::PatientState patient = lungar::sim::PatientState::of(a);
  long k = 0;
  for (auto _ : state) {
    lungar::sim::force_sh(a, patient, lungar::sim::ForceMode::Paper, turn(k++), force.data());
    benchmark::DoNotOptimize(force.data());
  }
}

/// CPU eq. (7) per frame: force SH, then p' = p + dV D n with D the SH dot product.
void BM_CpuEq7(benchmark::State& state) {
  const BakedAsset& a = asset(static_cast<std::uint32_t>(state.range(0)));
  std::vector<float> force(a.lungs.size() * a.coefficients()), positions(a.positions.size());
  const lungar::sim::PatientState patient = lungar::sim::PatientState::of(a);
  long k = 0;
  for (auto _ : state) {
    lungar::sim::force_sh(a, patient, lungar::sim::ForceMode::Exact, turn(k), force.data());
    lungar::sim::deform_eq7(a, patient, force, lungar::sim::gravity_in_lung_frame(turn(k)),
                            250.0 + 0.01 * static_cast<double>(k), positions);
    ++k;
    benchmark::DoNotOptimize(positions.data());
  }
  set_counters(state, a);
}

/// CPU eq. (1) per frame: the applied force, D = T F over the truncated rows, p' = p + dV D n.
void BM_CpuEq1(benchmark::State& state) {
  const BakedAsset& a = asset(static_cast<std::uint32_t>(state.range(0)));
  lungar::sim::Eq1Deformer eq1(a);
  std::vector<float> positions(a.positions.size());
  const lungar::sim::PatientState patient = lungar::sim::PatientState::of(a);
  long k = 0;
  for (auto _ : state) {
    eq1.deform(patient, lungar::sim::gravity_in_lung_frame(turn(k)), 250.0 + 0.01 * static_cast<double>(k), positions);
    ++k;
    benchmark::DoNotOptimize(positions.data());
  }
  set_counters(state, a);
  state.counters["nnz_per_row"] = static_cast<double>(a.transfer_cols.size()) / a.vertex_count();
}

BENCHMARK(BM_ForceShExact)->Arg(50000);
BENCHMARK(BM_ForceShPaper)->Arg(50000);
BENCHMARK(BM_CpuEq7)->Arg(50000)->Arg(200000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuEq1)->Arg(50000)->Arg(200000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
