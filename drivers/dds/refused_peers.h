/// @file refused_peers.h
/// @brief Who knocked on a secure classroom and was not let in: the DDS participants that discovery saw on the
/// classroom's domain and that never authenticated as stations of the classroom (another authority's keys, an
/// expired or revoked certificate, permissions that do not allow them, or no DDS Security at all).
/// @ingroup platform
///
/// Cyclone's security plugins refuse such a participant without telling the application: a failed handshake is
/// only a warning in its log, and a participant without security is dropped without a word. What the application
/// can see is discovery's list of participants (the DCPSParticipant built-in topic, which names every
/// participant heard on the domain) and which of them our Station reader matched (only an authenticated, allowed
/// participant matches a protected topic). A participant heard for longer than a grace time that has matched
/// nothing is refused; the count is `sync_rejected` in the stats JSON, each is logged once, with what Cyclone
/// said about the handshakes (the refused certificate's subject) when it said anything.
#pragma once

#include <dds/dds.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "drivers/dds/dds.h"

namespace lungar::dds {

class RefusedPeers {
 public:
  /// Watches discovery on `participant`'s domain. A participant gets `grace_ns` (handshakes take a few round
  /// trips, longer on a loaded machine) before it counts as refused.
  static Result<std::unique_ptr<RefusedPeers>> create(dds_entity_t participant, std::int64_t grace_ns);

  /// Takes what discovery heard, what Cyclone's security said, and which participants `station_reader` matched;
  /// logs each newly refused participant, and each new complaint of Cyclone's, once.
  void poll(dds_entity_t station_reader, std::int64_t now_ns, const std::function<void(const std::string&)>& log);

  /// Participants refused now (one that authenticated late leaves the count).
  std::uint64_t count() const { return count_.load(std::memory_order_relaxed); }

 private:
  RefusedPeers() = default;
  struct Heard {
    dds_guid_t key{};
    std::int64_t first_ns = 0;
    bool joined = false;   ///< matched our Station reader at some point: a station of this classroom
    bool refused = false;  ///< counted and logged
  };
  void take_discovered(std::int64_t now_ns);
  void mark_joined(dds_entity_t station_reader);

  dds::Entity reader_;  ///< DCPSParticipant
  dds_guid_t self_{};
  std::int64_t grace_ns_ = 0;
  std::vector<Heard> heard_;
  std::atomic<std::uint64_t> count_{0};
};

/// "1a2b3c4d:..." : a participant's GUID as Cyclone's log writes it, so the two can be matched by eye.
std::string guid_text(const dds_guid_t& g);

}  // namespace lungar::dds
