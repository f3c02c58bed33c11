/// @file class_control.h
/// @brief The instructor running the class live from its console: a request (pause the breath, add a tension
///        pneumothorax over 5 s, a marker) becomes an event of the class, timed a little ahead of now, on the
///        instructor's own breathing and lungs and, as the next revision of what the instructor shares, on every
///        trainee's. It also gives the console its live view, from what each frame hands it.
/// @ingroup platform
///
/// Threads. Requests and views come on the console server's thread; the frame only reads: the breathing through
/// an atomic pointer to the newest driver (drivers are kept for the run, so a pointer read is never left
/// dangling), the lungs through a version number it checks before it copies the timeline (ClassroomCourse builds
/// the course off the frame), and its samples go the other way through a ring. The frame never waits for the
/// console.
///
/// Why events and not a live setting: a trainee computes the breath itself from the shared start and events
/// (classroom/shared_breathing.h), so a change that is an event reaches it as what it already knows how to
/// follow, and a trainee joining later draws the same course from the start.
#pragma once

#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "config/base/spsc_ring.h"
#include "config/base/versioned_flag.h"
#include "drivers/breath/source/breathing_clock.h"
#include "drivers/classroom/classroom_station.h"
#include "platform/console/console_handler.h"
#include "platform/runtime/display_requests.h"
#include "platform/runtime/frame_listener.h"
#include "platform/runtime/scenario_patient.h"
#include "platform/sync/class_scenario.h"
#include "platform/sync/classroom_course.h"
#include "sim/breathing/driver.h"
#include "sim/breathing/event.h"
#include "sim/breathing/orientation.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::platform::sync {

/// The class as the instructor started it: what it shared.
struct ClassStart {
  sim::BreathingParams start;
  std::vector<sim::Event> events;
  sim::PathologyTimeline lungs;
  std::int64_t t0_ns = 0;  ///< breathing time 0 (monotonic)
  /// The breath's source when it is the patient's own, followed ("trace", "marker"...): the console cannot
  /// change that breath; empty: the model, which it can.
  std::string followed;
  /// The patient's orientation when it is simulated (the mock tracker: the start pose and any scripted turns),
  /// which the console may turn; empty: a tracker measures the patient, and no console turns a real one.
  std::optional<sim::OrientationTrack> posture;
};

/// One line of the class's timeline: what happened, when (breathing time) and who did it.
struct ClassEvent {
  double t_s = 0;
  std::string kind;  ///< "pathology add", "breath pause", "marker", "refused"...
  std::string user;  ///< the console login; empty for the class itself
  std::string text;
};

class ClassControl final : public console::ConsoleHandler,
                           public TimelineFeed,
                           public FrameListener,
                           public PatientTrack,
                           public DisplayRequests,
                           public std::enable_shared_from_this<ClassControl> {
 public:
  /// How far ahead of the request a change is timed: the trainees have it before it is due (one loopback or LAN
  /// round of DDS is milliseconds), so no station jumps to catch up.
  static constexpr double kLeadS = 0.1;
  /// A transition time the console gives when the request gives none, s.
  static constexpr double kDefaultOverS = 5.0;
  /// How long a scenario's start or a jump takes to bring the class to where the scenario stands (its breath,
  /// pathologies and posture), before the scenario's own steps go on.
  static constexpr double kSettleS = 2.0;
  /// The console's plot: each frame's sample of the last this many seconds.
  static constexpr double kSamplesS = 0.5;

  /// `station`: the instructor's (its Instructor shares each change). The start must build a breathing driver.
  static Result<std::shared_ptr<ClassControl>> create(ClassStart start,
                                                      std::shared_ptr<classroom::ClassroomStation> station,
                                                      std::function<void(const std::string&)> log);

  /// The instructor's own breathing clock, which follows every change the console makes (the model's).
  std::unique_ptr<breath::BreathingClock> breathing_clock() const;
  /// The instructor's breathing when it follows the patient's own (`followed`: a trace, a chest marker): the
  /// followed breath, until the console takes it over with the model's (any breath request), and again once the
  /// console gives it back (breath_follow); each switch goes over at sim::kHandoverMlPerS.
  std::unique_ptr<breath::BreathingClock> over_followed(std::unique_ptr<breath::BreathingClock> followed) const;
  /// Whether the console has taken a followed breath over (frame and console threads).
  bool breath_taken_over() const { return taken_over_.load(std::memory_order_acquire); }

  /// Whether this station can draw a timeline (ClassroomCourse builds it from the loaded lungs; a consolidation
  /// changes the lungs' response, which only the loaded asset has); set before the console starts. Unset: any
  /// timeline that passes sim::check_timeline.
  std::function<Status(const sim::PathologyTimeline&)> can_draw;
  /// Each event of the class as it is made (for the session record); set before the console starts.
  std::function<void(const ClassEvent&)> on_event;
  /// The pathology timeline after each change (for the session record).
  std::function<void(const sim::PathologyTimeline&)> on_timeline;
  /// The station's scenarios the console may load (by name); set before the console starts.
  std::vector<ClassScenario> scenarios;

  // FrameListener: the frame's sample for the live view. Allocates nothing.
  void on_frame(const FrameState& s) override;

  // TimelineFeed: the instructor's own lungs follow the console's pathologies.
  bool lungs_since(std::uint64_t& version, sim::PathologyTimeline& out) const override;
  bool breath_time(std::int64_t now_ns, double& t_s) const override;

  // PatientTrack: the simulated patient as the console last turned it (ScenarioPatient reads it each frame).
  Eigen::Quaterniond orientation_at(double t_s) const override;
  std::string turned_by() const override { return "the instructor's console"; }

  // DisplayRequests: the instructor's own display shows what the console asks of every station.
  bool ventilation_map_since(std::uint64_t& version, bool& on) const override;

  // ConsoleHandler.
  std::string snapshot_json() override;
  console::ControlReply control(const console::ConsoleUser& user, const nlohmann::json& request) override;
  std::string timeline_csv() override;
  void refused(int status, const std::string& line) override;

  /// Each trainee as the instructor last heard it (the live view's `stations`, and the record's).
  nlohmann::json stations_json() const;
  /// The class's events so far (for tests and the record).
  std::vector<ClassEvent> events() const;
  /// The breathing driver in force now (frame and console threads).
  const sim::BreathingDriver& driver() const { return *driver_.load(std::memory_order_acquire); }
  std::int64_t t0_ns() const { return start_.t0_ns; }

 private:
  struct FrameSample {
    double t_s, dv_ml, left_ml, right_ml;
    sim::BreathPhase phase;
    double w, x, y, z;  ///< the lung's orientation in the world
    double gx, gy, gz;  ///< gravity in the lung's frame: what the posture is
  };
  ClassControl(ClassStart start, std::shared_ptr<classroom::ClassroomStation> station,
               std::function<void(const std::string&)> log, sim::BreathingDriver driver);

  /// Breathing time now (s), the time a change is timed from.
  double now_s() const;
  console::ControlReply breath_request(const console::ConsoleUser& user, const std::string& action,
                                       const nlohmann::json& request);
  /// posture_set: the simulated patient turns to a named posture over over_s, after any turn under way.
  console::ControlReply posture_request(const console::ConsoleUser& user, const nlohmann::json& request);
  /// display_set: the ventilation map on or off on every station's display.
  console::ControlReply display_request(const console::ConsoleUser& user, const nlohmann::json& request);
  console::ControlReply pathology_request(const console::ConsoleUser& user, const std::string& action,
                                          const nlohmann::json& request);
  /// The class as the start, the console's own steps and the scenario's, each list in time order: checked whole
  /// (the breath builds, the pathologies' course is one this station draws, the turns do not cross), shared as
  /// the next revision, then installed here. The error leaves the class as it was.
  Status commit(const ClassSteps& manual, const ClassSteps& scenario);
  /// scenario_load, _start, _pause, _jump, _stop, each timed at breathing time t (now and the lead).
  console::ControlReply scenario_request(const console::ConsoleUser& user, const std::string& action,
                                         const nlohmann::json& request);
  /// One of `scenarios` by name, ready at its start; not while one runs or is paused.
  console::ControlReply scenario_load(const console::ConsoleUser& user, const nlohmann::json& request, double t);
  /// scenario_start (from where it stands) or scenario_jump (to a cue): the class brought there, then its steps.
  console::ControlReply scenario_go(const console::ConsoleUser& user, const std::string& action,
                                    const nlohmann::json& request, double t);
  /// scenario_pause or scenario_stop: its steps not yet begun dropped.
  console::ControlReply scenario_halt(const console::ConsoleUser& user, const std::string& action, double t);
  /// Brings the class to where the scenario stands at scenario time `at_s`, from class time `t_s` (a breath
  /// change, the pathologies' differences, a turn), then its steps from `at_s` on when `running`: the steps to
  /// add, and the scenario's offset (class time = scenario time + offset).
  ClassSteps scenario_steps(double at_s, double t_s, bool running, double& offset_s) const;
  /// Whether the class breathes the model now: none followed, or the console took the followed breath over.
  bool modelled() const { return start_.followed.empty() || breath_taken_over(); }
  /// The scenario's steps that have begun by class time t_s (those after it are dropped when it pauses, jumps or
  /// stops).
  ClassSteps begun_by(double t_s) const;
  nlohmann::json scenario_json(double t_s) const;
  void note(ClassEvent event);
  /// The pathologies present at breathing time t_s (one under way counts).
  std::vector<std::string> present_at(double t_s) const;
  /// The pathologies coming or going at t_s ("pneumothorax:right:30 (coming)"), "" when none.
  std::string changing_at(double t_s) const;

  ClassStart start_;
  std::shared_ptr<classroom::ClassroomStation> station_;
  std::function<void(const std::string&)> log_;

  std::vector<std::unique_ptr<const sim::BreathingDriver>> drivers_;  ///< console thread; every driver installed
  std::atomic<const sim::BreathingDriver*> driver_{nullptr};
  bool paused_ = false;  ///< console thread: a breath hold the console started is in force
  std::atomic<bool> taken_over_{false};  ///< the console's model breath in place of the followed one

  /// Console thread: the console's own steps (requests), and the scenario's, which it drops from when it pauses,
  /// jumps or stops. The class is the start, these, and nothing else.
  ClassSteps manual_;
  struct ScenarioRun {
    std::optional<ClassScenario> loaded;
    std::string phase;      ///< "ready", "running", "paused", "stopped"; empty: none loaded
    double position_s = 0;  ///< scenario time where it stands, when not running
    double offset_s = 0;    ///< running: class time = scenario time + offset_s
    ClassSteps issued;      ///< its steps in the class, on class time
  } scenario_;

  /// Console thread; every orientation track installed (none: the patient is tracked). The frame reads the newest
  /// through track_, as it does the breathing driver.
  std::vector<std::unique_ptr<const sim::OrientationTrack>> tracks_;
  std::atomic<const sim::OrientationTrack*> track_{nullptr};

  /// Console thread: the ventilation map the console asked of every display (none yet: each station's own). The
  /// frame reads it through shown_map_.
  std::optional<bool> ventilation_map_;
  VersionedFlag shown_map_;

  mutable std::mutex mutex_;  ///< guards events_ (breathing), lungs_ and log_lines_ against readers on other threads
  std::vector<sim::Event> breath_events_;
  sim::PathologyTimeline lungs_;
  std::vector<ClassEvent> log_lines_;
  std::atomic<std::uint64_t> lungs_version_{0};  ///< 0: as started (the station's own course draws it)
  std::atomic<std::uint64_t> refused_{0};

  SpscRing<FrameSample, 256> samples_;  ///< frame -> console thread
  std::deque<FrameSample> recent_;      ///< console thread: the last kSamplesS of them
};

}  // namespace lungar::platform::sync
