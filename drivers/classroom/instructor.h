/// @file instructor.h
/// @brief The instructor station: publishes the lung pose its frame drew, the breathing state and scenario
/// events, a heartbeat, and answers the trainees' clock requests. One instructor per classroom: it refuses to
/// start (or stops) when an older one is there, with one line naming it.
/// @ingroup platform
///
/// The frame hands its pose and breathing time over through lock-free mailboxes and a guard condition, so the
/// frame allocates nothing and never waits on DDS; the sync thread does the writing.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "drivers/classroom/classroom_link.h"
#include "drivers/classroom/sync_types.h"
#include "drivers/pose/mailbox.h"
#include "sim/breathing/driver.h"
#include "sim/breathing/event.h"
#include "sim/breathing/pattern.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::classroom {

class Instructor {
 public:
  static constexpr std::int64_t kHeartbeatPeriodNs = 50'000'000;  ///< 20 Hz: lost is seen within 250 ms

  /// Opens the classroom, listens options.probe_ns for another instructor and refuses with one line naming
  /// it; else starts the sync thread. Nothing of the shared state is published before share_breathing().
  static Result<std::unique_ptr<Instructor>> create(const SyncOptions& options);
  ~Instructor();
  Instructor(const Instructor&) = delete;
  Instructor& operator=(const Instructor&) = delete;

  /// The breathing the classroom follows: start parameters, every event, the lungs' pathologies on the same
  /// breathing time, and the monotonic instant of breathing time 0. Call once before the frames (it allocates).
  Status share_breathing(const sim::BreathingParams& start, std::span<const sim::Event> events,
                         const sim::PathologyTimeline& lungs, std::int64_t t0_mono_ns);
  /// The class changed while it runs (the instructor's console): the same start and time base with more events
  /// or pathologies, as the next revision. Every trainee rebuilds its breathing and its lungs from it; an event
  /// timed a little ahead of now reaches them before it is due, so no station jumps. Any thread but the frame's
  /// (it allocates and writes to DDS); after share_breathing(). `ventilation_map`: what the console asks every
  /// display to show (nullopt: each station its own choice).
  Status reshare(const sim::BreathingParams& start, std::span<const sim::Event> events,
                 const sim::PathologyTimeline& lungs, std::optional<bool> ventilation_map);
  /// The revision last shared (1 after share_breathing()).
  std::uint32_t revision() const;
  /// From the frame: the lung pose in the world it drew and when the tracker read it (monotonic ns). A pose
  /// with the same reading time as the last is not sent again. Allocates nothing.
  void publish_pose(const std::array<double, 3>& position_mm, const std::array<double, 4>& orientation_wxyz,
                    std::int64_t measured_mono_ns);
  /// The breath is the patient's own, followed (a trace, a chest marker, a mannequin): no trainee can compute it
  /// from the shared parameters, so each frame's dV goes out in a heartbeat of its own. Call before the frames.
  void share_followed_breath() { followed_.store(true); }
  /// From the frame: its breathing time at frame_mono_ns, which the heartbeat carries, and its dV when the breath
  /// is followed. Allocates nothing.
  void frame_breath(std::int64_t frame_mono_ns, const sim::BreathingSample& breath);

  SyncState state() const { return SyncState::InSync; }
  /// Set when an older instructor turned up while running: the runtime stops with this line.
  std::string fatal_error() const;
  SyncReport report() const;
  const std::string& station() const { return link_->name(); }
  /// The trainees heard from, by name, as their last status said (for the console); "lost" when it is older than
  /// kStationLostNs. Any thread.
  std::vector<StationStatus> stations() const;
  static constexpr std::int64_t kStationLostNs = 2'000'000'000;

 private:
  struct PoseMsg {
    std::array<double, 3> position_mm;
    std::array<double, 4> orientation_wxyz;
    std::int64_t measured_mono_ns;
  };
  struct BreathMsg {
    std::int64_t frame_mono_ns;
    double breath_t_s;
    double dv_ml;
    std::array<double, 2> lung_dv_ml;
  };
  explicit Instructor(std::unique_ptr<ClassroomLink> link);
  Status open_writers();
  void run();
  void send_pose();
  void send_heartbeat();
  void answer_requests();
  void check_roster();
  void take_statuses();
  /// Writes the breathing state and events again when a new reader matched: it gets them at once, instead of
  /// on the reliable protocol's next heartbeat (about 100 ms later).
  void push_to_new_readers();

  std::unique_ptr<ClassroomLink> link_;
  FromInstructor<dds::Writer> writers_;
  std::optional<dds::Reader<lungar_sync_TimeRequest>> request_reader_;
  std::optional<dds::Reader<lungar_sync_StationStatus>> status_reader_;
  struct HeardStatus {
    StationStatus status;
    std::int64_t heard_mono_ns = 0;
  };
  mutable std::mutex stations_mutex_;  ///< guards stations_: the sync thread writes, the console reads
  std::vector<HeardStatus> stations_;

  mutable std::mutex share_mutex_;       ///< guards state_ and events_ (and their storage) against reshare()
  lungar_sync_BreathingState state_{};   ///< the shared state, as last written
  lungar_sync_ScenarioEvents events_{};  ///< points into event_storage_
  std::vector<lungar_sync_ScenarioEvent> event_storage_;
  std::vector<lungar_sync_PathologyEvent> pathology_storage_;
  int state_readers_ = 0, event_readers_ = 0;  ///< sync thread: matched readers at the last look

  drivers::LatestMailbox<PoseMsg> pose_box_;
  drivers::LatestMailbox<BreathMsg> breath_box_;
  std::int64_t last_measured_ = -1;  ///< frame thread only
  std::uint64_t sent_pose_ = 0;      ///< sync thread only: the mailbox count last sent
  std::uint64_t sent_breath_ = 0;    ///< sync thread only: the breath mailbox count last sent
  std::atomic<bool> followed_{false};
  std::atomic<std::int64_t> time_base_ns_{0};
  std::atomic<bool> shared_{false};
  std::atomic<std::uint64_t> poses_{0};
  std::atomic<std::uint64_t> heartbeats_{0};
  std::atomic<int> peers_{0}, peers_max_{0};
  std::uint32_t pose_seq_ = 0, heartbeat_seq_ = 0;
  mutable std::mutex fatal_mutex_;  ///< guards fatal_ and last_orientation_, which report() reads
  std::string fatal_;
  std::array<double, 4> last_orientation_{1, 0, 0, 0};
  dds::WaitThread thread_;  ///< last: stopped before the members its loop uses go
};

}  // namespace lungar::classroom
