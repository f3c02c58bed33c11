/// @file classroom_check.cpp
/// @brief The classroom check: off, open (anyone on the network can join: a warning), or secure with a complete
/// station folder.
#include "drivers/dds/dds_security.h"
#include "platform/doctor/checks.h"

namespace lungar::platform::doctor {

Check check_classroom(const Settings& s) {
  const classroom::SyncSettings& y = s.sync;
  if (y.role == classroom::SyncRole::Off) return passed("sync", "not in a classroom (sync.role = off)");
  const std::string room = "classroom \"" + y.classroom + "\" (" + to_string(y.role) + ")";
  if (y.security.empty()) {
    return warned("sync", room + " is open: any DDS participant on this network can join it and publish to it",
                  "make its keys with lungar classroom-keys and give each station its folder (sync.security or "
                  "--sync-security)");
  }
  auto files = dds::find_security_files(y.security);
  if (!files)
    return failed("sync", files.error(), "run lungar classroom-keys again, or copy the station's whole folder");
  dds::Qos qos;
  if (Status p = dds::add_security_properties(*files, static_cast<std::uint32_t>(y.domain), qos); !p) {
    return failed("sync", p.error(), "install libddsc0debian, or choose sync.domain in [0, 230]");
  }
  return passed("sync", room + " is secure: DDS Security with " + files->dir);
}

}  // namespace lungar::platform::doctor
