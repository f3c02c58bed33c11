/// @file sync_settings.cpp
/// @brief The [sync] keys: a classroom name DDS can use as a partition, the domain's range, a station name.
#include "drivers/classroom/sync_settings.h"

namespace lungar::classroom {

void read_sync_settings(config::TomlSection s, SyncSettings& y) {
  s.choice("role", y.role, kSyncRoleNames);
  s.text("classroom", y.classroom);
  if (y.classroom.empty() || y.classroom.size() > 63 || y.classroom.find_first_of("*?[]\\") != std::string::npos) {
    s.fail("classroom", "expected a name of 1 to 63 characters without * ? [ ] \\, got \"" + y.classroom + "\"");
  }
  s.integer("domain", y.domain, 0, 232, "");
  s.text("cyclonedds_xml", y.cyclonedds_xml);
  s.text("station", y.station);
  s.text("security", y.security);
  if (y.station.size() > 63) s.fail("station", "expected at most 63 characters, got \"" + y.station + "\"");
  s.number("lost_after_ms", y.lost_after_ms, 50.0, 10000.0, "ms");
  s.finish();
}

}  // namespace lungar::classroom
