/// @file sync_report_json.h
/// @brief A station's sync report as the stats JSON's `sync_*` keys (snake_case, unit suffix).
/// @ingroup platform
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "drivers/classroom/sync_types.h"

namespace lungar::classroom {

/// Adds the sync keys of `r` to `j`: sync_role, sync_peers, sync_peers_max, sync_state, sync_breath_offset_ms_p50/p99,
/// sync_patient_pose_age_ms_p50/p99, sync_clock_offset_ms, sync_clock_offset_spread_ms, sync_clock_delay_ms,
/// sync_join_to_in_sync_ms, sync_poses, sync_patient_orientation_wxyz, sync_heartbeats, sync_malformed, sync_secure,
/// sync_rejected, sync_instructor, sync_transitions.
void add_sync_keys(const SyncReport& r, nlohmann::json& j);
/// The same keys alone, as one JSON object text.
std::string report_json(const SyncReport& r);

}  // namespace lungar::classroom
