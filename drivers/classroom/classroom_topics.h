/// @file classroom_topics.h
/// @brief The classroom's topics: names, the idlc-generated types (classroom.idl) and each topic's QoS.
/// @ingroup platform
///
/// The shared state's durability is what makes a late joiner in step at once: the breathing state, the
/// scenario's events and the stations are reliable, transient-local, keep-last 1, so a new reader gets the
/// latest sample on matching. The patient pose is best effort, keep-last 1: a lost pose is superseded 16 ms
/// later anyway, and a retransmitted old one would only be older. The classroom is a DDS partition on every
/// reader and writer, so two classrooms on one domain never match.
#pragma once

#include <string>

#include "drivers/dds/dds.h"
#include "lungar/sync/classroom.h"

namespace lungar::classroom {

/// Station roles on the wire (Station::role).
inline constexpr std::uint8_t kWireInstructor = 1;
inline constexpr std::uint8_t kWireTrainee = 2;

/// A topic's name and its generated descriptor.
template <class T>
struct TopicInfo;
#define LUNGAR_SYNC_TOPIC(Type, Name)                                                       \
  template <>                                                                               \
  struct TopicInfo<lungar_sync_##Type> {                                                    \
    static constexpr const char* name = Name;                                               \
    static const dds_topic_descriptor_t& descriptor() { return lungar_sync_##Type##_desc; } \
  }
LUNGAR_SYNC_TOPIC(Station, "lungar_station");
LUNGAR_SYNC_TOPIC(PatientPose, "lungar_patient_pose");
LUNGAR_SYNC_TOPIC(BreathingState, "lungar_breathing_state");
LUNGAR_SYNC_TOPIC(ScenarioEvents, "lungar_scenario_events");
LUNGAR_SYNC_TOPIC(Heartbeat, "lungar_heartbeat");
LUNGAR_SYNC_TOPIC(TimeRequest, "lungar_time_request");
LUNGAR_SYNC_TOPIC(TimeReply, "lungar_time_reply");
LUNGAR_SYNC_TOPIC(StationStatus, "lungar_station_status");
#undef LUNGAR_SYNC_TOPIC

/// Every topic of the classroom, in the order a station creates them.
using ClassroomTopics = dds::EntitySet<dds::Topic, lungar_sync_Station, lungar_sync_PatientPose,
                                       lungar_sync_BreathingState, lungar_sync_ScenarioEvents, lungar_sync_Heartbeat,
                                       lungar_sync_TimeRequest, lungar_sync_TimeReply, lungar_sync_StationStatus>;
/// The topics the instructor writes and every trainee reads, as a set of E (dds::Writer or dds::Reader) in
/// the order a station creates them.
template <template <class> class E>
using FromInstructor = dds::EntitySet<E, lungar_sync_PatientPose, lungar_sync_BreathingState,
                                      lungar_sync_ScenarioEvents, lungar_sync_Heartbeat, lungar_sync_TimeReply>;

/// How a topic is delivered.
enum class Delivery {
  Latest,   ///< best effort, volatile, keep-last 1: the pose, the heartbeat, the clock exchange, a trainee's status
  Durable,  ///< reliable, transient-local, keep-last 1: the station, the breathing state, the scenario events
};

template <class T>
constexpr Delivery delivery_of() {
  if constexpr (std::is_same_v<T, lungar_sync_Station> || std::is_same_v<T, lungar_sync_BreathingState> ||
                std::is_same_v<T, lungar_sync_ScenarioEvents>) {
    return Delivery::Durable;
  } else {
    return Delivery::Latest;
  }
}

/// The QoS of topic T in `classroom` (the same on its writers and readers, so they always match).
template <class T>
void classroom_qos(dds::Qos& qos, const std::string& classroom) {
  if (delivery_of<T>() == Delivery::Durable) {
    qos.reliable().transient_local().keep_last(1);
  } else {
    qos.best_effort().volatile_().keep_last(1);
  }
  qos.partition(classroom);
}

}  // namespace lungar::classroom
