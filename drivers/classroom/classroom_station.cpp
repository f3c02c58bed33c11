/// @file classroom_station.cpp
/// @brief [sync] -> the station.
#include "drivers/classroom/classroom_station.h"

namespace lungar::classroom {

std::string default_cyclonedds_xml() { return std::string(LUNGAR_CYCLONEDDS_DIR) + "/classroom-lan.xml"; }

SyncOptions to_sync_options(const SyncSettings& s, std::function<void(const std::string&)> log,
                            std::int64_t clock_skew_ns) {
  SyncOptions o;
  o.role = s.role;
  o.classroom = s.classroom;
  o.domain = static_cast<std::uint32_t>(s.domain);
  o.cyclonedds_xml = s.cyclonedds_xml.empty() ? default_cyclonedds_xml() : s.cyclonedds_xml;
  o.station = s.station;
  o.security_dir = s.security;
  o.lost_after_ns = static_cast<std::int64_t>(s.lost_after_ms * 1e6);
  o.log = std::move(log);
  o.clock_skew_ns = clock_skew_ns;
  return o;
}

Result<ClassroomStation> ClassroomStation::open(const SyncSettings& s, std::function<void(const std::string&)> log,
                                                std::int64_t clock_skew_ns) {
  ClassroomStation station;
  const SyncOptions o = to_sync_options(s, std::move(log), clock_skew_ns);
  if (s.role == SyncRole::Instructor) {
    auto made = Instructor::create(o);
    if (!made) return Error{made.error()};
    station.instructor_ = made.take();
  } else if (s.role == SyncRole::Trainee) {
    auto made = Trainee::create(o);
    if (!made) return Error{made.error()};
    station.trainee_ = made.take();
  }
  return station;
}

SyncRole ClassroomStation::role() const {
  return instructor_ ? SyncRole::Instructor : trainee_ ? SyncRole::Trainee : SyncRole::Off;
}

SyncState ClassroomStation::state() const {
  return instructor_ ? instructor_->state() : trainee_ ? trainee_->state() : SyncState::Off;
}

SyncReport ClassroomStation::report() const {
  if (instructor_) return instructor_->report();
  if (trainee_) return trainee_->report();
  return SyncReport{};
}

}  // namespace lungar::classroom
