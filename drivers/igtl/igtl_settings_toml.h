/// @file igtl_settings_toml.h
/// @brief [trackers.igtl] as TOML, read and written from one field list (config/toml_visit.h); tracker_config_toml.h
/// visits it inside [trackers].
/// @ingroup drivers
#pragma once

#include <string>
#include <utility>

#include "config/toml_visit.h"
#include "drivers/igtl/igtl_settings.h"

namespace lungar::drivers {

/// [trackers.igtl].
template <class Io>
void visit(Io& s, IgtlConfig& g) {
  s.text("host", g.host);
  if constexpr (config::kReads<Io>) {
    if (g.host.empty()) s.fail("host", "expected a host name or address (e.g. \"127.0.0.1\"), got \"\"");
  }
  s.integer("port", g.port, 1, 65535, "(TCP port)");
  const std::pair<const char*, std::string*> names[] = {
      {"head", &g.head}, {"patient", &g.patient}, {"stylus", &g.stylus}};
  for (const auto& [key, name] : names) {
    s.text(key, *name);
    if constexpr (config::kReads<Io>) {
      if (name->size() > 20) {  // OpenIGTLink's device and tool names are at most 20 bytes
        s.fail(key, "expected a device name of at most 20 characters (OpenIGTLink's limit), got \"" + *name + "\"");
      }
    }
  }
  if constexpr (config::kReads<Io>) {
    if (g.head.empty() && g.patient.empty() && g.stylus.empty()) {
      s.fail("patient", "expected a device name for at least one of head, patient, stylus, got none");
    }
  }
  s.number("scale", g.scale, 1e-6, 1e6, "mm per unit");
  s.number("rigid_tolerance", g.rigid_tolerance, 1e-7, 0.5, "");
  s.number("connect_timeout_ms", g.connect_timeout_ms, 10.0, 60000.0, "ms");
  s.finish();
}

}  // namespace lungar::drivers
