/// @file run.cpp
/// @brief Wiring a Runtime from the settings, the frame loop's limits, and the outputs of a run.
#include "platform/app/run.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

#include "config/base/atomic_file.h"
#include "config/base/clock.h"
#include "config/scenario_load.h"
#include "drivers/breath/breath_factory/breath_factory.h"
#include "drivers/breath/trace/clearest_trace.h"
#include "drivers/classroom/classroom_station.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "platform/app/console_run.h"
#include "platform/app/demo_asset.h"
#include "platform/app/join_classroom.h"
#include "platform/app/log.h"
#include "platform/app/open_output.h"
#include "platform/app/plus_recording.h"
#include "platform/app/run_limit.h"
#include "platform/app/runtime_settings.h"
#include "platform/app/scenario_adapter.h"
#include "platform/app/scene_lesions.h"
#include "platform/app/session_recording.h"
#include "platform/app/settings_load.h"
#include "platform/app/tracker_poses.h"
#include "platform/runtime/pathology_course.h"
#include "platform/runtime/runtime.h"
#include "platform/runtime/scenario_patient.h"
#include "sim/asset/asset_io.h"
#include "sim/pathology/pathology.h"

namespace lungar::platform {

std::atomic<bool> g_stop_requested{false};

namespace {

const char* const kDefaultSnapshot = "out/snapshot.png";
const char* const kDefaultStats = "out/stats.json";

/// The settings' scenario, read once for the lungs (its pathologies and their events); none without one, or when
/// it does not load: the breathing reads it again and reports what is wrong (add_sources).
std::optional<config::Scenario> the_scenario(const Settings& s) {
  if (s.breathing.scenario.empty()) return std::nullopt;
  Result<config::Scenario> scenario = config::load_scenario(s.breathing.scenario, s.breathing);
  if (!scenario) return std::nullopt;
  return scenario.take();
}

/// The configured asset, or the demo's lungs baked once and cached (the CT pair, centred on the patient; the
/// procedural one on --procedural); with the name the stats JSON reports, and the course of the scenario's
/// pathology events (none without them). `lungs` keeps what a trainee needs to draw its instructor's lungs.
Result<std::shared_ptr<LungScene>> load_scene(Settings& s, bool procedural, const std::optional<config::Scenario>& scenario,
                                              std::shared_ptr<PathologyCourse>& course, LoadedLungs& lungs) {
  DemoAssetOptions demo;
  demo.transfer_rows = s.render.deform == Deform::Cpu1;
  demo.procedural = procedural;
  demo.stop = &g_stop_requested;  // Ctrl-C during a first run's bake
  Result<DrawnAsset> drawn = load_drawn_asset(s.sim.asset, demo, log_line);
  if (!drawn) return drawn.with_context("");
  if (centre_demo_lungs(*drawn, s.registration)) log_line("demo: the CT lungs' centre put on the patient tracker");
  // After centring: the registration places the healthy pair, and a collapsed lung shrinks inside it.
  lungs.own = timeline_of(s.sim.pathologies, scenario ? &*scenario : nullptr);
  const bool trainee = s.sync.role == classroom::SyncRole::Trainee;
  // A trainee's lungs, and those of an instructor with its console, change as the class goes.
  const bool changing = trainee || (s.sync.role == classroom::SyncRole::Instructor && !s.console.listen.empty());
  if (!lungs.own.events.empty() || changing)  // each state of a course is built from it
    lungs.healthy = std::make_shared<const sim::BakedAsset>(drawn->asset);
  sim::PatientState patient = sim::PatientState::of(drawn->asset);
  if (Status p = sim::apply_pathologies(drawn->asset, patient, s.sim.pathologies); !p)
    return p.with_context("sim.pathology: ");
  if (changing) {
    lungs.drawn = s.sim.pathologies.empty() ? lungs.healthy : std::make_shared<const sim::BakedAsset>(drawn->asset);
    lungs.drawn_patient = patient;
  }
  if (!lungs.own.events.empty()) {
    Result<std::shared_ptr<PathologyCourse>> made = PathologyCourse::create(*lungs.healthy, drawn->asset, lungs.own);
    if (!made) return made.with_context("scenario " + s.breathing.scenario + ": ");
    course = made.take();
    log_line("pathologies: " + sim::describe(lungs.own));
  }
  for (const std::string& spec : s.sim.pathologies) {
    log_line("pathology: " + spec);
    drawn->name += " with " + spec;  // the stats JSON's "asset" says what was drawn
  }
  return LungScene::create(std::move(drawn->asset), std::move(patient), drawn->name,
                           {.half_float = s.render.half_float});
}

/// The breath source's options: the model, a trace's settings, the Cyclone configuration the DDS sources join with.
breath::BreathSourceOptions breath_options(const Settings& s, std::shared_ptr<const sim::BreathingScript> script) {
  breath::BreathSourceOptions options;
  options.script = std::move(script);
  options.trace.skip_flagged = s.breathing.rpm_flagged == "skip";
  options.cyclonedds_xml = s.sync.cyclonedds_xml.empty() ? classroom::default_cyclonedds_xml() : s.sync.cyclonedds_xml;
  options.log = [](const std::string& line) { log_line(line); };
  return options;
}

/// What --breath names: the one source given, or of several recordings the clearest (said in the log); empty when
/// it was not given.
Result<std::string> given_breath(const RuntimeOptions& o) {
  if (o.breath_paths.size() <= 1) return o.breath_paths.empty() ? std::string() : o.breath_paths.front();
  std::string said;
  auto best = breath::clearest_trace(o.breath_paths, said);
  if (best) log_line("breathing: " + said);
  return best;
}

/// This station's tracker, and the breathing script; with the mock tracker (no real patient to follow) a scenario
/// file, or a script with turns, lays the patient: its start pose, then its turns.
Status add_sources(const Settings& s, const RuntimeOptions& o, double limit_s, std::int64_t t0,
                   const LoadedLungs& lungs, RuntimeParts& parts, sync::JoinedClassroom& classroom) {
  auto script = load_breathing_script(s.breathing, limit_s > 0 ? limit_s : 60.0);
  if (!script) return script.with_context("");
  auto shared_script = std::make_shared<const sim::BreathingScript>(script.take());
  drivers::TrackerOptions topts;
  topts.record_path = tracker_record_path(o.record_path);
  topts.log = [](const std::string& line) { log_line(line); };
  // --breath (the clearest of several recordings), else [breathing] source ("model": the script itself).
  auto given = given_breath(o);
  if (!given) return given.with_context("--breath: ");
  const bool modelled = breath::breath_kind(s.breathing.source) == breath::BreathKind::Model;
  const std::string breath = !given->empty() ? *given : modelled ? "" : s.breathing.source;
  const std::string where = !given->empty() ? "--breath: " : "breathing.source: ";
  auto chosen = breath::choose_breath_source(breath, t0);  // a live marker's feed exists before its tracker
  if (!chosen) return chosen.with_context(where);
  topts.on_sample = chosen->tracker_tap();
  auto made = drivers::make_tracker(s.trackers(), topts);
  if (!made) return made.with_context("tracker: ");
  parts.poses = std::make_unique<TrackerPoses>(made.take());
  // An instructor serving its console turns the simulated patient through its class control instead, which starts
  // from the same script (join_classroom): one track read each frame, not one over the other.
  const bool console_turns = s.sync.role == classroom::SyncRole::Instructor && !s.console.listen.empty();
  if (s.trackers().source == drivers::TrackerSource::Mock && !console_turns &&
      (!s.breathing.scenario.empty() || !shared_script->orientation.turns().empty())) {
    parts.poses =
        std::make_unique<ScenarioPatient>(std::move(parts.poses), std::make_shared<ScriptTrack>(shared_script), t0);
  }
  if (chosen->followed() && s.sync.role == classroom::SyncRole::Trainee) {
    return fail(where +
                "a trainee breathes with its instructor, whatever the instructor follows; give the instructor "
                "--breath, and run the trainee without it (breathing.source = \"" +
                std::string(kBreathSourceNames.name(BreathSource::Model)) + "\")");
  }
  auto breathing = breath::make_breath_source(*chosen, breath_options(s, shared_script), t0);
  if (!breathing) return breathing.with_context(where);
  parts.breathing = breathing.take();
  auto joined =
      sync::join_classroom(s, static_cast<std::int64_t>(o.sync_clock_skew_ms * 1e6), *shared_script, lungs, t0,
                           chosen->followed() ? breath : "", parts, [](const std::string& line) { log_line(line); });
  if (!joined) return joined.with_context("");
  classroom = joined.take();
  if (classroom::Instructor* instructor = classroom.station ? classroom.station->instructor() : nullptr;
      instructor && chosen->followed()) {
    instructor->share_followed_breath();
    log_line("classroom: sharing the followed breath: every frame's dV goes to the trainees");
  }
  return ok();
}

/// The slow parts first (a display error shows before a long first bake): the output and the lungs on it.
Status open_output_and_scene(Settings& s, bool procedural, const std::optional<config::Scenario>& scenario,
                             RuntimeParts& parts, std::shared_ptr<PathologyCourse>& course, LoadedLungs& lungs) {
  auto output = open_output(s, log_line);
  if (!output) return output.with_context("");
  parts.output = output.take();
  log_line("output: " + parts.output->describe());
  auto scene = load_scene(s, procedural, scenario, course, lungs);
  if (!scene) return scene.with_context("");
  parts.scene = scene.take();
  const sim::BakedAsset& a = parts.scene->asset();
  log_line("asset: " + parts.scene->name() + ": " + std::to_string(a.vertex_count()) + " nodes, " +
           std::to_string(a.lungs.size()) + " lungs, " + std::to_string(a.coefficients()) + " SH coefficients");
  auto lesions = scene_lesions(s.sim.lesions, a);
  if (!lesions) return lesions.with_context("");
  parts.lesions = lesions.take();
  return ok();
}

/// The stats JSON: the runtime's, the lungs' pathologies for the whole run when no course of them says, and the
/// console's counts.
nlohmann::ordered_json stats_of(Runtime& runtime, double wall_s, const std::vector<std::string>& pathologies,
                                const ConsoleRun* console) {
  nlohmann::ordered_json stats = runtime.stats_json(wall_s);
  if (!stats.contains("pathologies")) stats["pathologies"] = pathologies;
  if (console != nullptr) {
    nlohmann::json keys;
    console->add_stats(keys);
    for (const auto& [key, value] : keys.items()) stats[key] = value;
  }
  return stats;
}

/// Frames until a limit, a closed output, the end of a replay, a stop request or an error; with --stats-every,
/// the stats JSON written again as it goes.
Status run_frames(Runtime& runtime, const RuntimeOptions& o, double limit_s, std::int64_t t0,
                  const classroom::ClassroomStation& classroom, const std::vector<std::string>& pathologies,
                  const ConsoleRun* console) {
  std::int64_t next_stats = o.stats_every_s ? t0 : std::numeric_limits<std::int64_t>::max();
  const std::string stats_path = !o.stats_json_path.empty() ? o.stats_json_path : std::string(kDefaultStats);
  while (!g_stop_requested.load()) {
    if (const std::int64_t now = monotonic_ns(); now >= next_stats) {
      next_stats = now + static_cast<std::int64_t>(*o.stats_every_s * 1e9);
      const std::string text = stats_of(runtime, seconds_between(t0, now), pathologies, console).dump(2) + "\n";
      if (Status written = write_file_atomically(stats_path, text); !written) return fail("stats: " + written.error());
    }
    if (const std::string refused = classroom.fatal_error(); !refused.empty()) return fail(refused);
    if (o.frames && runtime.frames() >= *o.frames) break;
    if (limit_s > 0 && seconds_between(t0, monotonic_ns()) >= limit_s) break;
    if (!runtime.keep_running()) {
      log_line(runtime.poses().finished() ? "replay finished" : "output closed");
      break;
    }
    if (Status drawn = runtime.frame(); !drawn) return drawn;
  }
  if (g_stop_requested.load()) log_line("stop requested; writing the outputs");
  return ok();
}

/// The snapshot (a last frame, not counted) and the stats JSON; every output is written whole or not at all.
/// `pathologies`: the lungs' for the whole run, which the stats JSON reports when no course of them does.
int write_outputs(Runtime& runtime, const RuntimeOptions& o, double wall_s, bool frames_ok,
                  const std::vector<std::string>& pathologies, const ConsoleRun* console) {
  int exit_code = frames_ok ? 0 : 1;
  const std::string snapshot = !o.snapshot_path.empty() ? o.snapshot_path : std::string(kDefaultSnapshot);
  const std::string stats_path = !o.stats_json_path.empty() ? o.stats_json_path : std::string(kDefaultStats);
  if (frames_ok) {
    if (Status shot = runtime.final_frame(snapshot); !shot) {
      log_line("error: " + shot.error());
      exit_code = 1;
    } else {
      log_line("snapshot: " + snapshot);
    }
  }
  runtime.poses().stop();
  const nlohmann::ordered_json stats = stats_of(runtime, wall_s, pathologies, console);
  if (Status written = write_file_atomically(stats_path, stats.dump(2) + "\n"); !written) {
    log_line("error: stats: " + written.error());
    exit_code = 1;
  } else {
    log_line("stats: " + stats_path);
  }
  log_line(runtime.summary(wall_s));
  return exit_code;
}

/// A scenario's patient brings its pathologies (after the settings' own): an error when one of them is one the
/// settings (or --pathology) already give otherwise (a second pneumothorax of the same lung would compound), or
/// when the scenario's events add one already there.
Status take_the_scenarios_pathologies(const std::optional<config::Scenario>& scenario, Settings& s) {
  if (!scenario) return ok();
  const std::string name = scenario->name.empty() ? scenario->source : scenario->name;
  std::vector<std::string> taken = s.sim.pathologies;
  for (const std::string& spec : scenario->pathologies) {
    if (std::find(taken.begin(), taken.end(), spec) != taken.end()) continue;
    taken.push_back(spec);
  }
  if (Status own = sim::check_pathologies(scenario->pathologies); !own) {
    return own.with_context("scenario " + scenario->source + ": key 'pathology': ");
  }
  if (Status distinct = sim::check_pathologies(taken); !distinct) {
    return distinct.with_context("scenario " + scenario->source +
                                 ": key 'pathology' against sim.pathology (or --pathology): ");
  }
  if (Status course = sim::check_timeline(timeline_of(taken, &*scenario)); !course) {
    return course.with_context("scenario " + scenario->source + ": ");
  }
  for (std::size_t k = s.sim.pathologies.size(); k < taken.size(); ++k)
    log_line("scenario " + name + ": pathology " + taken[k]);
  s.sim.pathologies = std::move(taken);
  return ok();
}

/// A pathology's breathing (an emphysema's poor recoil: the emphysema preset) is the breathing's, unless the
/// breathing was chosen otherwise.
void breathe_as_the_pathologies_do(Settings& s) {
  const sim::BreathingHint hint = sim::breathing_of(s.sim.pathologies);
  if (hint.preset.empty() || s.breathing.preset != kPresetNames.name(Preset::Normal) || !s.breathing.scenario.empty())
    return;
  s.breathing.preset = hint.preset;
  log_line("pathology: " + hint.spec + " breathes with the " + hint.preset + " preset");
}

}  // namespace

int run_runtime(const Settings& configured, const RuntimeOptions& o) {
  Settings s = configured;  // the demo's CT lungs may set the registration
  const std::optional<config::Scenario> scenario = the_scenario(s);
  if (Status taken = take_the_scenarios_pathologies(scenario, s); !taken) {
    log_line("error: " + taken.error());
    return 2;
  }
  breathe_as_the_pathologies_do(s);
  log_line(summarize(s, scenario ? &*scenario : nullptr));
  const double limit_s = run_limit_s(o, scenario ? &*scenario : nullptr);
  RuntimeParts parts;
  std::shared_ptr<PathologyCourse> course;
  LoadedLungs lungs;
  if (Status opened = open_output_and_scene(s, o.procedural, scenario, parts, course, lungs); !opened) {
    log_line("error: " + opened.error());
    return 1;
  }
  const std::int64_t t0 = monotonic_ns();  // breathing, the scenario and the time limit start now
  if (course) {
    course->start_at(t0);
    parts.course = course;
  }
  sync::JoinedClassroom classroom;
  if (Status sources = add_sources(s, o, limit_s, t0, lungs, parts, classroom); !sources) {
    log_line("error: " + sources.error());
    return 1;
  }
  log_line("tracker: " + parts.poses->describe());
  // --session-record: the session's record from the first frame on (platform/app/session_recording.h).
  auto recording = start_session_recording(s, o, lungs.own, t0, parts);
  if (!recording) {
    log_line("error: " + recording.error());
    return 1;
  }
  const std::shared_ptr<record::SessionRecorder> recorder = recording.take();
  auto runtime = Runtime::create(runtime_config(s), std::move(parts));
  if (!runtime) {
    log_line("error: " + runtime.error());
    return 1;
  }
  std::unique_ptr<ConsoleRun> console;
  if (classroom.control) {
    auto started = ConsoleRun::start(s, classroom.control, recorder, [](const std::string& line) { log_line(line); });
    if (!started) {
      log_line("error: " + started.error());
      return 1;
    }
    console = started.take();
  }
  log_line(describe_limit(o, scenario ? &*scenario : nullptr));
  const Status frames = run_frames(**runtime, o, limit_s, t0, *classroom.station, s.sim.pathologies, console.get());
  if (!frames) log_line("error: " + frames.error());
  int exit_code =
      write_outputs(**runtime, o, seconds_between(t0, monotonic_ns()), frames.ok(), s.sim.pathologies, console.get());
  console.reset();                                         // no request reaches the class after its last frame
  if (!finish_session_recording(recorder)) exit_code = 1;  // --session-record: closed whole
  if (tracker_record_path(o.record_path) != o.record_path) {
    runtime->reset();  // the tracker closes its log first
    auto plus = finish_plus_recording(o.record_path, s.trackers());
    log_line(plus ? *plus : "error: " + plus.error());
    if (!plus) exit_code = 1;
  }
  return exit_code;
}

}  // namespace lungar::platform
