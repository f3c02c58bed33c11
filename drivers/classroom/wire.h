/// @file wire.h
/// @brief The classroom's samples to and from lungar's types, with the checks a network message needs: a
/// sample that is malformed or out of range (a NaN pose, a negative breathing rate, events out of order) is
/// refused with one line naming the topic, the field and what was expected, and is never applied.
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "config/base/result.h"
#include "lungar/sync/classroom.h"
#include "sim/breathing/event.h"
#include "sim/breathing/pattern.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::classroom {

/// The lung's pose in the world, as the instructor's frame used it.
struct SharedPose {
  std::array<double, 3> position_mm{};
  std::array<double, 4> orientation_wxyz{1, 0, 0, 0};
  std::int64_t measured_ns = 0;  ///< instructor's station clock
};

/// Positions beyond this (mm from the tracker's origin) are not a classroom: 100 m.
inline constexpr double kMaxPositionMm = 1e5;
/// A unit quaternion's norm, give or take this.
inline constexpr double kQuaternionNormTolerance = 1e-3;
/// Scenario events a classroom sample carries at most (the IDL sequence's bound).
inline constexpr std::size_t kMaxScenarioEvents = 256;
/// Pathology events a classroom sample carries at most (the IDL sequence's bound).
inline constexpr std::size_t kMaxPathologyEvents = 64;
/// A followed breath's dV an instructor shares is at most this (mL) either way: beyond any lung's vital capacity.
inline constexpr double kMaxSharedDvMl = 8000.0;

Result<SharedPose> from_wire(const lungar_sync_PatientPose& s);
void to_wire(const SharedPose& pose, std::uint64_t session, std::uint32_t seq, lungar_sync_PatientPose& out);

/// The breathing parameters a BreathingState carries (its time base is read directly).
Result<sim::BreathingParams> from_wire(const lungar_sync_BreathingState& s);
void to_wire(const sim::BreathingParams& p, lungar_sync_BreathingState& out);

/// The events a ScenarioEvents carries, in time order, each in range.
Result<std::vector<sim::Event>> from_wire(const lungar_sync_ScenarioEvents& s);
/// Fills `storage` from `events` and points out.events at it (`storage` must outlive the write).
Status to_wire(std::span<const sim::Event> events, std::vector<lungar_sync_ScenarioEvent>& storage,
               lungar_sync_ScenarioEvents& out);

/// The lungs' pathologies a ScenarioEvents carries: each spec one lungar knows, the events in time order, each
/// removal of what is there (sim::check_timeline).
Result<sim::PathologyTimeline> pathologies_from_wire(const lungar_sync_ScenarioEvents& s);
/// Fills `storage` from `timeline` and points out's pathology members at it (`storage` must outlive the write);
/// an error when the timeline does not fit the sample's bounds.
Status to_wire(const sim::PathologyTimeline& timeline, std::vector<lungar_sync_PathologyEvent>& storage,
               lungar_sync_ScenarioEvents& out);

/// The ventilation map a ScenarioEvents asks of every display: nullopt when each station keeps its own choice
/// (0 on the wire), else off (1) or on (2); anything else is an error naming the field.
Result<std::optional<bool>> ventilation_map_from_wire(const lungar_sync_ScenarioEvents& s);
void ventilation_map_to_wire(std::optional<bool> on, lungar_sync_ScenarioEvents& out);

/// A heartbeat's frame time and breathing time must be real numbers.
Status check(const lungar_sync_Heartbeat& s);
/// A station's role must be instructor or trainee and its name not empty.
Status check(const lungar_sync_Station& s);
/// A trainee's status: a name, a known state, and figures that are real numbers, none negative.
Status check(const lungar_sync_StationStatus& s);

}  // namespace lungar::classroom
