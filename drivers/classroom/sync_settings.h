/// @file sync_settings.h
/// @brief [sync]: whether and how this station joins a classroom, owned by the classroom code that reads it,
/// with its TOML reader (sync_settings.cpp).
/// @ingroup platform
#pragma once

#include <string>

#include "config/base/enum_names.h"
#include "config/toml_section.h"

namespace lungar::classroom {

/// off: alone; instructor: publishes the shared state; trainee: follows it with its own head tracker.
enum class SyncRole { Off, Instructor, Trainee };
inline constexpr EnumNames<SyncRole, 3> kSyncRoleNames{
    {{{SyncRole::Off, "off"}, {SyncRole::Instructor, "instructor"}, {SyncRole::Trainee, "trainee"}}}};
inline const char* to_string(SyncRole v) { return kSyncRoleNames.name(v); }

/// Several stations sharing one patient and one breath over Cyclone DDS.
struct SyncSettings {
  SyncRole role = SyncRole::Off;
  std::string classroom = "classroom";  ///< the DDS partition: one name per classroom on a network
  int domain = 0;                       ///< the DDS domain id, [0, 232]
  std::string cyclonedds_xml;           ///< Cyclone XML; empty: the shipped config/cyclonedds/classroom-lan.xml
  std::string station;                  ///< this station's name; empty: host/pid
  std::string security;                 ///< this station's folder of `lungar classroom-keys`; empty: open classroom
  double lost_after_ms = 250.0;         ///< a trainee is lost after this long without a word from the instructor
};

/// Reads [sync] over `y`; throws config::ConfigError naming the file, key and expectation.
void read_sync_settings(config::TomlSection s, SyncSettings& y);

}  // namespace lungar::classroom
