/// @file class_control.cpp
/// @brief Console requests into the class's events, shared as the next revision; the live view from the frames.
#include "platform/sync/class_control.h"

#include "platform/record/timeline_csv.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "config/base/clock.h"
#include "config/base/patient_names.h"
#include "drivers/classroom/shared_breathing.h"
#include "sim/breathing/breath_follower.h"
#include "sim/breathing/orientation.h"
#include "sim/breathing/pv_curve.h"
#include "sim/pathology/pathology.h"

namespace lungar::platform::sync {

namespace {

/// The instructor's breathing: the newest driver the console installed, on breathing time since t0.
class LiveBreathing final : public breath::BreathingClock {
 public:
  explicit LiveBreathing(std::shared_ptr<const ClassControl> control) : control_(std::move(control)) {}
  sim::BreathingSample at(std::int64_t now_ns) const override {
    return control_->driver().at(seconds_between(control_->t0_ns(), now_ns));
  }
  const sim::Pattern* pattern_at(std::int64_t now_ns) const override {
    return &control_->driver().pattern_at(seconds_between(control_->t0_ns(), now_ns));
  }
  void add_stats(nlohmann::json& stats) const override {
    stats["breathing_preset"] = std::string(sim::to_string(control_->driver().params().preset));
  }

 private:
  std::shared_ptr<const ClassControl> control_;
};

/// A followed breath the console may take over with the model's and give back (ClassControl::over_followed).
class OverFollowedBreathing final : public breath::BreathingClock {
 public:
  OverFollowedBreathing(std::unique_ptr<breath::BreathingClock> followed, std::shared_ptr<const ClassControl> control)
      : followed_(std::move(followed)), control_(std::move(control)) {}
  sim::BreathingSample at(std::int64_t now_ns) const override {
    const bool model = control_->breath_taken_over();
    sim::BreathingSample s =
        model ? control_->driver().at(seconds_between(control_->t0_ns(), now_ns)) : followed_->at(now_ns);
    // At a switch, the jump dV would make is carried as an offset that goes to zero at the handover rate.
    if (last_ns_ != 0 && model != model_) {
      offset_ml_ = last_dv_ml_ - s.dv_ml;
    } else if (last_ns_ != 0) {
      const double step = sim::kHandoverMlPerS * std::max(0.0, seconds_between(last_ns_, now_ns));
      offset_ml_ = offset_ml_ > 0 ? std::max(0.0, offset_ml_ - step) : std::min(0.0, offset_ml_ + step);
    }
    model_ = model;
    s.dv_ml += offset_ml_;
    s.v_ml += offset_ml_;
    last_dv_ml_ = s.dv_ml;
    last_ns_ = now_ns;
    return s;
  }
  const sim::Pattern* pattern_at(std::int64_t now_ns) const override {
    return control_->breath_taken_over() ? &control_->driver().pattern_at(seconds_between(control_->t0_ns(), now_ns))
                                         : followed_->pattern_at(now_ns);
  }
  void add_stats(nlohmann::json& stats) const override {
    followed_->add_stats(stats);
    stats["breath_taken_over"] = control_->breath_taken_over();
  }

 private:
  std::unique_ptr<breath::BreathingClock> followed_;
  std::shared_ptr<const ClassControl> control_;
  // The frame's thread only.
  mutable bool model_ = false;
  mutable double offset_ml_ = 0, last_dv_ml_ = 0;
  mutable std::int64_t last_ns_ = 0;
};

console::ControlReply refuse(int status, const std::string& line) { return {status, {{"error", line}}}; }

/// A request's number field: absent (nullopt in `out`), a finite number, or an error naming the field.
Status optional_number(const nlohmann::json& request, const char* key, std::optional<double>& out) {
  out.reset();
  if (!request.contains(key)) return ok();
  const nlohmann::json& v = request[key];
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    return fail(std::string(key) + ": expected a number, not " + v.dump());
  out = v.get<double>();
  return ok();
}

/// A request's string field, which must be there.
Status required_text(const nlohmann::json& request, const char* key, std::string& out) {
  if (!request.contains(key) || !request[key].is_string() || request[key].get<std::string>().empty())
    return fail(std::string(key) + ": expected a text");
  out = request[key].get<std::string>();
  return ok();
}

/// The transition a request asks for: over_s, (0, 600] s, or the default.
Status transition_of(const nlohmann::json& request, double& over_s) {
  std::optional<double> given;
  if (Status s = optional_number(request, "over_s", given); !s) return s;
  over_s = given.value_or(ClassControl::kDefaultOverS);
  if (over_s <= 0 || over_s > 600) return fail("over_s: expected a transition in seconds, above 0 and at most 600");
  return ok();
}

/// "pitch" and "roll" of a lung orientation, degrees: its long axis (+z) from the vertical, and the side tilt.
std::pair<double, double> tilt_deg(double w, double x, double y, double z) {
  const Eigen::Quaterniond q(w, x, y, z);
  const Eigen::Vector3d up = q * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d front = q * Eigen::Vector3d::UnitY();
  const double kDeg = 180.0 / M_PI;
  return {std::atan2(up.y(), up.z()) * kDeg, std::atan2(-front.x(), front.y()) * kDeg};
}

/// The named posture whose gravity (in the lung's frame) is within 30 degrees of `g`, or "between".
std::string posture_of(const Eigen::Vector3d& g) {
  for (const Pose pose : sim::kAllPoses) {
    const Eigen::Vector3d gp = sim::pose_rotation(pose).inverse() * Eigen::Vector3d(0, 0, -1);
    if (g.normalized().dot(gp) > std::cos(30.0 * M_PI / 180.0)) return std::string(sim::to_string(pose));
  }
  return "between";
}

}  // namespace

ClassControl::ClassControl(ClassStart start, std::shared_ptr<classroom::ClassroomStation> station,
                           std::function<void(const std::string&)> log, sim::BreathingDriver driver)
    : start_(std::move(start)), station_(std::move(station)), log_(std::move(log)) {
  drivers_.push_back(std::make_unique<const sim::BreathingDriver>(std::move(driver)));
  driver_.store(drivers_.back().get(), std::memory_order_release);
  if (start_.posture) {
    tracks_.push_back(std::make_unique<const sim::OrientationTrack>(*start_.posture));
    track_.store(tracks_.back().get(), std::memory_order_release);
  }
  breath_events_ = start_.events;
  lungs_ = start_.lungs;
  log_lines_.push_back({0.0, "class start", "", sim::describe(lungs_)});
}

Result<std::shared_ptr<ClassControl>> ClassControl::create(ClassStart start,
                                                           std::shared_ptr<classroom::ClassroomStation> station,
                                                           std::function<void(const std::string&)> log) {
  if (!station || station->instructor() == nullptr)
    return fail("console: the console runs on the classroom's instructor (--sync instructor)");
  auto driver = classroom::SharedBreathing::build(start.start, start.events);
  if (!driver) return driver.with_context("console: ");
  return std::shared_ptr<ClassControl>(
      new ClassControl(std::move(start), std::move(station), std::move(log), driver.take()));
}

std::unique_ptr<breath::BreathingClock> ClassControl::breathing_clock() const {
  return std::make_unique<LiveBreathing>(shared_from_this());
}

std::unique_ptr<breath::BreathingClock> ClassControl::over_followed(
    std::unique_ptr<breath::BreathingClock> followed) const {
  return std::make_unique<OverFollowedBreathing>(std::move(followed), shared_from_this());
}

double ClassControl::now_s() const { return seconds_between(start_.t0_ns, monotonic_ns()); }

void ClassControl::on_frame(const FrameState& s) {
  const Eigen::Quaterniond& q = s.lung_in_world;
  const Eigen::Vector3d& g = s.gravity_lung;
  samples_.push({s.breath.t_s, s.breath.dv_ml, s.lung_dv_ml[0], s.lung_dv_ml[1], s.breath.phase, q.w(), q.x(), q.y(),
                 q.z(), g.x(), g.y(), g.z()});
}

bool ClassControl::lungs_since(std::uint64_t& version, sim::PathologyTimeline& out) const {
  const std::uint64_t now = lungs_version_.load(std::memory_order_acquire);
  if (now <= version) return false;  // the frame's usual answer: no lock, no copy
  std::lock_guard lock(mutex_);
  out = lungs_;
  version = lungs_version_.load(std::memory_order_relaxed);
  return true;
}

Eigen::Quaterniond ClassControl::orientation_at(double t_s) const {
  const sim::OrientationTrack* track = track_.load(std::memory_order_acquire);
  return track != nullptr ? track->at(t_s) : Eigen::Quaterniond::Identity();
}

bool ClassControl::breath_time(std::int64_t now_ns, double& t_s) const {
  t_s = seconds_between(start_.t0_ns, now_ns);
  return true;
}

console::ControlReply ClassControl::control(const console::ConsoleUser& user, const nlohmann::json& request) {
  if (!request.is_object() || !request.contains("action") || !request["action"].is_string())
    return refuse(400, "expected a JSON object with an \"action\"");
  const std::string action = request["action"].get<std::string>();
  if (action.rfind("breath_", 0) == 0) return breath_request(user, action, request);
  if (action.rfind("pathology_", 0) == 0) return pathology_request(user, action, request);
  if (action == "posture_set") return posture_request(user, request);
  if (action == "display_set") return display_request(user, request);
  if (action.rfind("scenario_", 0) == 0) return scenario_request(user, action, request);
  if (action == "marker") {
    std::string text;
    if (Status s = required_text(request, "text", text); !s) return refuse(400, "marker: " + s.error());
    if (text.size() > 500) return refuse(400, "marker: text: expected at most 500 characters");
    const double t = now_s();
    note({t, "marker", user.name, text});
    return {200, {{"t_s", t}}};
  }
  return refuse(400,
                "action: expected one of breath_pause, breath_resume, breath_set, breath_follow, pathology_add, "
                "pathology_remove, pathology_severity, posture_set, display_set, scenario_load, scenario_start, "
                "scenario_pause, scenario_jump, scenario_stop, marker; not '" +
                    action + "'");
}

console::ControlReply ClassControl::breath_request(const console::ConsoleUser& user, const std::string& action,
                                                   const nlohmann::json& request) {
  if (action == "breath_follow") {
    if (start_.followed.empty())
      return refuse(409, "breath_follow: the class breathes the model; it follows no patient's own breath");
    if (!breath_taken_over()) return refuse(409, "breath_follow: the class follows " + start_.followed + " already");
    taken_over_.store(false, std::memory_order_release);
    note({now_s(), "breath follow", user.name, "back to " + start_.followed});
    return {200, {{"t_s", now_s()}}};
  }
  const double t = now_s() + kLeadS;
  sim::Event event;
  std::string text;
  if (action == "breath_pause" || action == "breath_resume") {
    const bool pause = action == "breath_pause";
    if (pause == paused_)
      return refuse(409, action + ": the breath is " + (paused_ ? "paused" : "not paused") + " already");
    event = sim::Event::of(t, pause ? sim::EventKind::HoldStart : sim::EventKind::HoldEnd);
    text = pause ? "breath hold" : "breathing again";
  } else if (action == "breath_set") {
    sim::PatternChange change;
    std::optional<double> rate, tidal, ie;
    for (auto [key, out] : {std::pair{"rate_bpm", &rate}, {"tidal_volume_ml", &tidal}, {"ie_ratio", &ie}})
      if (Status s = optional_number(request, key, *out); !s) return refuse(400, action + ": " + s.error());
    change.rate_bpm = rate;
    change.tidal_volume_ml = tidal;
    change.ie_ratio = ie;
    if (request.contains("preset")) {
      const auto preset =
          request["preset"].is_string() ? kPresetNames.parse(request["preset"].get<std::string>()) : std::nullopt;
      if (!preset) return refuse(400, action + ": preset: expected " + kPresetNames.expected());
      change.preset = *preset;
    }
    if (!change.preset && !rate && !tidal && !ie)
      return refuse(400, action + ": expected at least one of preset, rate_bpm, tidal_volume_ml, ie_ratio");
    event = sim::Event::set(t, change);
    char line[160];
    std::snprintf(line, sizeof line, "%s%s%s", change.preset ? kPresetNames.name(*change.preset) : "",
                  rate ? (" " + std::to_string(static_cast<int>(std::lround(*rate))) + "/min").c_str() : "",
                  tidal ? (" " + std::to_string(static_cast<int>(std::lround(*tidal))) + " mL").c_str() : "");
    text = line;
    if (ie) text += " I:E " + std::to_string(*ie).substr(0, 4);
  } else {
    return refuse(400,
                  "action: expected breath_pause, breath_resume, breath_set or breath_follow; not '" + action + "'");
  }
  ClassSteps manual = manual_;
  manual.breath.push_back(event);
  if (Status s = commit(manual, scenario_.issued); !s) return refuse(400, action + ": " + s.error());
  manual_ = std::move(manual);
  // A followed breath: the console's model takes it over on this station until breath_follow gives it back. The
  // trainees draw what the instructor draws (its heartbeats carry each frame's dV), handover included.
  if (!modelled()) {
    taken_over_.store(true, std::memory_order_release);
    text += "; the console's breath in place of " + start_.followed;
  }
  if (action != "breath_set") paused_ = action == "breath_pause";
  note({t,
        action == "breath_pause"    ? "breath pause"
        : action == "breath_resume" ? "breath resume"
                                    : "breath set",
        user.name, text});
  return {200, {{"t_s", t}}};
}

console::ControlReply ClassControl::posture_request(const console::ConsoleUser& user, const nlohmann::json& request) {
  const sim::OrientationTrack* now = track_.load(std::memory_order_acquire);
  if (now == nullptr)
    return refuse(409,
                  "posture_set: a tracker measures the patient's posture; the console turns a simulated patient only "
                  "(an instructor on the mock tracker)");
  std::string name;
  if (Status s = required_text(request, "posture", name); !s) return refuse(400, "posture_set: " + s.error());
  const std::optional<Pose> pose = sim::pose_from_name(name);
  if (!pose) return refuse(400, "posture_set: posture: expected " + kPoseNames.expected() + "; not '" + name + "'");
  double over_s = 0;
  if (Status s = transition_of(request, over_s); !s) return refuse(400, "posture_set: " + s.error());
  // After a turn under way (the patient is not wrenched from the middle of one), and never across one a scenario
  // has coming: that turn would then start from wherever this one had brought the patient.
  sim::Turn turn{now_s() + kLeadS, over_s, sim::pose_rotation(*pose)};
  for (const sim::Turn& t : now->turns())
    if (t.t_s <= turn.t_s && turn.t_s < t.t_s + t.duration_s) turn.t_s = t.t_s + t.duration_s;
  for (const sim::Turn& t : now->turns()) {
    if (t.t_s >= turn.t_s && t.t_s < turn.t_s + turn.duration_s) {
      char line[160];
      std::snprintf(line, sizeof line,
                    "posture_set: the scenario turns the patient at %.1f s; a turn over %.1f s "
                    "from %.1f s would cross it",
                    t.t_s, over_s, turn.t_s);
      return refuse(409, line);
    }
  }
  ClassSteps manual = manual_;
  manual.turns.push_back(turn);
  if (Status s = commit(manual, scenario_.issued); !s) return refuse(400, "posture_set: " + s.error());
  manual_ = std::move(manual);
  char over[48];
  std::snprintf(over, sizeof over, " over %.1f s", over_s);
  note({turn.t_s, "posture", user.name, std::string(sim::to_string(*pose)) + over});
  return {200, {{"t_s", turn.t_s}}};
}

console::ControlReply ClassControl::display_request(const console::ConsoleUser& user, const nlohmann::json& request) {
  if (!request.contains("ventilation_map") || !request["ventilation_map"].is_boolean())
    return refuse(400, "display_set: ventilation_map: expected true or false");
  const bool on = request["ventilation_map"].get<bool>();
  // Shared like any change, so a trainee joining later shows what the others show.
  const std::optional<bool> before = ventilation_map_;
  ventilation_map_ = on;
  if (Status s = commit(manual_, scenario_.issued); !s) {
    ventilation_map_ = before;
    return refuse(400, "display_set: " + s.error());
  }
  shown_map_.set(on);
  note({now_s(), "display", user.name, on ? "ventilation map on" : "ventilation map off"});
  return {200, {{"t_s", now_s()}}};
}

bool ClassControl::ventilation_map_since(std::uint64_t& version, bool& on) const {
  return shown_map_.since(version, on);
}

console::ControlReply ClassControl::pathology_request(const console::ConsoleUser& user, const std::string& action,
                                                      const nlohmann::json& request) {
  sim::PathologyEvent event;
  if (Status s = transition_of(request, event.over_s); !s) return refuse(400, action + ": " + s.error());
  std::string spec;
  if (Status s = required_text(request, "spec", spec); !s) return refuse(400, action + ": " + s.error());
  if (action == "pathology_add") {
    event.add = spec;
  } else if (action == "pathology_remove") {
    event.remove = spec;
  } else if (action == "pathology_severity") {
    event.remove = spec;
    if (Status s = required_text(request, "to", event.add); !s) return refuse(400, action + ": " + s.error());
  } else {
    return refuse(400, "action: expected pathology_add, pathology_remove or pathology_severity; not '" + action + "'");
  }
  if (!event.add.empty()) {
    auto p = sim::parse_pathology(event.add);
    if (!p) return refuse(400, action + ": " + p.error());
    if (!(*p)->model().may_change_in_a_run())
      return refuse(400, action + ": '" + std::string((*p)->model().name()) +
                             "' cannot come or go during a class (it would switch at once); start the class with it");
  }
  event.at_s = now_s() + kLeadS;
  ClassSteps manual = manual_;
  manual.lungs.push_back(event);
  if (Status s = commit(manual, scenario_.issued); !s) return refuse(400, action + ": " + s.error());
  manual_ = std::move(manual);
  char over[48];
  std::snprintf(over, sizeof over, " over %.1f s", event.over_s);
  const std::string what = event.remove.empty() ? event.add
                           : event.add.empty()  ? event.remove
                                                : event.remove + " -> " + event.add;
  note({event.at_s,
        action == "pathology_add"      ? "pathology add"
        : action == "pathology_remove" ? "pathology remove"
                                       : "pathology severity",
        user.name, what + over});
  return {200, {{"t_s", event.at_s}}};
}

namespace {

/// `a`, `b` and `c` together in time order (stable: at one time, `a`'s first, then `b`'s).
template <class T, class Time>
std::vector<T> merged(const std::vector<T>& a, const std::vector<T>& b, const std::vector<T>& c, Time time) {
  std::vector<T> out = a;
  out.insert(out.end(), b.begin(), b.end());
  out.insert(out.end(), c.begin(), c.end());
  std::stable_sort(out.begin(), out.end(), [&](const T& x, const T& y) { return time(x) < time(y); });
  return out;
}

}  // namespace

Status ClassControl::commit(const ClassSteps& manual, const ClassSteps& scenario) {
  const std::vector<sim::Event> events =
      merged(start_.events, manual.breath, scenario.breath, [](const sim::Event& e) { return e.t_s; });
  sim::PathologyTimeline lungs{start_.lungs.start, merged(start_.lungs.events, manual.lungs, scenario.lungs,
                                                          [](const sim::PathologyEvent& e) { return e.at_s; })};
  // The breath a trainee builds from the whole list: the instructor's is built the same way.
  auto built = classroom::SharedBreathing::build(start_.start, events);
  if (!built) return Error{built.error()};
  std::optional<sim::OrientationTrack> track;
  if (start_.posture) {
    auto made = sim::OrientationTrack::create(
        start_.posture->start(),
        merged(start_.posture->turns(), manual.turns, scenario.turns, [](const sim::Turn& t) { return t.t_s; }));
    if (!made) return Error{made.error()};
    track.emplace(made.take());
  }
  sim::PathologyTimeline now;
  {
    std::lock_guard lock(mutex_);
    now = lungs_;
  }
  const bool lungs_changed = !(lungs == now);
  if (lungs_changed) {
    if (Status s = sim::check_timeline(lungs); !s) return s;
    if (can_draw) {  // the instructor draws what it shares: what it cannot, no trainee is sent
      if (Status s = can_draw(lungs); !s) return s;
    }
  }
  if (Status shared = station_->instructor()->reshare(start_.start, events, lungs, ventilation_map_); !shared)
    return shared;
  {
    std::lock_guard lock(mutex_);
    breath_events_ = events;
    lungs_ = lungs;
  }
  drivers_.push_back(std::make_unique<const sim::BreathingDriver>(built.take()));
  driver_.store(drivers_.back().get(), std::memory_order_release);
  if (track) {
    tracks_.push_back(std::make_unique<const sim::OrientationTrack>(std::move(*track)));
    track_.store(tracks_.back().get(), std::memory_order_release);
  }
  if (lungs_changed) {
    lungs_version_.fetch_add(1, std::memory_order_release);
    if (on_timeline) on_timeline(lungs);
  }
  return ok();
}

ClassSteps ClassControl::begun_by(double t_s) const {
  ClassSteps kept;
  for (const sim::Event& e : scenario_.issued.breath)
    if (e.t_s <= t_s) kept.breath.push_back(e);
  for (const sim::PathologyEvent& e : scenario_.issued.lungs)
    if (e.at_s <= t_s) kept.lungs.push_back(e);
  for (const sim::Turn& turn : scenario_.issued.turns)
    if (turn.t_s <= t_s) kept.turns.push_back(turn);
  return kept;
}

ClassSteps ClassControl::scenario_steps(double at_s, double t_s, bool running, double& offset_s) const {
  const ClassScenario& sc = *scenario_.loaded;
  const ScenarioState target = sc.state_before(at_s);
  ClassSteps steps;
  // The breath: one change to every parameter the scenario has by then (a followed breath is the patient's own).
  if (modelled()) {
    sim::PatternChange c;
    c.preset = target.params.preset;
    c.rate_bpm = target.params.rate_bpm;
    c.ie_ratio = target.params.ie_ratio;
    c.tidal_volume_ml = target.params.tidal_volume_ml;
    c.mode = target.params.mode;
    c.ventilator_tau_s = target.params.ventilator_tau_s;
    c.peep_cmh2o = target.params.peep_cmh2o;
    steps.breath.push_back(sim::Event::set(t_s, c));
  }
  // The pathologies: what the class has then and the scenario has not goes, what the scenario has comes.
  const std::vector<std::string> present = present_at(t_s);
  for (const std::string& p : present)
    if (std::find(target.pathologies.begin(), target.pathologies.end(), p) == target.pathologies.end())
      steps.lungs.push_back({t_s, kSettleS, "", p});
  for (const std::string& p : target.pathologies)
    if (std::find(present.begin(), present.end(), p) == present.end()) steps.lungs.push_back({t_s, kSettleS, p, ""});
  // The posture, when simulated: after any turn under way.
  double settle_at = t_s;
  if (const sim::OrientationTrack* track = track_.load(std::memory_order_acquire)) {
    for (const sim::Turn& turn : track->turns())
      if (turn.t_s <= settle_at && settle_at < turn.t_s + turn.duration_s) settle_at = turn.t_s + turn.duration_s;
    if (track->at(settle_at).angularDistance(target.orientation) > 1e-3)
      steps.turns.push_back({settle_at, kSettleS, target.orientation});
  }
  offset_s = settle_at + kSettleS - at_s;
  if (!running) return steps;
  ClassSteps after = sc.steps_from(at_s, offset_s);
  if (!modelled()) after.breath.clear();
  if (!start_.posture) after.turns.clear();
  steps.breath.insert(steps.breath.end(), after.breath.begin(), after.breath.end());
  steps.lungs.insert(steps.lungs.end(), after.lungs.begin(), after.lungs.end());
  steps.turns.insert(steps.turns.end(), after.turns.begin(), after.turns.end());
  return steps;
}

console::ControlReply ClassControl::scenario_request(const console::ConsoleUser& user, const std::string& action,
                                                     const nlohmann::json& request) {
  const double t = now_s() + kLeadS;
  if (action == "scenario_load") return scenario_load(user, request, t);
  if (action != "scenario_start" && action != "scenario_jump" && action != "scenario_pause" &&
      action != "scenario_stop")
    return refuse(400,
                  "action: expected scenario_load, scenario_start, scenario_pause, scenario_jump or "
                  "scenario_stop; not '" +
                      action + "'");
  if (!scenario_.loaded) return refuse(409, action + ": no scenario is loaded; load one first");
  if (action == "scenario_start" || action == "scenario_jump") return scenario_go(user, action, request, t);
  return scenario_halt(user, action, t);
}

console::ControlReply ClassControl::scenario_load(const console::ConsoleUser& user, const nlohmann::json& request,
                                                  double t) {
  ScenarioRun& run = scenario_;
  std::string name;
  if (Status s = required_text(request, "name", name); !s) return refuse(400, "scenario_load: " + s.error());
  const auto found =
      std::find_if(scenarios.begin(), scenarios.end(), [&](const ClassScenario& c) { return c.name() == name; });
  if (found == scenarios.end()) {
    std::string names;
    for (const ClassScenario& c : scenarios) names += (names.empty() ? "" : ", ") + c.name();
    return refuse(400, "scenario_load: name: expected one of this station's scenarios (" +
                           (names.empty() ? std::string("none") : names) + "); not '" + name + "'");
  }
  if (run.phase == "running" || run.phase == "paused")
    return refuse(409, "scenario_load: '" + run.loaded->name() + "' is " + run.phase + "; stop it first");
  run = ScenarioRun{*found, "ready", 0, 0, {}};
  note({t, "scenario load", user.name, found->name()});
  return {200, {{"t_s", t}}};
}

console::ControlReply ClassControl::scenario_go(const console::ConsoleUser& user, const std::string& action,
                                                const nlohmann::json& request, double t) {
  ScenarioRun& run = scenario_;
  const std::string& name = run.loaded->name();
  double at_s = run.phase == "running" ? t - run.offset_s : run.position_s;
  if (action == "scenario_jump") {
    if (!request.contains("cue") || !request["cue"].is_number_integer())
      return refuse(400, action + ": cue: expected the number of one of the scenario's events, from 0");
    const auto cue = request["cue"].get<long long>();
    if (cue < 0 || cue >= static_cast<long long>(run.loaded->cues().size()))
      return refuse(400, action + ": cue: expected 0 to " + std::to_string(run.loaded->cues().size() - 1) + "; not " +
                             std::to_string(cue));
    at_s = run.loaded->cues()[static_cast<std::size_t>(cue)].t_s;
  } else if (run.phase == "running") {
    return refuse(409, action + ": '" + name + "' is running already");
  } else if (run.phase == "stopped") {
    at_s = 0;
  }
  const bool running = action == "scenario_start" || run.phase == "running";
  double offset_s = 0;
  ClassSteps issued = begun_by(t);
  const ClassSteps added = scenario_steps(at_s, t, running, offset_s);
  issued.breath.insert(issued.breath.end(), added.breath.begin(), added.breath.end());
  issued.lungs.insert(issued.lungs.end(), added.lungs.begin(), added.lungs.end());
  issued.turns.insert(issued.turns.end(), added.turns.begin(), added.turns.end());
  if (Status s = commit(manual_, issued); !s) return refuse(400, action + ": '" + name + "': " + s.error());
  run.issued = std::move(issued);
  run.offset_s = offset_s;
  run.position_s = at_s;
  run.phase = running ? "running" : run.phase;
  char text[200];
  std::snprintf(text, sizeof text, "%s from %.1f s", name.c_str(), at_s);
  // What the scenario cannot change here, said where the trainer reads it.
  std::string left_out;
  if (!start_.posture) left_out += "its turns (a tracker measures the patient)";
  if (!modelled())
    left_out +=
        (left_out.empty() ? "" : " and ") + std::string("its breathing (followed from ") + start_.followed + ")";
  note({t, action == "scenario_start" ? "scenario start" : "scenario jump", user.name,
        text + (left_out.empty() ? "" : "; left out: " + left_out)});
  return {200, {{"t_s", t}, {"scenario_s", at_s}}};
}

console::ControlReply ClassControl::scenario_halt(const console::ConsoleUser& user, const std::string& action,
                                                  double t) {
  ScenarioRun& run = scenario_;
  const std::string& name = run.loaded->name();
  const bool stop = action == "scenario_stop";
  if (!stop && run.phase != "running") return refuse(409, action + ": '" + name + "' is not running");
  if (stop && run.phase != "running" && run.phase != "paused")
    return refuse(409, action + ": '" + name + "' is not running or paused");
  ClassSteps issued = begun_by(t);
  if (Status s = commit(manual_, issued); !s) return refuse(400, action + ": '" + name + "': " + s.error());
  const double at_s = run.phase == "running" ? t - run.offset_s : run.position_s;
  run.issued = std::move(issued);
  run.position_s = stop ? 0 : at_s;
  run.phase = stop ? "stopped" : "paused";
  char text[200];
  std::snprintf(text, sizeof text, "%s at %.1f s", name.c_str(), at_s);
  note({t, stop ? "scenario stop" : "scenario pause", user.name, text});
  return {200, {{"t_s", t}, {"scenario_s", at_s}}};
}

nlohmann::json ClassControl::scenario_json(double t_s) const {
  nlohmann::json available = nlohmann::json::array();
  for (const ClassScenario& c : scenarios)
    available.push_back({{"name", c.name()}, {"description", c.description()}, {"duration_s", c.duration_s()}});
  nlohmann::json j = {{"available", std::move(available)}};
  const ScenarioRun& run = scenario_;
  if (!run.loaded) return j;
  const double at_s = run.phase == "running" ? t_s - run.offset_s : run.position_s;
  nlohmann::json cues = nlohmann::json::array();
  for (const ScenarioCue& c : run.loaded->cues()) cues.push_back({{"t_s", c.t_s}, {"kind", c.kind}, {"text", c.text}});
  j["loaded"] = {{"name", run.loaded->name()},
                 {"phase", run.phase == "running" && at_s > run.loaded->duration_s() ? "ended" : run.phase},
                 {"t_s", at_s},
                 {"duration_s", run.loaded->duration_s()},
                 {"cues", std::move(cues)}};
  return j;
}

void ClassControl::note(ClassEvent event) {
  if (log_) log_("console: " + event.kind + (event.user.empty() ? "" : " by " + event.user) + ": " + event.text);
  if (on_event) on_event(event);
  std::lock_guard lock(mutex_);
  log_lines_.push_back(std::move(event));
}

void ClassControl::refused(int status, const std::string& line) {
  refused_.fetch_add(1, std::memory_order_relaxed);
  note({now_s(), "refused", "", std::to_string(status) + ": " + line});
}

std::vector<ClassEvent> ClassControl::events() const {
  std::lock_guard lock(mutex_);
  return log_lines_;
}

std::vector<std::string> ClassControl::present_at(double t_s) const {
  std::lock_guard lock(mutex_);
  std::size_t begun = 0;
  while (begun < lungs_.events.size() && t_s > lungs_.events[begun].at_s) ++begun;
  std::vector<std::string> present = sim::present_after(lungs_, begun);
  return present;
}

std::string ClassControl::changing_at(double t_s) const {
  std::lock_guard lock(mutex_);
  std::string changing;
  for (const sim::PathologyEvent& e : lungs_.events) {
    if (t_s < e.at_s || t_s >= e.at_s + e.over_s) continue;
    changing += (changing.empty() ? "" : ", ") + (e.add.empty() ? e.remove + " (going)" : e.add + " (coming)");
  }
  return changing;
}

std::string ClassControl::snapshot_json() {
  const double t = now_s();
  samples_.drain([&](const FrameSample& s) { recent_.push_back(s); });
  // Only the last kSamplesS: the ring also holds what waited in it while nobody watched (a full ring drops the
  // newest), which a page opened now would draw as an old stub before a gap.
  while (!recent_.empty() && recent_.front().t_s < t - kSamplesS) recent_.pop_front();
  nlohmann::json j;
  j["station"] = station_->instructor()->station();
  j["t_s"] = t;
  const classroom::SyncReport report = station_->report();
  j["secure"] = report.secure;
  j["refused"] = refused_.load(std::memory_order_relaxed);
  const sim::Pattern& pattern = driver().pattern_at(t);
  j["breath"] = {{"state", pattern.held     ? "paused"
                           : pattern.apnoea ? "apnoea"
                                            : "breathing"},
                 {"source", start_.followed.empty() ? "model"
                            : breath_taken_over()   ? "model, in place of " + start_.followed
                                                    : start_.followed},
                 {"followed", start_.followed},
                 {"taken_over", breath_taken_over()},
                 {"preset", std::string(sim::to_string(pattern.params.preset))},
                 {"rate_bpm", pattern.params.rate_bpm},
                 {"tidal_volume_ml", pattern.params.tidal_volume_ml},
                 {"ie_ratio", pattern.params.ie_ratio}};
  nlohmann::json samples = nlohmann::json::array();
  for (const FrameSample& s : recent_) {
    samples.push_back({s.t_s, s.dv_ml, std::isfinite(s.left_ml) ? nlohmann::json(s.left_ml) : nlohmann::json(),
                       std::isfinite(s.right_ml) ? nlohmann::json(s.right_ml) : nlohmann::json()});
  }
  j["samples"] = std::move(samples);
  if (!recent_.empty()) {
    const FrameSample& s = recent_.back();
    const auto [pitch, roll] = tilt_deg(s.w, s.x, s.y, s.z);
    j["orientation"] = {{"posture", posture_of({s.gx, s.gy, s.gz})},
                        {"wxyz", {s.w, s.x, s.y, s.z}},
                        {"pitch_deg", pitch},
                        {"roll_deg", roll}};
  }
  nlohmann::json postures = nlohmann::json::array();
  for (const Pose pose : sim::kAllPoses) postures.push_back(std::string(sim::to_string(pose)));
  j["posture"] = {{"simulated", track_.load(std::memory_order_acquire) != nullptr}, {"choices", std::move(postures)}};
  j["display"] = {{"ventilation_map", ventilation_map_ ? nlohmann::json(*ventilation_map_) : nlohmann::json()}};
  j["scenario"] = scenario_json(t);
  j["pathologies"] = present_at(t);
  j["pathologies_changing"] = changing_at(t);
  j["stations"] = stations_json();
  nlohmann::json events = nlohmann::json::array();
  for (const ClassEvent& e : this->events())
    events.push_back({{"t_s", e.t_s}, {"kind", e.kind}, {"user", e.user}, {"text", e.text}});
  j["events"] = std::move(events);
  nlohmann::json presets = nlohmann::json::array();
  for (const auto& [preset, name] : kPresetNames.entries) presets.push_back(name);
  j["presets"] = std::move(presets);
  nlohmann::json forms = nlohmann::json::array();
  for (const sim::PathologyModel* m : sim::pathology_models())
    if (m->may_change_in_a_run()) forms.push_back(std::string(m->syntax()));
  j["pathology_forms"] = std::move(forms);
  return j.dump();
}

nlohmann::json ClassControl::stations_json() const {
  nlohmann::json stations = nlohmann::json::array();
  for (const classroom::StationStatus& st : station_->instructor()->stations()) {
    stations.push_back({{"name", st.name},
                        {"state", st.state},
                        {"breath_offset_ms", st.breath_offset_ms},
                        {"pose_age_ms", st.pose_age_ms},
                        {"fps", st.fps},
                        {"secure", st.secure},
                        {"heard_s_ago", st.heard_s_ago}});
  }
  return stations;
}

std::string ClassControl::timeline_csv() {
  std::string out = "t_s,kind,user,text\n";
  char t[32];
  for (const ClassEvent& e : events()) {
    std::snprintf(t, sizeof t, "%.3f", e.t_s);
    out += std::string(t) + "," + record::csv_field(e.kind) + "," + record::csv_field(e.user) + "," +
           record::csv_field(e.text) + "\n";
  }
  return out;
}

}  // namespace lungar::platform::sync
