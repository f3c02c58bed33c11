/// @file soak_main.cpp
/// @brief lungar-soak: the runtime headless for a teaching day's worth of minutes, its tracker a real hidapi read
/// of an emulated hidraw device (umockdev) fed by a recorded log in a loop, unplugged and plugged back every
/// minute. Prints the process's peak RSS at 1 min, 1/4, 1/2 and the end, frame p99 and reconnects, and writes them
/// as JSON. Run under umockdev-wrapper (scripts/soak does).
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "config/base/atomic_file.h"
#include "config/base/clock.h"
#include "config/base/command_line.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_reader.h"
#include "platform/app/run.h"
#include "umockdev_tracker.h"

namespace {

using namespace lungar;
using Clock = std::chrono::steady_clock;

/// VmHWM (peak resident set) and VmRSS of this process, in MiB.
std::pair<double, double> rss_mib() {
  std::ifstream status("/proc/self/status");
  double hwm = 0, rss = 0;
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) == 0) hwm = std::stod(line.substr(6)) / 1024.0;
    if (line.rfind("VmRSS:", 0) == 0) rss = std::stod(line.substr(6)) / 1024.0;
  }
  return {hwm, rss};
}

struct Options {
  double minutes = 30;
  double unplug_every_s = 60;
  double unplugged_s = 2;
  std::string log = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/upright_to_supine.trk";
  std::string asset;  ///< empty: the demo asset
  std::string out = "out/soak";
  int min_reconnects = 0;  ///< a check for tests: fewer reconnects than this is a failure (exit 3)
};

/// Feeds the log's reports to the emulated device at their recorded pace, over and over, with the device time
/// moved on by a whole log each loop (the time field as the layout places it), and pulls the cable now and then.
class Feeder {
 public:
  Feeder(const Options& o, drivers::TrkLog log, const drivers::TrackerConfig& t) : o_(o), log_(std::move(log)), t_(t) {
    spec_.report_id = t.report.report_id;
    spec_.length = t.report.length;
  }
  bool plug() { return device_.plug(spec_); }
  void run(const std::atomic<bool>& stop);
  int unplugs() const { return unplugs_; }
  const std::string& error() const { return device_.error(); }

 private:
  void patch_time(std::vector<std::uint8_t>& report, std::uint64_t add_ticks) const;
  const Options& o_;
  drivers::TrkLog log_;
  drivers::TrackerConfig t_;
  testing::UmockdevTracker device_;
  testing::UmockdevTrackerSpec spec_;
  int unplugs_ = 0;
};

void Feeder::patch_time(std::vector<std::uint8_t>& r, std::uint64_t add_ticks) const {
  const int at = t_.report.time_offset, bytes = t_.report.time_bits / 8;
  if (at < 0 || at + bytes > static_cast<int>(r.size())) return;
  const bool little = t_.report.endian == drivers::Endian::Little;
  std::uint64_t v = 0;
  for (int k = 0; k < bytes; ++k) v |= std::uint64_t{r[static_cast<std::size_t>(at + (little ? k : bytes - 1 - k))]} << (8 * k);
  v += add_ticks;  // wraps in the field's width, as a device clock does
  for (int k = 0; k < bytes; ++k) r[static_cast<std::size_t>(at + (little ? k : bytes - 1 - k))] = static_cast<std::uint8_t>(v >> (8 * k));
}

void Feeder::run(const std::atomic<bool>& stop) {
  const auto& recs = log_.records;
  const std::int64_t span_ns = recs.back().t_arrival_ns - recs.front().t_arrival_ns + 16'000'000;
  auto next_unplug = Clock::now() + std::chrono::duration<double>(o_.unplug_every_s);
  for (std::uint64_t loop = 0; !stop.load(); ++loop) {
    const auto loop_start = Clock::now();
    const auto add_ticks = static_cast<std::uint64_t>(static_cast<double>(loop * span_ns) * 1e-3 / t_.report.time_tick_us);
    for (const auto& rec : recs) {
      if (stop.load()) return;
      std::this_thread::sleep_until(loop_start + std::chrono::nanoseconds(rec.t_arrival_ns - recs.front().t_arrival_ns));
      if (Clock::now() >= next_unplug) {
        device_.unplug();
        ++unplugs_;
        std::this_thread::sleep_for(std::chrono::duration<double>(o_.unplugged_s));
        if (!plug()) return;
        next_unplug = Clock::now() + std::chrono::duration<double>(o_.unplug_every_s);
      }
      std::vector<std::uint8_t> report(rec.report.begin(), rec.report.end());
      patch_time(report, add_ticks);
      (void)device_.write(report);  // unread reports beyond the node's buffer are lost, as on a busy bus
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"lungar-soak: the runtime for a long time on an emulated tracker that is unplugged every minute; "
               "peak RSS over the run (run under umockdev-wrapper, as scripts/soak does)"};
  app.add_option("--minutes", o.minutes, "how long")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--unplug-every", o.unplug_every_s, "seconds between unplugs")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--log", o.log, "tracker log to loop")->capture_default_str();
  app.add_option("--asset", o.asset, "baked asset (default: the demo lungs)");
  app.add_option("--out", o.out, "folder for stats.json, soak.json and the snapshot")->capture_default_str();
  app.add_option("--min-reconnects", o.min_reconnects, "exit 3 when the runtime reconnected fewer times (tests)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar-soak");
  }
  if (!testing::UmockdevTracker::available()) {
    std::fprintf(stderr, "lungar-soak: expected to run under umockdev-wrapper (tests/drivers/umockdev_run.sh)\n");
    return 2;
  }
  auto log = drivers::load_trk(o.log);
  if (!log || log->records.empty()) {
    std::fprintf(stderr, "lungar-soak: %s\n", log ? (o.log + ": no records").c_str() : log.error().c_str());
    return 2;
  }
  auto layout = drivers::tracker_config_from_toml(log->header.layout_toml, o.log);
  if (!layout) {
    std::fprintf(stderr, "lungar-soak: %s\n", layout.error().c_str());
    return 2;
  }
  Feeder feeder(o, std::move(*log), *layout);
  if (!feeder.plug()) {
    std::fprintf(stderr, "lungar-soak: %s\n", feeder.error().c_str());
    return 1;
  }
  platform::Settings s;
  s.display.output = platform::Output::Headless;
  s.sim.asset = o.asset;
  s.trackers() = *layout;
  s.trackers().source = drivers::TrackerSource::Hid;
  s.trackers().hid = {};  // the emulated device below, not whichever the log's header names
  s.trackers().hid.vendor_id = 0x1234;
  s.trackers().hid.product_id = 0x5678;
  platform::RuntimeOptions ro;
  ro.seconds = o.minutes * 60.0;
  ro.stats_json_path = o.out + "/stats.json";
  ro.snapshot_path = o.out + "/snapshot.png";

  std::atomic<bool> stop{false};
  std::thread feed([&] { feeder.run(stop); });
  // Peak RSS after the first minute (the baseline), at 1/4, 1/2 and the end of the run.
  const double total_s = o.minutes * 60.0;
  std::vector<std::pair<std::string, double>> marks = {{"1min", 60.0}, {"quarter", total_s / 4}, {"half", total_s / 2}};
  std::sort(marks.begin(), marks.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  nlohmann::ordered_json rss = nlohmann::ordered_json::object();
  std::mutex rss_mutex;
  std::thread watch([&] {
    const auto t0 = Clock::now();
    for (const auto& [name, at] : marks) {
      while (!stop.load() && std::chrono::duration<double>(Clock::now() - t0).count() < at) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
      }
      if (stop.load()) return;
      const auto [hwm, now] = rss_mib();
      std::lock_guard lock(rss_mutex);
      rss[name] = {{"at_s", at}, {"peak_rss_mib", hwm}, {"rss_mib", now}};
      std::fprintf(stderr, "lungar-soak: %-7s (%6.0f s): peak RSS %.1f MiB, RSS %.1f MiB\n", name.c_str(), at, hwm, now);
    }
  });
  const int rc = platform::run_runtime(s, ro);
  stop.store(true);
  feed.join();
  watch.join();
  const auto [hwm, now] = rss_mib();
  rss["end"] = {{"at_s", total_s}, {"peak_rss_mib", hwm}, {"rss_mib", now}};

  std::ifstream in(ro.stats_json_path);
  const nlohmann::json stats = nlohmann::json::parse(in, nullptr, false);
  nlohmann::ordered_json out = {{"minutes", o.minutes},
                                {"unplugs", feeder.unplugs()},
                                {"rss", rss},
                                {"runtime_exit_code", rc}};
  if (!stats.is_discarded()) {
    for (const char* key : {"frames", "frame_ms_p50", "frame_ms_p99", "tracker_reconnects", "tracker_reports",
                            "tracker_malformed", "pose_age_ms_p99"}) {
      if (stats.contains(key)) out[key] = stats[key];
    }
  }
  std::printf("%s\n", out.dump(2).c_str());
  if (Status written = write_file_atomically(o.out + "/soak.json", out.dump(2) + "\n"); !written) {
    std::fprintf(stderr, "lungar-soak: %s\n", written.error().c_str());
    return 1;
  }
  const int reconnects = out.value("tracker_reconnects", 0);
  if (rc == 0 && reconnects < o.min_reconnects) {
    std::fprintf(stderr, "lungar-soak: expected at least %d reconnects after %d unplugs, got %d\n", o.min_reconnects,
                 feeder.unplugs(), reconnects);
    return 3;
  }
  return rc;
}
