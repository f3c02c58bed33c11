/// @file sync_probe_main.cpp
/// @brief lungar-sync-probe: one classroom station without rendering, to measure the DDS link on its own (clock
/// offset and spread, breath offset, pose age, lost and rejoin): an instructor publishes a pose turning at
/// 62.5 Hz and steady breathing; a trainee follows and prints its report as JSON.
///
///   lungar-sync-probe --role instructor --seconds 10 --domain 7 --cyclonedds-xml config/cyclonedds/loopback-tests.xml
///   lungar-sync-probe --role trainee --seconds 8 --domain 7 --cyclonedds-xml ... --report-json trainee.json
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <thread>

#include "config/base/atomic_file.h"
#include "config/base/clock.h"
#include "config/base/command_line.h"
#include "config/base/log_line.h"
#include "drivers/classroom/instructor.h"
#include "drivers/classroom/sync_report_json.h"
#include "drivers/classroom/trainee.h"

using namespace lungar;
using namespace lungar::classroom;

namespace {

std::atomic<bool> g_stop{false};

/// A patient turning slowly about the world x axis, one pose per tracker period.
void turn_pose(double t, std::array<double, 4>& q) {
  const double half = 0.5 * 0.3 * std::sin(0.5 * t);
  q = {std::cos(half), std::sin(half), 0.0, 0.0};
}

int run_instructor(const SyncOptions& o, double seconds) {
  auto made = Instructor::create(o);
  if (!made) {
    log_line("lungar-sync-probe", made.error());
    return 1;
  }
  Instructor& node = **made;
  const std::int64_t t0 = monotonic_ns();
  if (Status s = node.share_breathing(sim::BreathingParams{}, {}, {}, t0); !s) {
    log_line("lungar-sync-probe", s.error());
    return 1;
  }
  const std::int64_t period = 16'000'000;
  for (std::int64_t next = t0; !g_stop && monotonic_ns() - t0 < static_cast<std::int64_t>(seconds * 1e9);) {
    const std::int64_t now = monotonic_ns();
    const double t = seconds_between(t0, now);
    std::array<double, 4> q;
    turn_pose(t, q);
    node.publish_pose({0.0, 700.0, 0.0}, q, now);
    sim::BreathingSample breath;
    breath.t_s = t;
    node.frame_breath(now, breath);
    if (!node.fatal_error().empty()) return 1;
    next += period;
    std::this_thread::sleep_for(std::chrono::nanoseconds(std::max<std::int64_t>(0, next - monotonic_ns())));
  }
  log_line("lungar-sync-probe", report_json(node.report()));
  return 0;
}

int run_trainee(const SyncOptions& o, double seconds, const std::string& report_path) {
  auto made = Trainee::create(o);
  if (!made) {
    log_line("lungar-sync-probe", made.error());
    return 1;
  }
  const std::int64_t t0 = monotonic_ns();
  for (std::int64_t now = t0; !g_stop && now - t0 < static_cast<std::int64_t>(seconds * 1e9); now = monotonic_ns()) {
    sim::BreathingSample b;  // a frame every 16 ms that draws the shared breathing, as the runtime's does
    if ((*made)->breathing(now, b)) (*made)->frame_breath(now, b.t_s);
    std::this_thread::sleep_for(std::chrono::milliseconds(16));
  }
  const std::string json = report_json((*made)->report());
  if (!report_path.empty()) {
    if (Status w = write_file_atomically(report_path, json + "\n"); !w) {
      log_line("lungar-sync-probe", w.error());
      return 1;
    }
  }
  std::printf("%s\n", json.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lungar-sync-probe: one classroom station over Cyclone DDS, without rendering, to measure the link"};
  SyncOptions o;
  double seconds = 5.0;
  double skew_ms = 0.0;
  std::string report_path;
  app.add_option("--role", o.role, "instructor or trainee")
      ->required()
      ->transform(CLI::CheckedTransformer(kSyncRoleNames.map()));
  app.add_option("--classroom", o.classroom, "the classroom (DDS partition)");
  app.add_option("--domain", o.domain, "the DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--cyclonedds-xml", o.cyclonedds_xml, "the Cyclone DDS XML configuration")->required();
  app.add_option("--station", o.station, "this station's name (default host/pid)");
  app.add_option("--seconds", seconds, "how long to run")->check(CLI::Range(0.1, 3600.0));
  app.add_option("--clock-skew-ms", skew_ms, "pretend this station's clock is off by this much (tests)");
  app.add_option("--report-json", report_path, "a trainee's report, as JSON");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar-sync-probe");
  }
  if (o.role == SyncRole::Off) {
    log_line("lungar-sync-probe", "--role: expected instructor or trainee, got off");
    return 2;
  }
  o.clock_skew_ns = static_cast<std::int64_t>(skew_ms * 1e6);
  o.log = [](const std::string& line) { log_line("lungar-sync-probe", line); };
  std::signal(SIGINT, [](int) { g_stop = true; });
  std::signal(SIGTERM, [](int) { g_stop = true; });
  return o.role == SyncRole::Instructor ? run_instructor(o, seconds) : run_trainee(o, seconds, report_path);
}
