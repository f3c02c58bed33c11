/// @file plus_settings_toml.h
/// @brief [trackers.plus] as TOML, read and written from one field list (config/toml_visit.h); tracker_config_toml.h
/// visits it inside [trackers].
/// @ingroup drivers
#pragma once

#include <string>
#include <utility>

#include "config/toml_visit.h"
#include "drivers/plus/plus_settings.h"

namespace lungar::drivers {

/// [trackers.plus].
template <class Io>
void visit(Io& s, PlusConfig& p) {
  const std::pair<const char*, std::string*> names[] = {
      {"head", &p.head}, {"patient", &p.patient}, {"stylus", &p.stylus}};
  for (const auto& [key, name] : names) {
    s.text(key, *name);
    if constexpr (config::kReads<Io>) {
      // The tool is what comes before "To" in <Tool>To<Frame>Transform; OpenIGTLink carries <Tool>To<Frame> in 20.
      if (name->empty() || name->size() > 17 || name->find("To") != std::string::npos ||
          name->find_first_of(" =") != std::string::npos) {
        s.fail(key,
               "expected a PLUS tool name of 1 to 17 characters without \"To\", spaces or '=' (such as "
               "\"Reference\"), got \"" +
                   *name + "\"");
      }
    }
  }
  if constexpr (config::kReads<Io>) {
    if (p.head == p.patient || p.head == p.stylus || p.patient == p.stylus) {
      s.fail("patient", "expected a different tool for each of head, patient and stylus, got \"" + p.head + "\", \"" +
                            p.patient + "\", \"" + p.stylus + "\"");
    }
  }
  s.finish();
}

}  // namespace lungar::drivers
