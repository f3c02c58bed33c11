/// @file trainee.h
/// @brief The trainee station: follows the instructor's lung pose and breathing (its head stays its own),
/// estimates the instructor's clock, and says when it is in sync or lost. It never publishes shared state:
/// it has writers only for its Station announcement and its clock requests.
/// @ingroup platform
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "config/base/log_histogram.h"
#include "config/base/result.h"
#include "config/base/versioned_flag.h"
#include "drivers/classroom/classroom_link.h"
#include "drivers/classroom/clock_offset.h"
#include "drivers/classroom/followed_breath_share.h"
#include "drivers/classroom/shared_breathing.h"
#include "drivers/classroom/sync_types.h"
#include "drivers/classroom/wire.h"
#include "drivers/pose/mailbox.h"
#include "drivers/pose/pose_sample.h"

namespace lungar::classroom {

class Trainee {
 public:
  /// Clock requests: every kBurstPeriodNs until kBurstExchanges answers, then every kRequestPeriodNs.
  static constexpr std::int64_t kBurstPeriodNs = 10'000'000;
  static constexpr int kBurstExchanges = 8;
  static constexpr std::int64_t kRequestPeriodNs = 200'000'000;

  static Result<std::unique_ptr<Trainee>> create(const SyncOptions& options);
  ~Trainee();
  Trainee(const Trainee&) = delete;
  Trainee& operator=(const Trainee&) = delete;

  /// The lung pose in the world from the instructor (role Patient; arrival = its receipt here, monotonic),
  /// flagged stale while lost; an invalid sample before the first. Lock-free, allocates nothing.
  drivers::PoseSample patient_pose() const;
  /// The shared breathing at monotonic `now_ns` (the instructor's followed dV where it follows the patient's own
  /// breath); false until the instructor's breathing has arrived. The frame thread.
  bool breathing(std::int64_t now_ns, sim::BreathingSample& out) const;
  /// The instructor's breathing time at monotonic `now_ns`, on which its pathology events are timed; false until
  /// its breathing has arrived.
  bool breath_time(std::int64_t now_ns, double& t_s) const;
  /// The instructor's pathologies, when they changed since `version` (0 at first): true, `out` and `version` set.
  bool lungs_since(std::uint64_t& version, sim::PathologyTimeline& out) const;
  /// The ventilation map the instructor's console asked every display to show, when that request changed since
  /// `version` (0 at first): true, `on` and `version` set. A station's own choice (its V key) stands until the
  /// console asks something else. Lock-free, allocates nothing.
  bool ventilation_map_since(std::uint64_t& version, bool& on) const;
  /// From the frame: the breathing time it drew at monotonic `now_ns`, whichever clock gave it. The sync thread
  /// compares it with the instructor's at the same instant (sync_breath_offset_ms_*). Allocates nothing.
  void frame_breath(std::int64_t now_ns, double t_s) { frame_box_.publish(FrameBreath{now_ns, t_s}); }

  SyncState state() const { return state_.load(std::memory_order_acquire); }
  SyncReport report() const;
  const std::string& station() const { return link_->name(); }

 private:
  struct PendingState {
    std::uint64_t session = 0;
    std::uint32_t revision = 0;
    std::int64_t time_base_ns = 0;
    std::string station;
    sim::BreathingParams params;
  };
  struct PendingEvents {
    std::uint64_t session = 0;
    std::uint32_t revision = 0;
    std::vector<sim::Event> events;
    sim::PathologyTimeline lungs;
    std::optional<bool> ventilation_map;
  };
  struct FrameBreath {
    std::int64_t now_mono_ns;
    double t_s;
  };
  explicit Trainee(std::unique_ptr<ClassroomLink> link);
  void compare_breath(const lungar_sync_Heartbeat& hb);
  Status open_endpoints();
  void run();
  void take_breathing();
  void take_events();
  void install_if_complete();
  void take_heartbeats(std::int64_t now_mono);
  void take_poses();
  void take_replies();
  /// About twice a second: this station's status, for the instructor's console.
  void send_status(std::int64_t now_mono);
  /// A sample from instructor `session` arrived: it is alive; a new session restarts the clock estimate.
  void hear(std::uint64_t session, std::int64_t now_mono);
  /// Until the first clock exchange, a one-way estimate from a sample's source timestamp: the instructor's clock
  /// minus this one at its receipt is the offset less the path's delay (a fraction of a millisecond on a LAN),
  /// so a joining trainee is in step on its first heartbeat or pose; the exchanges refine it smoothly.
  void provisional_offset(std::int64_t source_ns, std::int64_t here_ns);
  void request_time(std::int64_t now_mono);
  void update_state(std::int64_t now_mono);
  void transition(SyncState to);
  void record(LogHistogram& values, double v);

  std::unique_ptr<ClassroomLink> link_;
  std::optional<dds::Writer<lungar_sync_TimeRequest>> request_writer_;
  std::optional<dds::Writer<lungar_sync_StationStatus>> status_writer_;
  FromInstructor<dds::Reader> readers_;

  drivers::LatestMailbox<drivers::PoseSample> pose_box_;
  drivers::LatestMailbox<FrameBreath> frame_box_;
  SharedBreathing breathing_;
  mutable FollowedBreathShare followed_;  ///< heartbeats in on the sync thread, dV out on the frame's
  std::atomic<std::uint64_t> followed_points_{0};
  ClockOffsetEstimator estimator_;
  mutable std::mutex lungs_mutex_;  ///< guards lungs_ (the sync thread writes, the lungs' course reads)
  sim::PathologyTimeline lungs_;
  std::atomic<std::uint64_t> lungs_version_{0};
  VersionedFlag ventilation_map_;        ///< the console's display request, once per change
  std::optional<bool> display_applied_;  ///< sync thread: the request last taken

  // Sync thread only.
  std::optional<PendingState> pending_state_;
  std::optional<PendingEvents> pending_events_;
  std::uint64_t installed_session_ = 0;
  std::uint32_t installed_revision_ = 0;
  std::uint64_t heard_session_ = 0;      ///< the instructor session last heard from (0: none, or lost)
  std::int64_t last_heard_mono_ = 0;     ///< its last heartbeat, pose or state
  std::int64_t join_mono_ = 0;           ///< first word from the current instructor session
  std::int64_t in_sync_since_mono_ = 0;  ///< frames from here on are compared with the instructor
  std::uint32_t request_seq_ = 0;
  std::int64_t next_status_mono_ = 0;
  std::uint64_t status_frames_ = 0;  ///< frame_box_'s count at the last status
  double status_offset_ms_ = 0;      ///< the largest |breath offset| since the last status
  double status_pose_age_ms_ = 0;    ///< the oldest pose applied since the last status
  std::int64_t next_request_mono_ = 0;
  int exchanges_ = 0;

  std::atomic<SyncState> state_{SyncState::Lost};
  std::atomic<int> peers_{0}, peers_max_{0};
  std::atomic<std::uint64_t> poses_{0};
  std::atomic<std::uint64_t> heartbeats_{0};
  mutable std::mutex report_mutex_;  ///< guards what report() copies
  std::string instructor_;
  std::array<double, 4> last_orientation_{1, 0, 0, 0};
  std::optional<ClockEstimate> estimate_;
  bool provisional_ = false;  ///< estimate_ is one-way, not yet from an exchange
  double join_to_in_sync_ms_ = -1;
  LogHistogram breath_offset_ms_;  ///< magnitudes: constant memory over a teaching day
  LogHistogram pose_age_ms_;
  std::vector<SyncTransition> transitions_;

  dds::WaitThread thread_;  ///< last: stopped before the members its loop uses go
};

}  // namespace lungar::classroom
