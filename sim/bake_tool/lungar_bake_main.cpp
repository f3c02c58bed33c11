/// @file lungar_bake_main.cpp
/// @brief `lungar-bake`: a lung mesh (or the procedural pair) -> a `.lungbake` asset and a JSON report.
#include <CLI/CLI.hpp>

#include <unistd.h>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "config/base/command_line.h"
#include "config/base/log_line.h"
#include "lungar/version.h"
#include "sim/bake_tool/bake_command.h"
#include "sim/bake_tool/export_command.h"
#include "sim/pathology/pathology.h"

namespace {

void log_line(const std::string& message) { lungar::log_line("lungar-bake", message); }

/// Set by the first Ctrl-C (SIGINT) or SIGTERM: the bake stops at its next step and writes nothing.
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};

void on_interrupt(int signal) {
  g_signal.store(signal);
  g_interrupted.store(true);
  constexpr char kLine[] = "\nlungar-bake: interrupted; stopping at the next step (again to end at once)\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, kLine, sizeof kLine - 1);  // stdio is not signal-safe
}

/// The first SIGINT or SIGTERM cancels the bake; the handler then resets, so a second one ends the process.
void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

/// A one-line bar redrawn in place; only on a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled) {}
  void operator()(std::string_view stage, double fraction) {
    if (!enabled_) return;
    const int percent = static_cast<int>(fraction * 100 + 0.5);
    if (stage == stage_ && percent == percent_) return;
    stage_ = std::string(stage);
    percent_ = percent;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    if (percent == 0) {  // a stage that reports no share done (a factorisation): its start, not a bar stuck at 0 %
      const double in_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      std::fprintf(stderr, "\r  %-14s running (began %.0f s into the bake)   ", stage_.c_str(), in_s);
    } else {
      std::fprintf(stderr, "\r  %-14s [%s%s] %3d%%                ", stage_.c_str(), std::string(filled, '#').c_str(),
                   std::string(kWidth - filled, ' ').c_str(), percent);
    }
    std::fflush(stderr);
    dirty_ = true;
  }
  void finish() {
    if (dirty_) std::fprintf(stderr, "\n");
    dirty_ = false;
  }

 private:
  bool enabled_;
  bool dirty_ = false;
  std::string stage_;
  int percent_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// An option that takes one of `names` (in any case), its help like the other options': TEXT:{a,b}=default.
/// (CLI11's CheckedTransformer on the enum map prints "ENUM:value in {a->,b-> } OR {, }=".)
template <class E, std::size_t N>
void add_enum_option(CLI::App& app, const std::string& flag, E& value, const lungar::EnumNames<E, N>& names,
                     const std::string& help) {
  std::vector<std::string> choices;
  for (const auto& entry : names.entries) choices.emplace_back(entry.second);
  const auto set = [&value, &names](const std::string& text) {
    if (const std::optional<E> parsed = names.parse(text)) value = *parsed;
  };
  app.add_option_function<std::string>(flag, set, help)
      ->transform(CLI::IsMember(choices, CLI::ignore_case))  // a transform: the input becomes the table's spelling
      ->default_str(names.name(value));
}

/// The command line: every option of `cmd` on `app`.
void add_bake_options(CLI::App& app, lungar::sim::BakeCommand& cmd) {
  app.set_version_flag("--version", std::string("lungar-bake ") + LUNGAR_VERSION);
  auto* procedural = app.add_flag("--procedural", cmd.procedural, "bake the built-in procedural pair of lungs");
  app.add_option("--nodes", cmd.nodes, "vertices in all, shared between the lungs by area (default: 400000 for "
                                       "--procedural and --labelmap; meshes with more are simplified to it)")
      ->check(CLI::Range(52u, 8000000u));
  app.add_option("--seed", cmd.seed, "seed of the procedural pair")->needs(procedural)->capture_default_str();
  auto* mesh = app.add_option("--mesh", cmd.meshes, "lung surface (STL, OBJ, PLY): one file with both lungs, "
                                                    "or one file per lung")
                   ->expected(1, 2)->allow_extra_args(false)->take_all();
  auto* labelmap = app.add_option("--labelmap", cmd.labelmap, "CT label map (NRRD, NIfTI .nii/.nii.gz, MetaImage "
                                                              ".mha/.mhd) holding the lungs");
  app.add_option("--label", cmd.labels, "NAME=VALUE: a lung of the label map and its label (e.g. --label right=2 "
                                        "--label left=3)")
      ->needs(labelmap)->allow_extra_args(false);
  app.add_option("--lesion", cmd.lesions,
                 "NAME=VALUE: a lesion (a tumour) segmented in the label map with that label, baked as the ball of "
                 "its volume at its centroid, its voxels counted in the lung around it; or NAME=x,y,z,radius_mm (LPS, "
                 "mm) with any input. The runtime draws it moving with the tissue around it; repeatable")
      ->allow_extra_args(false);
  procedural->excludes(mesh)->excludes(labelmap);
  mesh->excludes(labelmap);
  app.add_option("--out", cmd.out, "the .lungbake file to write (required)");
  app.add_option("--bands", cmd.options.bands, "SH bands L (L^2 coefficients)")
      ->check(CLI::Range(1u, 8u))->capture_default_str();
  app.add_option("--units", cmd.units, "units of the mesh files")->check(CLI::IsMember({"mm", "cm", "m"}))
      ->capture_default_str();
  app.add_flag("--any-volume", cmd.any_volume,
               "bake lungs enclosing less than 30 mL or more than 8000 mL each (refused otherwise: the units are "
               "likely wrong)");
  add_enum_option(app, "--model", cmd.options.model, lungar::sim::kMotionModelNames,
                  "how the surface moves (sliding: driven by the diaphragm, sliding along the chest wall, held at the "
                  "mediastinum; paper: every vertex along its normal, the paper's)");
  app.add_option("--gamma", cmd.options.gamma_per_mm,
                 "gravity's pressure gradient gamma in p = p0 + gamma g.(x - c), per mm (p0 = 10): how much more the "
                 "dependent regions move")
      ->check(CLI::Range(0.0, 0.075))->capture_default_str();
  add_enum_option(app, "--map", cmd.options.sphere.map, lungar::sim::kSphereMapNames,
                  "the sphere map of the SH fit (radial: the paper's, folds where the surface is not star-shaped; "
                  "conformal: one-to-one on genus-0 surfaces)");
  app.add_option("--threads", cmd.options.threads, "worker threads, at most one a core (0: all)")
      ->check(CLI::Range(0, 256))->capture_default_str();
  app.add_option("--report-json", cmd.report_json, "write the bake report here");
  app.add_flag("!--no-transfer-rows", cmd.options.transfer_rows,
               "leave out the explicit transfer rows (the CPU eq. (1) baseline, --deform cpu1)");
  app.add_flag("!--no-evaluate", cmd.options.evaluate,
               "skip the report's accuracy and physiology figures (a faster bake, as the demo's)");
}

/// `lungar-bake export`: its options on `sub`; --gravity is parsed after the command line.
void add_export_options(CLI::App& sub, lungar::sim::ExportCommand& cmd, std::string& gravity) {
  sub.add_option("--asset", cmd.asset, "the .lungbake asset")->required();
  sub.add_option("--posture", cmd.posture,
                 "upright, supine, prone, left-lateral (lying on the left side) or "
                 "right-lateral")
      ->check(CLI::IsMember(lungar::sim::posture_names()))
      ->capture_default_str();
  sub.add_option("--gravity", gravity, "x,y,z: gravity's direction in the lung frame (LPS) instead of a posture");
  sub.add_option("--volume-ml", cmd.volume_ml, "the pair's volume change from the rest shape, mL (negative: below "
                                               "it); with --series, the breath's tidal volume")
      ->capture_default_str();
  sub.add_option("--out", cmd.out, "the .ply file to write (with --series: FILE_000.ply, FILE_001.ply, ...)")
      ->required();
  sub.add_option("--series", cmd.series, "N: one file per phase of a breath, N phases")->check(CLI::Range(1, 1000));
  sub.add_option("--pathology", cmd.pathologies,
                 "SPEC: " + lungar::sim::pathology_syntaxes() + "; repeatable")
      ->allow_extra_args(false);
  sub.add_option("--interior", cmd.interior, "N: also write N points uniform over the lungs' volume (a fixed seed), "
                                             "moved by the harmonic extension of the surface's motion");
  sub.add_option("--interior-out", cmd.interior_out, "the .ply of the interior points (vertices only: x y z, dx dy "
                                                     "dz; with --series: FILE_000.ply, ...); needs --interior");
  sub.add_option("--lesion", cmd.lesions,
                 "NAME=x,y,z,radius_mm: a lesion (a tumour) there (LPS, mm), inside a lung, moved with the tissue "
                 "around it; its excursion is reported (with --series over one breath, else from rest to "
                 "--volume-ml); repeatable")
      ->allow_extra_args(false);
  sub.add_option("--lesions-out", cmd.lesions_out,
                 "a CSV of each lesion's position in each exported phase (phase, volume_ml, name, lung, x_mm, y_mm, "
                 "z_mm, dx_mm, dy_mm, dz_mm; LPS); needs --lesion");
}

/// Runs the export and says what it wrote; the exit code.
int run_export(lungar::sim::ExportCommand& cmd, const std::string& gravity) {
  if (lungar::Status s = lungar::sim::check_export_command(cmd); !s) {
    std::fprintf(stderr, "lungar-bake export: %s\n", s.error().c_str());
    return 2;
  }
  if (!gravity.empty()) {
    auto g = lungar::sim::parse_gravity(gravity);
    if (!g) {
      std::fprintf(stderr, "lungar-bake export: %s\n", g.error().c_str());
      return 2;
    }
    cmd.gravity = *g;
  }
  auto written = lungar::sim::run_export_command(cmd);
  if (!written) {
    std::fprintf(stderr, "lungar-bake export: %s\n", written.error().c_str());
    return 1;
  }
  for (const lungar::sim::ExportedFile& f : *written) {
    char line[512];
    std::snprintf(line, sizeof line, "wrote %s: volume change %.1f mL (phase %.3f)", f.path.c_str(), f.volume_ml,
                  f.phase);
    lungar::log_line("lungar-bake export", line);
    if (f.interior_path.empty()) continue;
    const lungar::sim::MotionFigures& m = f.interior;
    std::snprintf(line, sizeof line, "wrote %s: %zu interior points; SI share %.3f, apex : base %.3f, dorsal : "
                  "ventral %.3f, mean |d| %.2f mm, max |d| %.2f mm", f.interior_path.c_str(), f.interior_points,
                  m.si_share, m.apex_base_ratio, m.dorsal_ventral_ratio, m.mean_displacement_mm,
                  m.max_displacement_mm);
    lungar::log_line("lungar-bake export", line);
  }
  for (const lungar::sim::LesionExcursion& e : lungar::sim::lesion_excursions(*written)) {
    char line[256];
    std::snprintf(line, sizeof line, "lesion %s (%s lung): peak-to-peak %.2f mm, cranio-caudal %.2f mm", e.name.c_str(),
                  e.lung.c_str(), e.peak_to_peak_mm, e.si_mm);
    lungar::log_line("lungar-bake export", line);
  }
  return 0;
}

/// One line: what was written, and the figures the bake computed.
void log_summary(const lungar::sim::BakeCommand& cmd, const lungar::sim::BakeReport& r) {
  char line[512];
  std::snprintf(line, sizeof line, "wrote %s: %u nodes, %u lungs, %u coefficients, %.1f s; %s map, %llu folded triangles",
                cmd.out.c_str(), r.nodes, r.lungs, r.coefficients, r.bake_s, lungar::sim::kSphereMapNames.name(r.map),
                static_cast<unsigned long long>(r.folded_triangles));
  std::string message = line;
  if (r.evaluated) {
    std::snprintf(line, sizeof line, "; eq7 error %.4f, alpha %.4f", r.eq7_rms_rel_error, r.alpha);
    message += line;
  }
  if (r.transfer_nnz_per_row_mean > 0) {
    std::snprintf(line, sizeof line, "; %.0f non-zeros a transfer row", r.transfer_nnz_per_row_mean);
    message += line;
  }
  log_line(message);
}
}  // namespace

int main(int argc, char** argv) {
  lungar::sim::BakeCommand cmd;
  CLI::App app{"lungar-bake: bakes lung surfaces or CT label maps into a .lungbake asset (transfer-matrix SH, force bases, "
               "truncated rows) and reports its accuracy against the exact eq. (1)."};
  add_bake_options(app, cmd);
  lungar::sim::ExportCommand export_cmd;
  std::string export_gravity;
  CLI::App* export_sub = app.add_subcommand(
      "export", "write a baked asset's surface, displaced for a posture and a volume change, as PLY (x y z, dx dy dz "
                "in mm, LPS; the triangles) for 3D Slicer or ParaView");
  add_export_options(*export_sub, export_cmd, export_gravity);
  app.require_subcommand(0, 1);
  try {
    app.parse(argc, argv);
    if (export_sub->parsed()) return run_export(export_cmd, export_gravity);
    if (!cmd.procedural && cmd.meshes.empty() && cmd.labelmap.empty())
      throw CLI::RequiredError("--procedural, --mesh FILE or --labelmap FILE");
    if (cmd.out.empty()) throw CLI::RequiredError("--out");
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar-bake");
  }

  cmd.options.cancel = &g_interrupted;
  catch_interrupts();
  ProgressBar bar(::isatty(STDERR_FILENO) == 1);
  std::vector<std::string> notes;
  log_line(cmd.procedural  ? "baking the procedural pair, seed " + std::to_string(cmd.seed)
           : !cmd.labelmap.empty() ? "baking the lungs of the label map " + cmd.labelmap
                                   : "baking " + cmd.meshes.front() + (cmd.meshes.size() > 1 ? " and " + cmd.meshes[1] : ""));
  lungar::Result<lungar::sim::BakeReport> result = lungar::fail("not baked");
  try {
    result = lungar::sim::run_bake_command(cmd, [&](std::string_view s, double f) { bar(s, f); }, notes);
  } catch (const std::bad_alloc&) {
    bar.finish();
    std::fprintf(stderr, "lungar-bake: out of memory; try fewer --nodes\n");
    return 1;
  }
  bar.finish();
  for (const std::string& n : notes) log_line("note: " + n);
  if (!result) {
    std::fprintf(stderr, "lungar-bake: %s\n", result.error().c_str());
    return g_interrupted.load() ? 128 + g_signal.load() : 1;  // the shell's code for a process a signal ended
  }
  log_summary(cmd, *result);
  return 0;
}
