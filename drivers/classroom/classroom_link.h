/// @file classroom_link.h
/// @brief What every station of a classroom has: the DDS domain and participant, the classroom's topics, its
/// own Station announcement and the roster of the others, a waitset, and the malformed-sample counter.
/// @ingroup platform
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "config/base/result.h"
#include "drivers/classroom/classroom_topics.h"
#include "drivers/classroom/station_clock.h"
#include "drivers/classroom/sync_types.h"
#include "drivers/dds/dds.h"
#include "drivers/dds/refused_peers.h"
#include "drivers/dds/wait_thread.h"

namespace lungar::classroom {

/// Another station of the classroom as its Station sample says.
struct RosterEntry {
  std::string name;
  std::uint8_t role = 0;
  std::uint64_t session = 0;
  std::int64_t started_ns = 0;
  dds_instance_handle_t instance = 0;
  bool alive = false;
};

class ClassroomLink {
 public:
  /// Creates the domain from the XML, the participant, every topic, and this station's Station writer and the
  /// roster's reader, all in the classroom's partition.
  static Result<std::unique_ptr<ClassroomLink>> open(const SyncOptions& options, std::uint8_t wire_role);

  /// Announces this station (reliable, transient-local: a later station learns of it on joining).
  Status announce();
  /// Takes new Station samples into the roster; returns how many.
  int poll_roster();
  /// Other stations seen alive now, and the most seen at once.
  int peers() const;
  int peers_max() const { return peers_max_; }
  /// The instructor, other than this station, that keeps the room against this one (started earlier, or at
  /// the same time with a smaller name), if any.
  std::optional<RosterEntry> senior_instructor() const;

  template <class T>
  Result<dds::Writer<T>> writer() const {
    return endpoint<dds::Writer<T>, T>("publish");
  }
  template <class T>
  Result<dds::Reader<T>> reader() const {
    return endpoint<dds::Reader<T>, T>("read");
  }

  dds::WaitSet& waitset() { return *waitset_; }
  const StationClock& clock() const { return clock_; }
  const SyncOptions& options() const { return options_; }
  const std::string& name() const { return name_; }
  std::uint64_t session() const { return session_; }
  std::int64_t started_ns() const { return started_ns_; }
  void log(const std::string& line) const;
  /// Counts a dropped sample and logs it, the first few and then one in a hundred.
  void malformed(const std::string& why);
  std::uint64_t malformed_count() const { return malformed_.load(std::memory_order_relaxed); }
  /// A report with what the link knows: `role`, dropped samples, security and the participants it refused.
  SyncReport report(SyncRole role) const {
    SyncReport r;
    r.role = role;
    r.malformed = malformed_count();
    r.secure = secure();
    r.rejected = rejected_count();
    return r;
  }
  /// Joined with DDS Security (SyncOptions::security_dir).
  bool secure() const { return !options_.security_dir.empty(); }
  /// Participants that did not authenticate as stations of this classroom (0 in an open classroom).
  std::uint64_t rejected_count() const { return refused_ ? refused_->count() : 0; }

 private:
  ClassroomLink(const SyncOptions& options, dds::Domain domain);
  /// A writer or reader (E) of T with the topic's classroom QoS; `what` it does, for a refusal's line.
  template <class E, class T>
  Result<E> endpoint(const char* what) const {
    dds::Qos qos;
    classroom_qos<T>(qos, options_.classroom);
    auto made = E::create(domain_.participant(), topics_.get<T>(), qos);
    if (!made && secure()) return fail(not_permitted(TopicInfo<T>::name, what, made.error()));
    return made;
  }
  /// The one line for an endpoint a secure classroom's permissions refused.
  std::string not_permitted(const char* topic, const char* what, const std::string& cyclone) const;

  SyncOptions options_;
  StationClock clock_;
  std::string name_;
  std::uint64_t session_ = 0;
  std::int64_t started_ns_ = 0;
  std::uint8_t wire_role_ = 0;
  std::atomic<std::uint64_t> malformed_{0};
  std::array<RosterEntry, 64> roster_{};
  std::size_t roster_size_ = 0;
  int peers_max_ = 0;
  std::int64_t refused_polled_ns_ = 0;
  // Entities: the domain first, so that it is deleted last.
  dds::Domain domain_;
  ClassroomTopics topics_;
  std::optional<dds::Writer<lungar_sync_Station>> station_writer_;
  std::optional<dds::Reader<lungar_sync_Station>> station_reader_;
  std::optional<dds::WaitSet> waitset_;
  std::unique_ptr<dds::RefusedPeers> refused_;  ///< only in a secure classroom
};

/// A random 64-bit session id for this run of a station.
std::uint64_t new_session_id();
/// "host/pid": a default station name that says where to look.
std::string default_station_name();

}  // namespace lungar::classroom
