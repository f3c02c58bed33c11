/// @file decode_micro_bench.cpp
/// @brief Report decoding (drivers/decode/decoder.h): the default 32-byte layout, reports of the mock's
/// upright-to-supine trajectory for both sensors; valid reports, and corrupted ones (rejected, never applied).
///
///   build-release/tests/bench/lungar-bench-decode-micro --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "drivers/decode/decoder.h"
#include "drivers/decode/report_layout.h"
#include "drivers/mock/mock_reports.h"
#include "drivers/tracker/tracker_config.h"

namespace {

using namespace lungar::drivers;

constexpr int kTicks = 512;  // 8 s of reports at 62.5 Hz, two sensors each

struct Reports {
  ReportLayout layout;
  std::vector<std::vector<std::uint8_t>> valid, corrupt;
};

const Reports& reports() {
  static const Reports r = [] {
    lungar::drivers::TrackerConfig settings;
    const auto made = make_layout(settings);
    if (!made) {
      std::fprintf(stderr, "decode micro bench: %s\n", made.error().c_str());
      std::exit(1);
    }
    Reports out;
    out.layout = *made;
    MockReports mock(settings.mock, out.layout);
    for (int k = 0; k < kTicks; ++k) {
      mock.tick(k, [&](std::span<const std::uint8_t> bytes) { out.valid.emplace_back(bytes.begin(), bytes.end()); });
    }
    // Corrupted copies: an unknown station byte on a third, a scrambled quaternion on the rest.
    for (std::size_t i = 0; i < out.valid.size(); ++i) {
      std::vector<std::uint8_t> bad = out.valid[i];
      if (i % 3 == 0) {
        bad[static_cast<std::size_t>(out.layout.station_offset)] = 0x7f;
      } else {
        for (int b = 0; b < 8; ++b) bad[static_cast<std::size_t>(out.layout.orientation_offset + b)] ^= 0x5a;
      }
      out.corrupt.push_back(std::move(bad));
    }
    return out;
  }();
  return r;
}

void run(benchmark::State& state, const std::vector<std::vector<std::uint8_t>>& set, const ReportLayout& layout) {
  std::size_t i = 0;
  std::int64_t rejected = 0;
  for (auto _ : state) {
    DecodedReport d = decode_report(set[i], layout);
    rejected += d.error != DecodeError::None;
    benchmark::DoNotOptimize(d);
    if (++i == set.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["rejected_fraction"] =
      state.iterations() ? static_cast<double>(rejected) / static_cast<double>(state.iterations()) : 0.0;
}

void BM_DecodeValid(benchmark::State& state) { run(state, reports().valid, reports().layout); }
void BM_DecodeCorrupt(benchmark::State& state) { run(state, reports().corrupt, reports().layout); }

BENCHMARK(BM_DecodeValid);
BENCHMARK(BM_DecodeCorrupt);

}  // namespace

BENCHMARK_MAIN();
