/// @file demo_asset.cpp
/// @brief Finds the demo's label map and lungar-bake, runs the bake once as a child process (the procedural pair's
///        too, in-process only when no lungar-bake is found), caches the asset.
#include "platform/app/demo_asset.h"
#include "platform/app/shipped_data.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include "config/base/clock.h"
#include "config/base/crc32.h"
#include "config/config_paths.h"
#include "sim/asset/asset_io.h"
#include "sim/parallel/parallel_for.h"

extern char** environ;

namespace lungar::platform {

namespace fs = std::filesystem;

namespace {

std::string cache_dir(const DemoAssetOptions& o) {
  return o.cache_dir.empty() ? config::cache_dir(config::XdgDirs::from_environment()) : o.cache_dir;
}

/// The folder of the running executable ("" when /proc cannot say).
fs::path exe_dir() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return !p.empty() && fs::is_regular_file(p, ec);
}

/// The shipped label map: $LUNGAR_DATA_DIR/lungs/, <exe dir>/../share/lungar/lungs/, the source tree.
fs::path find_label_map(const DemoAssetOptions& o) {
  std::vector<fs::path> places;
  if (!o.data_dir.empty()) places.push_back(fs::path(o.data_dir) / "lungs");
  for (fs::path& p : shipped_data_places("lungs", "sim/data/lungs")) places.push_back(std::move(p));
  for (const fs::path& p : places)
    if (is_file(p / kDemoLabelMap)) return (p / kDemoLabelMap).lexically_normal();
  return {};
}

/// lungar-bake beside the running lungar (installed), else the build tree's.
fs::path find_bake_tool(const DemoAssetOptions& o) {
  if (!o.bake_tool.empty()) return is_file(o.bake_tool) ? fs::path(o.bake_tool) : fs::path();
  if (const fs::path exe = exe_dir(); is_file(exe / "lungar-bake")) return exe / "lungar-bake";
  return is_file(LUNGAR_BAKE_TOOL) ? fs::path(LUNGAR_BAKE_TOOL) : fs::path();
}

/// Eight hex digits of the file's CRC-32: a changed map is a new cache entry ("" when unreadable).
std::string content_key(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  if (!in.eof() && in.fail()) return "";
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", crc32(bytes.data(), bytes.size()));
  return hex;
}

std::string ct_asset_path(const DemoAssetOptions& o, const fs::path& map) {
  char name[200];
  std::snprintf(name, sizeof name, "ct-%s-%s-n%u-L%u%s-v%u-b%u.lungbake", map.stem().c_str(), content_key(map).c_str(),
                o.nodes, o.bands, o.transfer_rows ? "-rows" : "", sim::kAssetVersion, sim::kBakeRevision);
  return (fs::path(cache_dir(o)) / name).string();
}

/// How long a bake asked to stop (SIGTERM: it stops at its next step) may take before it is killed.
constexpr std::int64_t kStopGraceNs = 500'000'000;

/// Removes `path` and the partial files an atomic write of it leaves beside it ("<path>.partial-XXXXXX").
void remove_with_partials(const fs::path& path) {
  std::error_code ec;
  fs::remove(path, ec);
  const std::string prefix = path.filename().string() + ".partial-";
  for (const auto& entry : fs::directory_iterator(path.parent_path(), ec)) {
    if (entry.path().filename().string().rfind(prefix, 0) == 0) fs::remove(entry.path(), ec);
  }
}

/// Waits for `pid`; once `*stop` is set, asks it to stop and, still running half a second later, kills it.
/// Whether it was stopped so.
bool wait_or_stop(pid_t pid, int& status, const std::atomic<bool>* stop) {
  std::int64_t asked_ns = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) return asked_ns != 0;
    if (done < 0 && errno != EINTR) return asked_ns != 0;
    if (stop != nullptr && stop->load()) {
      if (asked_ns == 0) {
        asked_ns = monotonic_ns();
        ::kill(pid, SIGTERM);
      } else if (monotonic_ns() - asked_ns > kStopGraceNs) {
        ::kill(pid, SIGKILL);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

/// Runs the bake `argv` (argv[0] a path) with the runtime's stdout and stderr, writing `out`, and waits for it.
/// It writes to a name of this process's own beside `out`, renamed into place when it succeeds, so that a stop
/// (Ctrl-C) removes everything it wrote, partial files included, and nothing half-baked is ever cached.
Status run_bake(std::vector<std::string> argv, const fs::path& out, const std::atomic<bool>* stop) {
  const fs::path own = out.string() + ".baking-" + std::to_string(::getpid());
  argv.push_back("--out");
  argv.push_back(own.string());
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ); e != 0)
    return fail(argv[0] + ": cannot start it: " + std::strerror(e));
  int status = 0;
  const bool stopped = wait_or_stop(pid, status, stop);
  if (stopped || !WIFEXITED(status) || WEXITSTATUS(status) != 0) remove_with_partials(own);
  if (stopped) return fail(argv[0] + ": stopped before the bake finished; nothing was cached");
  if (WIFSIGNALED(status)) return fail(argv[0] + ": stopped by signal " + std::to_string(WTERMSIG(status)));
  if (WEXITSTATUS(status) != 0)
    return fail(argv[0] + ": failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
  std::error_code ec;
  fs::rename(own, out, ec);
  if (ec) {
    remove_with_partials(own);
    return fail(out.string() + ": cannot move the baked asset into place: " + ec.message());
  }
  return ok();
}

/// The CT lungs: loaded from the cache, or baked by lungar-bake into it first.
Result<DrawnAsset> ct_asset(const DemoAssetOptions& o, const fs::path& map, const fs::path& tool,
                            const std::function<void(const std::string&)>& log) {
  const std::string path = ct_asset_path(o, map);
  const std::string name = fs::path(path).filename().string();
  std::error_code ec;
  if (fs::exists(path, ec)) {
    auto loaded = sim::load_asset(path);
    if (loaded) return DrawnAsset{loaded.take(), name, true};
    log("cached demo asset unusable (" + loaded.error() + "); baking it again");
  }
  log("baking the demo lungs from the CT label map " + map.string() + " with " + tool.string() +
      " (once; about a minute; cached at " + path + ")");
  fs::create_directories(fs::path(path).parent_path(), ec);
  std::vector<std::string> argv = {tool.string(),
                                   "--labelmap",
                                   map.string(),
                                   "--label",
                                   "right=2",
                                   "--label",
                                   "left=3",
                                   "--nodes",
                                   std::to_string(o.nodes),
                                   "--bands",
                                   std::to_string(o.bands),
                                   "--no-evaluate"};
  if (!o.transfer_rows) argv.push_back("--no-transfer-rows");
  if (Status s = run_bake(argv, path, o.stop); !s) return fail("demo asset: " + s.error());
  auto loaded = sim::load_asset(path);
  if (!loaded) return fail("demo asset: " + loaded.error());
  return DrawnAsset{loaded.take(), name, true};
}

/// The procedural pair baked here (no lungar-bake found), stopped at its next step once `o.stop` is set. The log
/// names each stage as it starts, and a stage's share done only where the bake knows one (no "0 %" that sits).
Result<sim::BakedAsset> bake_in_process(const DemoAssetOptions& o, const std::string& path,
                                        const std::function<void(const std::string&)>& log) {
  sim::BakeOptions bake;
  bake.bands = o.bands;
  bake.transfer_rows = o.transfer_rows;
  bake.evaluate = false;
  bake.cancel = o.stop;
  int last_percent = -1;
  std::string last_stage;
  Result<sim::BakeOutput> baked = fail("not baked");
  try {
    baked = sim::bake_procedural(o.nodes, o.seed, bake, [&](std::string_view stage, double fraction) {
      const int percent = static_cast<int>(fraction * 100.0);
      if (stage != last_stage) {
        last_stage = std::string(stage);
        last_percent = percent;
        log("  bake: " + last_stage + (percent > 0 ? " " + std::to_string(percent) + " %" : std::string()));
      } else if (percent / 25 != last_percent / 25) {
        last_percent = percent;
        log("  bake: " + last_stage + " " + std::to_string(percent) + " %");
      }
    });
  } catch (const sim::Cancelled&) {
    return fail("procedural demo asset: stopped before the bake finished; nothing was cached");
  }
  if (!baked) return fail("procedural demo asset: " + baked.error());
  if (auto written = sim::write_asset(baked->asset, path); !written) {
    log("could not cache the demo asset (" + written.error() + "); going on without the cache");
  }
  return std::move(baked->asset);
}

}  // namespace

bool centre_demo_lungs(const DrawnAsset& drawn, RegistrationSettings& r) {
  const RegistrationSettings identity;
  if (!drawn.demo_ct || r.translation_mm != identity.translation_mm || r.rotation_wxyz != identity.rotation_wxyz ||
      drawn.asset.positions.empty())
    return false;
  std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (std::size_t i = 0; i < drawn.asset.positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], drawn.asset.positions[i]);
    hi[i % 3] = std::max(hi[i % 3], drawn.asset.positions[i]);
  }
  for (int k = 0; k < 3; ++k) r.translation_mm[k] = -0.5 * (static_cast<double>(lo[k]) + hi[k]);
  return true;
}

std::string demo_asset_path(const DemoAssetOptions& o) {
  char name[160];
  std::snprintf(name, sizeof name, "procedural-n%u-s%llu-L%u%s-v%u-b%u.lungbake", o.nodes,
                static_cast<unsigned long long>(o.seed), o.bands, o.transfer_rows ? "-rows" : "", sim::kAssetVersion,
                sim::kBakeRevision);
  return (fs::path(cache_dir(o)) / name).string();
}

std::string demo_cache_path(const DemoAssetOptions& o) {
  if (!o.procedural) {
    const fs::path map = find_label_map(o);
    if (!map.empty() && !find_bake_tool(o).empty()) return ct_asset_path(o, map);
  }
  return demo_asset_path(o);
}

Result<DrawnAsset> load_drawn_asset(const std::string& configured_path, const DemoAssetOptions& o,
                                    const std::function<void(const std::string&)>& log) {
  if (!configured_path.empty()) {
    auto loaded = sim::load_asset(configured_path);
    if (!loaded) return fail(loaded.error());
    return DrawnAsset{loaded.take(), configured_path};
  }
  if (!o.procedural) {
    const fs::path map = find_label_map(o), tool = find_bake_tool(o);
    if (!map.empty() && !tool.empty()) return ct_asset(o, map, tool, log);
    log(std::string("warning: ") +
        (map.empty() ? "no CT label map (" + std::string(kDemoLabelMap) + ") found"
                     : "no lungar-bake found beside lungar or in the build tree") +
        "; drawing the procedural lungs instead (set LUNGAR_DATA_DIR, or see sim/data/lungs/README.md)");
  }
  auto baked = load_or_bake_demo_asset(o, log);
  if (!baked) return fail(baked.error());
  return DrawnAsset{baked.take(), fs::path(demo_asset_path(o)).filename().string()};
}

Result<sim::BakedAsset> load_or_bake_demo_asset(const DemoAssetOptions& o,
                                                const std::function<void(const std::string&)>& log) {
  const std::string path = demo_asset_path(o);
  std::error_code ec;
  if (fs::exists(path, ec)) {
    auto loaded = sim::load_asset(path);
    if (loaded) return loaded;
    log("cached demo asset unusable (" + loaded.error() + "); baking it again");
  }
  log("baking the procedural demo lungs (" + std::to_string(o.nodes) + " nodes, once; cached at " + path +
      "; Ctrl-C stops it)");
  fs::create_directories(fs::path(path).parent_path(), ec);
  // In a child, as the CT lungs: a Ctrl-C stops it within a second, not at the end of a long factorisation.
  if (const fs::path tool = find_bake_tool(o); !tool.empty()) {
    std::vector<std::string> argv = {tool.string(),  "--procedural",         "--nodes", std::to_string(o.nodes),
                                     "--seed",       std::to_string(o.seed), "--bands", std::to_string(o.bands),
                                     "--no-evaluate"};
    if (!o.transfer_rows) argv.push_back("--no-transfer-rows");
    if (Status s = run_bake(argv, path, o.stop); !s) return fail("procedural demo asset: " + s.error());
    auto loaded = sim::load_asset(path);
    if (!loaded) return fail("procedural demo asset: " + loaded.error());
    return loaded;
  }
  return bake_in_process(o, path, log);
}

}  // namespace lungar::platform
