/// @file classroom_station.h
/// @brief The station the config's [sync] asks for: none (off), the instructor or a trainee, opened from
/// SyncSettings; one place for what the runtime asks of either (state, report, a fatal refusal).
/// @ingroup platform
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "drivers/classroom/instructor.h"
#include "drivers/classroom/sync_settings.h"
#include "drivers/classroom/trainee.h"

namespace lungar::classroom {

/// The Cyclone XML used when sync.cyclonedds_xml is empty: the shipped classroom-lan.xml.
std::string default_cyclonedds_xml();

/// SyncOptions from the config ([sync]); `log` receives the station's lines.
SyncOptions to_sync_options(const SyncSettings& s, std::function<void(const std::string&)> log,
                            std::int64_t clock_skew_ns = 0);

class ClassroomStation {
 public:
  /// Off: a station that is neither. Else the instructor (refused, with one line naming the other, when the
  /// classroom has one) or a trainee. `clock_skew_ns`: tests pretend this station's clock is off.
  static Result<ClassroomStation> open(const SyncSettings& s, std::function<void(const std::string&)> log,
                                       std::int64_t clock_skew_ns = 0);

  SyncRole role() const;
  Instructor* instructor() const { return instructor_.get(); }
  Trainee* trainee() const { return trainee_.get(); }
  SyncState state() const;
  /// True while a trainee hears no instructor: the status line says "sync lost".
  bool lost() const { return state() == SyncState::Lost; }
  /// Set when an older instructor turned up in the classroom while this one ran: stop with this line.
  std::string fatal_error() const { return instructor_ ? instructor_->fatal_error() : std::string(); }
  SyncReport report() const;

 private:
  std::unique_ptr<Instructor> instructor_;
  std::unique_ptr<Trainee> trainee_;
};

}  // namespace lungar::classroom
