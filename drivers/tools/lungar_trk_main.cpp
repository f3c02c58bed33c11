/// @file lungar_trk_main.cpp
/// @brief lungar-trk: inspect (info), decode (dump as CSV or JSON lines), trim (cut) and synthesise (synth)
/// .trk tracker logs, and stand in for an OpenIGTLink tracker server (serve-igtl). Errors: one line on stderr
/// naming the file and what was expected; exit 1.
#include <CLI/CLI.hpp>

#include <atomic>
#include <cinttypes>
#include <csignal>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "drivers/decode/decoder.h"
#include "drivers/igtl/igtl_decoder.h"
#include "drivers/igtl/igtl_serve.h"
#include "drivers/mock/mock_reports.h"
#include "drivers/plus/plus_sequence_writer.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_reader.h"
#include "drivers/trk/trk_writer.h"
#include "config/base/command_line.h"
#include "config/base/log_line.h"
#include "lungar/version.h"

using namespace lungar;
using namespace lungar::drivers;

namespace {

int die(const std::string& line) {
  std::fprintf(stderr, "lungar-trk: %s\n", line.c_str());
  return 1;
}

/// Tracker settings from --config's [trackers] when given, else from the log's own header.
Result<TrackerConfig> settings_for(const TrkLog& log, const std::string& file,
                                   const std::vector<std::string>& config_paths) {
  if (!config_paths.empty()) return tracker_config_from_files(config_paths);
  if (log.header.layout_toml.empty()) {
    return fail(file + ": the log does not describe its report layout: expected --config FILE.toml");
  }
  return tracker_config_from_toml(log.header.layout_toml, file + " (header layout)");
}

/// Each sensor's reports per second, as the header's rate_hz counts them (a record carries one sensor's report, or
/// an OpenIGTLink message with one or more poses), decoded with the log's own layout; "" when it has none.
std::string sensor_rates(const TrkLog& log, const std::string& file) {
  if (log.header.layout_toml.empty()) return "";
  auto settings = settings_for(log, file, {});
  if (!settings) return "";
  auto layout = make_layout(*settings);
  auto igtl_layout = make_igtl_layout(settings->igtl, *settings);
  if (!layout || !igtl_layout) return "";
  struct Seen {
    std::size_t count = 0;
    std::int64_t first_ns = 0, last_ns = 0;
  };
  std::map<std::string, Seen> roles;
  for (const auto& rec : log.records) {
    const DecodedReport d = rec.source == TrkSource::Igtl ? decode_igtl_message(rec.report, *igtl_layout)
                                                          : decode_report(rec.report, *layout);
    for (int k = 0; d.error == DecodeError::None && k < d.count; ++k) {
      Seen& s = roles[to_string(d.poses[k].role)];
      if (s.count++ == 0) s.first_ns = rec.t_arrival_ns;
      s.last_ns = rec.t_arrival_ns;
    }
  }
  double sum = 0;
  int rated = 0;
  std::string each;
  for (const auto& [role, s] : roles) {
    if (s.count < 2 || s.last_ns <= s.first_ns) continue;
    const double hz = static_cast<double>(s.count - 1) / (static_cast<double>(s.last_ns - s.first_ns) * 1e-9);
    char part[64];
    std::snprintf(part, sizeof part, "%s%s %.2f", each.empty() ? "" : ", ", role.c_str(), hz);
    each += part;
    sum += hz;
    ++rated;
  }
  if (rated == 0) return "";
  char line[128];
  std::snprintf(line, sizeof line, "rate_hz: %.2f (each sensor's reports per second: ", sum / rated);
  return line + each + ")";
}

int info(const std::string& file) {
  auto r = load_trk(file);
  if (!r) return die(r.error());
  const TrkLog& log = *r;
  std::printf("file: %s\nversion: %u\n", file.c_str(), log.header.version);
  std::printf("description:\n");
  std::string d = log.header.description;
  std::size_t pos = 0;
  while (pos < d.size()) {
    std::size_t e = d.find('\n', pos);
    if (e == std::string::npos) e = d.size();
    std::printf("  %s\n", d.substr(pos, e - pos).c_str());
    pos = e + 1;
  }
  std::map<std::string, std::size_t> sources, lengths;
  for (const auto& rec : log.records) {
    ++sources[to_string(rec.source)];
    ++lengths[std::to_string(rec.report.size())];
  }
  const double dur_s = log.records.size() > 1
                           ? static_cast<double>(log.records.back().t_arrival_ns - log.records.front().t_arrival_ns) * 1e-9
                           : 0.0;
  std::printf("records: %zu\nduration_s: %.3f\n", log.records.size(), dur_s);
  // The header's rate_hz is each sensor's; the records of all sensors together come that many times more often.
  if (dur_s > 0) std::printf("records_per_s: %.2f\n", static_cast<double>(log.records.size() - 1) / dur_s);
  if (const std::string rates = sensor_rates(log, file); !rates.empty()) std::printf("%s\n", rates.c_str());
  for (const auto& [k, v] : sources) std::printf("source %s: %zu\n", k.c_str(), v);
  for (const auto& [k, v] : lengths) std::printf("report length %s: %zu\n", k.c_str(), v);
  std::printf("layout: %s\ntruncated_tail: %s\n", log.header.layout_toml.empty() ? "absent" : "present",
              log.truncated_tail ? "yes (the last, incomplete record is left out)" : "no");
  return 0;
}

int dump(const std::string& file, const std::string& format, const std::vector<std::string>& config_paths) {
  auto r = load_trk(file);
  if (!r) return die(r.error());
  auto settings = settings_for(*r, file, config_paths);
  if (!settings) return die(settings.error());
  auto layout = make_layout(*settings);
  if (!layout) return die(file + ": " + layout.error());
  auto igtl_layout = make_igtl_layout(settings->igtl, *settings);
  if (!igtl_layout) return die(file + ": " + igtl_layout.error());
  const bool csv = format == "csv";
  if (csv) std::printf("record,t_arrival_ns,t_device_ns,role,status,x_mm,y_mm,z_mm,qw,qx,qy,qz\n");
  DeviceClock clock;
  std::size_t index = 0;
  for (const auto& rec : r->records) {
    // An OpenIGTLink record decodes as a message, the others as HID reports (trk_format.h).
    DecodedReport d = rec.source == TrkSource::Igtl ? decode_igtl_message(rec.report, *igtl_layout)
                                                    : decode_report(rec.report, *layout);
    std::int64_t t_dev = -1;
    if (d.error == DecodeError::None && d.has_time) {
      t_dev = clock.advance(d.device_ticks, d.time_bits, d.time_tick_ns);
      if (t_dev < 0) d.error = DecodeError::TimeBackwards;
    }
    if (d.error != DecodeError::None || d.count == 0) {  // malformed, or only devices that feed no role
      const char* status = d.error != DecodeError::None ? to_string(d.error) : "ignored";
      if (csv) {
        std::printf("%zu,%" PRId64 ",,,%s,,,,,,,\n", index, rec.t_arrival_ns, status);
      } else {
        std::printf("{\"record\":%zu,\"t_arrival_ns\":%" PRId64 ",\"status\":\"%s\"}\n", index, rec.t_arrival_ns,
                    status);
      }
    }
    for (int k = 0; d.error == DecodeError::None && k < d.count; ++k) {
      const auto& p = d.poses[k];
      if (csv) {
        std::printf("%zu,%" PRId64 ",%" PRId64 ",%s,ok,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f\n", index, rec.t_arrival_ns,
                    t_dev, to_string(p.role), p.position_mm[0], p.position_mm[1], p.position_mm[2],
                    p.orientation_wxyz[0], p.orientation_wxyz[1], p.orientation_wxyz[2], p.orientation_wxyz[3]);
      } else {
        std::printf("{\"record\":%zu,\"t_arrival_ns\":%" PRId64 ",\"t_device_ns\":%" PRId64
                    ",\"role\":\"%s\",\"status\":\"ok\",\"position_mm\":[%.4f,%.4f,%.4f],"
                    "\"orientation_wxyz\":[%.6f,%.6f,%.6f,%.6f]}\n",
                    index, rec.t_arrival_ns, t_dev, to_string(p.role), p.position_mm[0], p.position_mm[1],
                    p.position_mm[2], p.orientation_wxyz[0], p.orientation_wxyz[1], p.orientation_wxyz[2],
                    p.orientation_wxyz[3]);
      }
    }
    ++index;
  }
  if (r->truncated_tail) {
    std::fprintf(stderr, "lungar-trk: %s: the last record is incomplete (cut short while writing) and is left out\n",
                 file.c_str());
  }
  return 0;
}

/// The log as a PLUS sequence (3D Slicer opens it), decoded with the [trackers] of its header (else the defaults).
int to_plus(const std::string& file, const std::string& out) {
  auto r = load_trk(file);
  if (!r) return die(r.error());
  int skipped = 0;
  auto seq = plus_from_trk(*r, file, TrackerConfig{}, skipped);
  if (!seq) return die(seq.error());
  if (Status w = write_plus_sequence(out, *seq); !w) return die(w.error());
  std::printf("%s: %zu frames from %zu records (%d malformed, left out)\n", out.c_str(), seq->frames.size(),
              r->records.size(), skipped);
  return 0;
}

int cut(const std::string& file, const std::string& out, double from_s, double to_s) {
  auto r = load_trk(file);
  if (!r) return die(r.error());
  if (!(to_s > from_s)) return die("--to: expected a time after --from (" + std::to_string(from_s) + " s)");
  TrkWriter w;
  if (Status s = w.open(out, r->header, TrkWriter::Mode::Atomic); !s) return die(s.error());
  const std::int64_t t0 = r->records.empty() ? 0 : r->records.front().t_arrival_ns;
  for (const auto& rec : r->records) {
    const double t = static_cast<double>(rec.t_arrival_ns - t0) * 1e-9;
    if (t < from_s || t >= to_s) continue;
    if (Status s = w.append(rec.source, rec.t_arrival_ns, rec.report); !s) return die(s.error());
  }
  if (Status s = w.commit(); !s) return die(s.error());
  std::fprintf(stderr, "lungar-trk: wrote %" PRIu64 " records to %s\n", w.records(), out.c_str());
  return 0;
}

int synth(const std::string& out, const std::vector<std::string>& config_paths, const std::string& trajectory,
          double seconds, double rate_hz, double noise_mm, double dropout) {
  TrackerConfig t;
  if (!config_paths.empty()) {
    auto r = tracker_config_from_files(config_paths);
    if (!r) return die(r.error());
    t = *r;
  }
  if (!trajectory.empty()) t.mock.trajectory = trajectory;
  if (rate_hz > 0) t.mock.rate_hz = rate_hz;
  t.mock.noise_mm = noise_mm;
  t.mock.dropout = dropout;
  if (!mock_pose(t.mock.trajectory, Role::Head, 0)) {
    return die(unknown_trajectory("--trajectory", t.mock.trajectory));
  }
  auto layout = make_layout(t);
  if (!layout) return die(layout.error());
  TrkHeader h;
  h.description = "source=synth\ntrajectory=" + t.mock.trajectory + "\nrate_hz=" + std::to_string(t.mock.rate_hz) +
                  "\nseconds=" + std::to_string(seconds) + "\nnoise_mm=" + std::to_string(noise_mm) +
                  "\ndropout=" + std::to_string(dropout) + "\n";
  h.layout_toml = tracker_config_to_toml(t);
  TrkWriter w;
  if (Status s = w.open(out, h, TrkWriter::Mode::Atomic); !s) return die(s.error());
  MockReports reports(t.mock, *layout);
  const auto ticks = static_cast<std::int64_t>(seconds * t.mock.rate_hz);
  const std::int64_t period_ns = static_cast<std::int64_t>(1e9 / t.mock.rate_hz);
  Status written;
  for (std::int64_t k = 0; k < ticks && written; ++k) {
    // Arrival times start at 1 s, a report's own period apart, as if read on time.
    reports.tick(k, [&](std::span<const std::uint8_t> bytes) {
      if (written) written = w.append(TrkSource::Synth, 1'000'000'000 + k * period_ns, bytes);
    });
  }
  if (written) written = w.commit();
  if (!written) return die(written.error());
  std::fprintf(stderr, "lungar-trk: wrote %" PRIu64 " records to %s\n", w.records(), out.c_str());
  return 0;
}

std::atomic<bool> g_stop{false};

int serve(const ServeIgtlOptions& o) {
  std::signal(SIGINT, [](int) { g_stop = true; });
  std::signal(SIGTERM, [](int) { g_stop = true; });
  const auto log = [](const std::string& line) { log_line("lungar-trk", line); };
  auto served = serve_igtl(o, g_stop, log, [&](int port) {
    log("serving OpenIGTLink on " + o.address + ":" + std::to_string(port) + " (TRANSFORM " + o.head + ", " +
        o.patient + (o.stylus.empty() ? "" : ", " + o.stylus) + "; " + o.trajectory + "); Ctrl-C stops");
  });
  if (!served) return die(served.error());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lungar-trk: inspect, dump, cut, convert and synthesise .trk tracker logs; serve OpenIGTLink poses"};
  app.set_version_flag("--version", std::string("lungar-trk ") + LUNGAR_VERSION);
  app.require_subcommand(1);
  std::string file, out, format = "csv", trajectory = "upright_to_supine";
  std::vector<std::string> config_paths;  // --config, repeatable
  double from_s = 0, to_s = 1e12, seconds = 6.0, rate_hz = 0, noise_mm = 0, dropout = 0;

  auto* info_cmd = app.add_subcommand("info", "header, record count, duration and rate of a log");
  info_cmd->add_option("file", file, ".trk log")->required();
  auto* dump_cmd = app.add_subcommand("dump", "decode every record to CSV or JSON lines on stdout");
  dump_cmd->add_option("file", file, ".trk log")->required();
  dump_cmd->add_option("--format", format, "csv | jsonl")->check(CLI::IsMember({"csv", "jsonl"}));
  dump_cmd
      ->add_option("--config", config_paths,
                   "decode with this config's [trackers] layout, not the log's (repeatable: later over earlier)")
      ->allow_extra_args(false);
  auto* cut_cmd = app.add_subcommand("cut", "copy the records between --from and --to seconds into a new log");
  cut_cmd->add_option("file", file, ".trk log")->required();
  cut_cmd->add_option("out", out, "new .trk log")->required();
  cut_cmd->add_option("--from", from_s, "start, seconds from the first record");
  cut_cmd->add_option("--to", to_s, "end (exclusive), seconds from the first record");
  auto* plus_cmd = app.add_subcommand("to-plus", "convert a log to a PLUS sequence (.igs.mha) that 3D Slicer opens");
  plus_cmd->add_option("file", file, ".trk log")->required();
  plus_cmd->add_option("out", out, "new .igs.mha")->required();
  auto* synth_cmd = app.add_subcommand("synth", "write a log of a mock trajectory through a report layout");
  synth_cmd->add_option("out", out, "new .trk log")->required();
  synth_cmd
      ->add_option("--config", config_paths,
                   "config TOML whose [trackers] layout to use, repeatable: later over earlier (default: built-in)")
      ->allow_extra_args(false);
  synth_cmd->add_option("--trajectory", trajectory, kMockTrajectoriesExpected);
  synth_cmd->add_option("--seconds", seconds, "duration, s")->check(CLI::Range(0.01, 3600.0));
  synth_cmd->add_option("--rate-hz", rate_hz, "reports per sensor per second (default: the config's)")
      ->check(CLI::Range(1.0, 2000.0));
  synth_cmd->add_option("--noise-mm", noise_mm, "Gaussian position noise, mm")->check(CLI::Range(0.0, 100.0));
  synth_cmd->add_option("--dropout", dropout, "probability of dropping a report")->check(CLI::Range(0.0, 1.0));
  ServeIgtlOptions serve_opts;
  auto* serve_cmd = app.add_subcommand(
      "serve-igtl", "stream a mock trajectory as OpenIGTLink TRANSFORM messages, as a PlusServer would (a stand-in "
                    "to try `lungar --tracker igtl:HOST:PORT` without a tracker)");
  serve_cmd->add_option("--address", serve_opts.address, "IPv4 address to listen on (0.0.0.0: every interface)");
  serve_cmd->add_option("--port", serve_opts.port, "TCP port (0: any free one, printed)")->check(CLI::Range(0, 65535));
  serve_cmd->add_option("--rate-hz", serve_opts.rate_hz, "messages per device per second")
      ->check(CLI::Range(1.0, 1000.0));
  serve_cmd->add_option("--trajectory", serve_opts.trajectory, kMockTrajectoriesExpected);
  serve_cmd->add_option("--seconds", serve_opts.seconds, "stop after this long (0: until Ctrl-C)")
      ->check(CLI::Range(0.0, 1e6));
  serve_cmd->add_option("--head", serve_opts.head, "device name of the head pose (\"\": not sent)");
  serve_cmd->add_option("--patient", serve_opts.patient, "device name of the patient pose (\"\": not sent)");
  serve_cmd->add_option("--stylus", serve_opts.stylus, "device name of the stylus pose (default: not sent)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar-trk");
  }

  if (info_cmd->parsed()) return info(file);
  if (dump_cmd->parsed()) return dump(file, format, config_paths);
  if (cut_cmd->parsed()) return cut(file, out, from_s, to_s);
  if (plus_cmd->parsed()) return to_plus(file, out);
  if (serve_cmd->parsed()) return serve(serve_opts);
  return synth(out, config_paths, trajectory, seconds, rate_hz, noise_mm, dropout);
}
