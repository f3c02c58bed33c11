/// @file sync_types.h
/// @brief A classroom station's role, its sync state, its options and what it reports (stats JSON keys).
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "config/base/enum_names.h"
#include "drivers/classroom/sync_settings.h"

namespace lungar::classroom {

/// off: no sync; in_sync: following (a trainee) or followed (the instructor); lost: a trainee that hears no
/// instructor (yet, or any more) and goes on breathing on the last shared time base.
enum class SyncState : std::uint8_t { Off, InSync, Lost };
inline constexpr EnumNames<SyncState, 3> kSyncStateNames{
    {{{SyncState::Off, "off"}, {SyncState::InSync, "in_sync"}, {SyncState::Lost, "lost"}}}};

inline const char* to_string(SyncState s) { return kSyncStateNames.name(s); }

/// A trainee as the instructor's console shows it, from the status it sends about twice a second.
struct StationStatus {
  std::string name;
  std::string state;            ///< "in step", "joining" (not yet in step) or "lost" (no status for 2 s)
  double breath_offset_ms = 0;  ///< the largest |breath offset| over its last status's interval
  double pose_age_ms = 0;       ///< the oldest patient pose it applied over that interval
  double fps = 0;               ///< frames it drew per second over that interval
  bool secure = false;
  double heard_s_ago = 0;  ///< since its last status
};

struct SyncOptions {
  SyncRole role = SyncRole::Off;
  std::string classroom = "classroom";           ///< the DDS partition: stations of one classroom see only each other
  std::uint32_t domain = 0;                      ///< the DDS domain id
  std::string cyclonedds_xml;                    ///< the Cyclone DDS XML configuration file
  std::string station;                           ///< this station's name ("" -> host/pid)
  std::string security_dir;                      ///< a station folder of `lungar classroom-keys`; "": an open classroom
  std::int64_t refuse_after_ns = 3'000'000'000;  ///< a participant that has not authenticated by then is refused
  std::int64_t clock_skew_ns = 0;                ///< tests: this station's clock runs this far from the machine's
  std::int64_t lost_after_ns = 250'000'000;      ///< a trainee is lost after this long without a heartbeat
  std::int64_t probe_ns = 600'000'000;           ///< an instructor listens this long for another one before it starts
  std::function<void(const std::string&)> log;   ///< one line per event
};

/// One change of sync state, for the stats JSON: when (the machine's CLOCK_REALTIME, ns) and to what.
struct SyncTransition {
  SyncState state = SyncState::Off;
  std::int64_t realtime_ns = 0;
};

/// What a station reports at the end of a run (stats JSON `sync_*`).
struct SyncReport {
  SyncRole role = SyncRole::Off;
  SyncState state = SyncState::Off;
  int peers = 0;                       ///< other stations of the classroom seen now
  int peers_max = 0;                   ///< the most seen at once during the run
  std::string instructor;              ///< the instructor followed (a trainee) or this station (the instructor)
  double breath_offset_ms_p50 = 0;     ///< trainee's breathing time minus the instructor's, same instant
  double breath_offset_ms_p99 = 0;     ///< (absolute values' percentiles)
  double patient_pose_age_ms_p50 = 0;  ///< instructor's publication -> trainee's receipt
  double patient_pose_age_ms_p99 = 0;
  double clock_offset_ms = 0;         ///< instructor clock minus this clock, estimated
  double clock_offset_spread_ms = 0;  ///< the estimate's jitter
  double clock_delay_ms = 0;          ///< the round trip of the best exchange
  double join_to_in_sync_ms = -1;     ///< first word from the instructor -> in step (the last join)
  std::uint64_t poses = 0;            ///< patient poses published (instructor) or applied (trainee)
  std::array<double, 4> patient_orientation_wxyz{1, 0, 0, 0};  ///< the last lung orientation sent or received
  std::uint64_t malformed = 0;                                 ///< samples dropped as malformed or out of range
  std::uint64_t heartbeats = 0;
  std::uint64_t followed_breath_points = 0;  ///< a trainee: the instructor's followed dV points received
  bool secure = false;                       ///< joined with DDS Security (authenticated, access-controlled, encrypted)
  std::uint64_t rejected = 0;                ///< participants that did not authenticate as stations of the classroom
  std::vector<SyncTransition> transitions;
};

}  // namespace lungar::classroom
