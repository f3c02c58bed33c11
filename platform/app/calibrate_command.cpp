/// @file calibrate_command.cpp
/// @brief Reads the fiducials, fits the registration, reports the fiducial registration error, writes the result.
#include "platform/app/calibrate_command.h"

#include <cstdio>
#include <optional>

#include "config/toml_layers.h"
#include "drivers/decode/decoder.h"
#include "drivers/decode/report_layout.h"
#include "drivers/plus/plus_replay.h"
#include "drivers/plus/plus_sequence.h"
#include "drivers/replay/recorded_trackers.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_reader.h"
#include "platform/app/settings_load.h"
#include "platform/registration/landmark_matching.h"
#include "platform/registration/pivot_calibration.h"

namespace lungar::platform {

namespace {

/// The --config files' trackers, read once (none without --config): the report layout and the stylus's tip.
Result<std::optional<drivers::TrackerConfig>> config_trackers(const std::vector<std::string>& config_paths) {
  if (config_paths.empty()) return std::optional<drivers::TrackerConfig>{};
  auto s = load_settings(config_paths);
  if (!s) return s.with_context("");
  return std::optional<drivers::TrackerConfig>(s->trackers());
}

Eigen::Vector3d tip_of(const drivers::TrackerConfig& t) {
  const auto& tip = t.stylus.tip_offset_mm;
  return Eigen::Vector3d(tip[0], tip[1], tip[2]);
}

/// A path as the shell takes it: as it is when it holds only plain characters, else in single quotes.
std::string shell_word(const std::string& path) {
  const bool plain = !path.empty() && path.find_first_not_of(
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                          "0123456789_./-+,=:@%") == std::string::npos;
  if (plain) return path;
  std::string quoted = "'";
  for (char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

/// The stylus in the Reference's (the patient's) frame in each frame of a PLUS sequence where both are valid (or
/// the stylus is given relative to the Reference); the tip from --config, else none.
Result<StylusLog> stylus_poses_from_plus(const std::string& path, const std::vector<std::string>& config_paths) {
  auto seq = drivers::read_plus_sequence(path);
  if (!seq) return seq.with_context("");
  auto config = config_trackers(config_paths);
  if (!config) return config.with_context("");
  StylusLog out;
  if (*config) out.tip_offset_mm = tip_of(**config);
  const drivers::PlusConfig names = *config ? (*config)->plus : drivers::PlusConfig{};
  const auto tool_of = [&](const drivers::PlusFrame& f, drivers::Role role) -> const drivers::PlusTransform* {
    for (const drivers::PlusTransform& t : f.transforms)
      if (drivers::plus_tool_role(t.tool, names) == role) return &t;
    return nullptr;
  };
  const double t0 = seq->frames.empty() ? 0.0 : seq->frames.front().timestamp_s;
  for (const drivers::PlusFrame& f : seq->frames) {
    const drivers::PlusTransform* stylus = tool_of(f, drivers::Role::Stylus);
    if (!stylus || !stylus->valid) continue;
    Eigen::Matrix4d in_patient = stylus->matrix;
    if (stylus->frame != names.patient) {
      const drivers::PlusTransform* reference = tool_of(f, drivers::Role::Patient);
      if (!reference || !reference->valid || reference->frame != stylus->frame) continue;
      in_patient = reference->matrix.inverse() * stylus->matrix;
    }
    out.t_s.push_back(f.timestamp_s - t0);
    out.poses.push_back(Eigen::Isometry3d(in_patient));
  }
  if (out.poses.empty()) {
    return fail(path + ": expected frames with a valid " + names.stylus + " transform relative to the " +
                names.patient + " (or to the tracker beside a valid " + names.patient +
                "), got none ([trackers.plus] names the tools)");
  }
  return out;
}

Result<StylusLog> stylus_poses_from_log(const std::string& log_path, const std::vector<std::string>& config_paths) {
  if (drivers::is_plus_sequence_path(log_path)) return stylus_poses_from_plus(log_path, config_paths);
  auto loaded = drivers::load_trk(log_path);
  if (!loaded) return loaded.with_context("");
  auto config = config_trackers(config_paths);
  if (!config) return config.with_context("");
  // The report layout the log was recorded with: its header's, else the config's, else the defaults.
  auto trackers = drivers::recorded_trackers(*loaded, log_path, *config ? **config : drivers::TrackerConfig{});
  if (!trackers) return trackers.with_context("");
  auto layout = drivers::make_layout(*trackers);
  if (!layout) return layout.with_context(log_path + ": report layout: ");
  StylusLog out;
  // The tip is the stylus's, not the log's: a --config (where `calibrate pivot` wrote it) wins over the header.
  out.tip_offset_mm = tip_of(*config ? **config : *trackers);
  Eigen::Quaterniond patient_q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d patient_p = Eigen::Vector3d::Zero();
  const std::int64_t t0 = loaded->records.empty() ? 0 : loaded->records.front().t_arrival_ns;
  for (const auto& rec : loaded->records) {
    const drivers::DecodedReport r = drivers::decode_report(rec.report, *layout);
    if (r.error != drivers::DecodeError::None) continue;  // malformed reports are never applied
    for (int k = 0; k < r.count; ++k) {
      const auto& pose = r.poses[static_cast<std::size_t>(k)];
      const Eigen::Vector3d p = pose.position();
      if (pose.role == drivers::Role::Patient) {
        patient_q = pose.orientation().normalized();
        patient_p = p;
      } else if (pose.role == drivers::Role::Stylus) {
        Eigen::Isometry3d in_patient = Eigen::Isometry3d::Identity();
        in_patient.linear() = (patient_q.conjugate() * pose.orientation().normalized()).toRotationMatrix();
        in_patient.translation() = patient_q.conjugate() * (p - patient_p);
        out.t_s.push_back(static_cast<double>(rec.t_arrival_ns - t0) * 1e-9);
        out.poses.push_back(in_patient);
      }
    }
  }
  if (out.poses.empty()) return fail(log_path + ": expected stylus poses in the log, got none");
  return out;
}

Result<std::vector<Dwell>> stylus_dwells_from_log(const std::string& log_path,
                                                  const std::vector<std::string>& config_paths,
                                                  const std::optional<Eigen::Vector3d>& tip_mm) {
  auto log = stylus_poses_from_log(log_path, config_paths);
  if (!log) return log.with_context("");
  // A stylus is read at its tip, never at its sensor: an all-zero offset that nobody gave is a pivot calibration
  // not done (or not passed on), which would otherwise surface as a landmark that no touch fits.
  if (!tip_mm && log->tip_offset_mm.isZero()) {
    return fail(log_path + ": the stylus tip offset is missing: [trackers.stylus] tip_offset_mm is [0, 0, 0] (" +
                (config_paths.empty() ? std::string("no --config given") : "in " + config::join_paths(config_paths)) +
                "); find it with `lungar calibrate pivot --stylus-log pivot.trk --out stylus.toml`, then add "
                "`--config stylus.toml` here (or give --stylus-tip-mm x,y,z)");
  }
  const Eigen::Vector3d tip = tip_mm ? *tip_mm : log->tip_offset_mm;
  std::vector<StylusSample> samples;
  for (std::size_t i = 0; i < log->poses.size(); ++i) samples.push_back({log->t_s[i], log->poses[i] * tip});
  return find_dwells(samples);
}

Result<std::vector<Eigen::Vector3d>> stylus_points_from_log(const std::string& log_path,
                                                            const std::vector<std::string>& config_paths,
                                                            const std::optional<Eigen::Vector3d>& tip_mm) {
  auto dwells = stylus_dwells_from_log(log_path, config_paths, tip_mm);
  if (!dwells) return dwells.with_context("");
  std::vector<Eigen::Vector3d> points;
  for (const Dwell& d : *dwells) points.push_back(d.position_mm);
  return points;
}

std::string config_flags(const std::vector<std::string>& given, const std::string& out_path) {
  std::string flags;
  for (const std::string& p : given) {
    if (p != out_path) flags += "--config " + shell_word(p) + " ";  // a step re-run over its own output
  }
  return flags + "--config " + shell_word(out_path);
}

int run_pivot(const PivotOptions& o) {
  auto say = [](const std::string& message) { std::fprintf(stderr, "lungar calibrate pivot: %s\n", message.c_str()); };
  auto log = stylus_poses_from_log(o.stylus_log, o.config_paths);
  if (!log) return say(log.error()), 2;
  auto fit = fit_pivot(log->poses);
  if (!fit) return say(fit.error() + " (" + o.stylus_log + ")"), 2;
  if (Status written = write_tip_offset_toml(o.out_path, *fit); !written) return say(written.error()), 1;
  std::printf("stylus tip from %d poses turning up to %.1f degrees: RMS error %.3f mm (worst %.3f mm)\n", fit->poses,
              fit->spread_deg, fit->rms_mm, fit->max_mm);
  std::printf("  tip_offset_mm = [%.3f, %.3f, %.3f] (stylus frame); pivot at [%.3f, %.3f, %.3f] (patient frame)\n",
              fit->tip_mm.x(), fit->tip_mm.y(), fit->tip_mm.z(), fit->pivot_mm.x(), fit->pivot_mm.y(),
              fit->pivot_mm.z());
  std::printf(
      "written to %s; the registration reads it: lungar calibrate --model MODEL.csv --stylus-log TOUCHES.trk %s "
      "--out registration.toml\n",
      o.out_path.c_str(), config_flags(o.config_paths, o.out_path).c_str());
  return 0;
}

int run_calibrate(const CalibrateOptions& o) {
  auto say = [](const std::string& message) { std::fprintf(stderr, "lungar calibrate: %s\n", message.c_str()); };
  if (o.model_csv.empty() || o.out_path.empty()) return say("expected --model FILE.csv and --out FILE.toml"), 2;
  auto model = read_points_csv(o.model_csv);
  if (!model) return say(model.error()), 2;
  if (o.stylus_csv.empty() == o.stylus_log.empty()) {
    return say("expected exactly one of --stylus FILE.csv or --stylus-log FILE.trk"), 2;
  }
  if (o.stylus_tip_mm && !o.stylus_csv.empty())
    return say("--stylus-tip-mm applies to --stylus-log, not to --stylus"), 2;
  Registration r;
  std::vector<double> fre_mm;
  if (!o.stylus_csv.empty()) {  // the touches as pairs, in the model's order
    auto tracked = read_points_csv(o.stylus_csv);
    if (!tracked) return say(tracked.error()), 2;
    auto fitted = register_fiducials(*model, *tracked);
    if (!fitted) return say(fitted.error() + " (" + o.stylus_csv + ")"), 2;
    r = *fitted;
  } else {  // a session: dwells, repeats, rests; matched to the landmarks
    auto dwells = stylus_dwells_from_log(o.stylus_log, o.config_paths, o.stylus_tip_mm);
    if (!dwells) return say(dwells.error()), 2;
    auto matched = match_landmarks(*model, *dwells);
    if (!matched) return say(matched.error() + " (" + o.stylus_log + ")"), 2;
    for (const std::string& w : matched->warnings) say(w);
    r = matched->registration;
    fre_mm = matched->fre_mm;
  }
  if (Status written = write_registration_toml(o.out_path, r); !written) return say(written.error()), 1;
  std::printf("registration from %d fiducials: RMS fiducial registration error %.3f mm (worst %.3f mm)\n", r.fiducials,
              r.fre_rms_mm, r.fre_max_mm);
  for (std::size_t k = 0; k < fre_mm.size(); ++k) std::printf("  landmark %zu: %.3f mm\n", k + 1, fre_mm[k]);
  std::printf("  translation_mm = [%.3f, %.3f, %.3f], rotation_wxyz = [%.6f, %.6f, %.6f, %.6f]\n", r.translation_mm.x(),
              r.translation_mm.y(), r.translation_mm.z(), r.rotation.w(), r.rotation.x(), r.rotation.y(),
              r.rotation.z());
  std::printf("written to %s; the runtime reads it: lungar %s\n", o.out_path.c_str(),
              config_flags(o.config_paths, o.out_path).c_str());
  return 0;
}

}  // namespace lungar::platform
