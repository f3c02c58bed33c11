/// @file bench_main.cpp
/// @brief lungar-bench: the paper's Table II and Figs. 4, 6 and 7 measured side by side in one run, headless.
///        Writes JSON (scripts/plot-bench turns it into the Markdown table and the plots); progress on stderr.
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "config/base/command_line.h"
#include "lungar/version.h"
#include "platform/bench/bench_run.h"

int main(int argc, char** argv) {
  using lungar::platform::bench::BenchOptions;
  using lungar::platform::bench::kSections;
  BenchOptions o;
  std::string sections;
  CLI::App app{
      "lungar-bench: frame rates of GPU eq. (7), CPU eq. (7) and CPU eq. (1) (the paper's Table II), "
      "frame time against model size, SH coefficients and point size (Figs. 4, 6, 7), the stereo "
      "strategies, level of detail, and bake times, headless on this machine's GLES 3"};
  app.set_version_flag("--version", std::string("lungar-bench ") + LUNGAR_VERSION);
  app.add_flag("--quick", o.quick, "a smaller sweep (50k nodes, odd point sizes, 0.1 s repetitions)");
  app.add_option("--nodes", o.nodes, "nodes of the 1x model (default 400000, 50000 with --quick)")
      ->check(CLI::Range(1000u, 4000000u));
  app.add_option("--reps", o.reps, "repetitions per configuration after the warm-up (median reported)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--rep-seconds", o.rep_s, "minimum length of one repetition (default 0.3, 0.1 with --quick)")
      ->check(CLI::Range(0.001, 60.0));
  app.add_option("--warmup-seconds", o.warmup_s, "warm-up before the repetitions (default 0.5, 0.15 with --quick)")
      ->check(CLI::Range(0.001, 60.0));
  app.add_option("--json", o.json_path, "where to write the results")->capture_default_str();
  app.add_option("--asset-dir", o.asset_dir, "cache of baked benchmark assets")->capture_default_str();
  app.add_option("--snapshot-dir", o.snapshot_dir, "write PNGs of the timed stereo frames (points, mesh) here");
  app.add_flag("--rebake", o.rebake, "bake every asset again, for fresh bake times");
  app.add_option("--eq1-epsilon", o.eq1_epsilon,
                 "also time CPU eq. (1) with transfer rows kept down to this fraction of T_II (denser rows: 0.0065 "
                 "keeps 191 a row at 400k nodes, the paper had 192; the default bake keeps 0.02); 0: skip; "
                 "default 0.0065, 0 with --quick")
      ->check(CLI::Range(0.0, 0.5));
  app.add_flag("--bake-only", o.bake_only, "fill the asset cache (recording bake times) and measure nothing");
  app.add_option("--coeff-storage", o.storage,
                 "where the SH coefficients live on the GPU: auto (the program's choice), attributes (up to 36) or "
                 "texture")
      ->transform(CLI::CheckedTransformer(lungar::render::kCoeffStorageNames.map()).description("auto|attributes|texture"));
  app.add_option("--fig6-bands", o.fig6_bands, "Fig. 6 at these band counts only (default 2 .. 8)")
      ->delimiter(',')
      ->check(CLI::Range(2, 8));
  std::string all;
  for (const auto& s : kSections) all += (all.empty() ? "" : ",") + s;
  app.add_option("--sections", sections, "comma-separated subset of " + all + " (default: all)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar-bench");
  }

  std::stringstream list(sections);
  for (std::string s; std::getline(list, s, ',');) {
    if (s.empty()) continue;
    bool known = false;
    for (const auto& k : kSections) known = known || k == s;
    if (!known) {
      std::fprintf(stderr, "lungar-bench: --sections: expected names from %s, got '%s'\n", all.c_str(), s.c_str());
      return 2;
    }
    o.sections.insert(s);
  }
  return lungar::platform::bench::run_bench(o);
}
