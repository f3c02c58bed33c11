/// @file refused_peers.cpp
/// @brief Discovery's participants against the authenticated ones: who was refused.
#include "drivers/dds/refused_peers.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

namespace lungar::dds {

namespace {

bool same(const dds_guid_t& a, const dds_guid_t& b) { return std::memcmp(a.v, b.v, sizeof a.v) == 0; }

/// A participant's GUID is its endpoints' GUID prefix (the first 12 bytes) with the participant's entity id.
bool same_participant(const dds_guid_t& a, const dds_guid_t& b) { return std::memcmp(a.v, b.v, 12) == 0; }

}  // namespace

std::string guid_text(const dds_guid_t& g) {
  char text[40];
  std::snprintf(text, sizeof text, "%02x%02x%02x%02x:%02x%02x%02x%02x:%02x%02x%02x%02x", g.v[0], g.v[1], g.v[2], g.v[3],
                g.v[4], g.v[5], g.v[6], g.v[7], g.v[8], g.v[9], g.v[10], g.v[11]);
  return text;
}

Result<std::unique_ptr<RefusedPeers>> RefusedPeers::create(dds_entity_t participant, std::int64_t grace_ns) {
  std::unique_ptr<RefusedPeers> made(new RefusedPeers());
  RefusedPeers& r = *made;
  auto reader = dds::own("dds_create_reader(DCPSParticipant)",
                         dds_create_reader(participant, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, nullptr));
  if (!reader) return Error{reader.error()};
  r.reader_ = reader.take();
  if (const dds_return_t rc = dds_get_guid(participant, &r.self_); rc < 0)
    return fail(dds::describe("dds_get_guid", rc));
  r.grace_ns_ = grace_ns;
  return made;
}

void RefusedPeers::take_discovered(std::int64_t now_ns) {
  std::array<void*, 8> samples{};
  std::array<dds_sample_info_t, 8> infos{};
  int n;
  while ((n = dds_take(reader_.get(), samples.data(), infos.data(), samples.size(), samples.size())) > 0) {
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const dds_guid_t key = static_cast<const dds_builtintopic_participant_t*>(samples[i])->key;
      if (same(key, self_) || heard_.size() >= 256) continue;
      const bool known = std::any_of(heard_.begin(), heard_.end(), [&](const Heard& h) { return same(h.key, key); });
      if (!known) heard_.push_back(Heard{key, now_ns, false, false});
    }
    dds_return_loan(reader_.get(), samples.data(), n);
  }
}

void RefusedPeers::mark_joined(dds_entity_t station_reader) {
  std::array<dds_instance_handle_t, 64> writers{};
  const dds_return_t n = dds_get_matched_publications(station_reader, writers.data(), writers.size());
  for (dds_return_t i = 0; i < std::min<dds_return_t>(n, writers.size()); ++i) {
    dds_builtintopic_endpoint_t* w = dds_get_matched_publication_data(station_reader, writers[i]);
    if (w == nullptr) continue;
    for (Heard& h : heard_) {
      if (same_participant(h.key, w->participant_key)) h.joined = true;
    }
    dds_builtintopic_free_endpoint(w);
  }
}

void RefusedPeers::poll(dds_entity_t station_reader, std::int64_t now_ns,
                        const std::function<void(const std::string&)>& log) {
  take_discovered(now_ns);
  mark_joined(station_reader);
  for (const std::string& complaint : dds::take_security_complaints())
    log("sync: DDS Security refused a peer: " + complaint);
  std::uint64_t refused = 0;
  for (Heard& h : heard_) {
    if (h.joined && h.refused) {
      h.refused = false;
      log("sync: DDS participant " + guid_text(h.key) + " authenticated after all: a station of this classroom");
    }
    if (!h.joined && !h.refused && now_ns - h.first_ns >= grace_ns_) {
      h.refused = true;
      log("sync: refused DDS participant " + guid_text(h.key) +
          ": it did not authenticate as a station of this classroom (another authority's keys, an expired or "
          "revoked identity, or no DDS Security); it is ignored");
    }
    refused += h.refused ? 1 : 0;
  }
  count_.store(refused, std::memory_order_relaxed);
}

}  // namespace lungar::dds
