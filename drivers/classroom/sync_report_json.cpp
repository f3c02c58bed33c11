/// @file sync_report_json.cpp
/// @brief The sync keys of the stats JSON.
#include "drivers/classroom/sync_report_json.h"

namespace lungar::classroom {

void add_sync_keys(const SyncReport& r, nlohmann::json& j) {
  j["sync_role"] = to_string(r.role);
  j["sync_peers"] = r.peers;
  j["sync_peers_max"] = r.peers_max;
  j["sync_state"] = to_string(r.state);
  j["sync_instructor"] = r.instructor;
  j["sync_breath_offset_ms_p50"] = r.breath_offset_ms_p50;
  j["sync_breath_offset_ms_p99"] = r.breath_offset_ms_p99;
  j["sync_patient_pose_age_ms_p50"] = r.patient_pose_age_ms_p50;
  j["sync_patient_pose_age_ms_p99"] = r.patient_pose_age_ms_p99;
  j["sync_clock_offset_ms"] = r.clock_offset_ms;
  j["sync_clock_offset_spread_ms"] = r.clock_offset_spread_ms;
  j["sync_clock_delay_ms"] = r.clock_delay_ms;
  j["sync_join_to_in_sync_ms"] = r.join_to_in_sync_ms;
  j["sync_poses"] = r.poses;
  j["sync_patient_orientation_wxyz"] = r.patient_orientation_wxyz;
  j["sync_heartbeats"] = r.heartbeats;
  j["sync_followed_breath_points"] = r.followed_breath_points;
  j["sync_malformed"] = r.malformed;
  j["sync_secure"] = r.secure;
  j["sync_rejected"] = r.rejected;
  nlohmann::json transitions = nlohmann::json::array();
  for (const SyncTransition& t : r.transitions) {
    transitions.push_back({{"state", to_string(t.state)}, {"realtime_ns", t.realtime_ns}});
  }
  j["sync_transitions"] = transitions;
}

std::string report_json(const SyncReport& r) {
  nlohmann::json j;
  add_sync_keys(r, j);
  return j.dump();
}

}  // namespace lungar::classroom
