/// @file breath_source_names.h
/// @brief The breath sources' names, as `--breath`, `[breathing] source` and the stats JSON spell them: one table,
///        read by the settings' check (config/), the factory that picks a source and the sources' own stats
///        (drivers/breath/), and the command line's help. In the base because config/ checks the setting and
///        does not depend on drivers/.
/// @ingroup base
#pragma once

#include <string>

#include "config/base/enum_names.h"

namespace lungar {

/// A kind of breath source. A trace has no keyword: any text that names none of the others is a file.
enum class BreathSource { Model, Trace, Marker, Amm, OpenIce };
inline constexpr EnumNames<BreathSource, 5> kBreathSourceNames{{{{BreathSource::Model, "model"},
                                                                 {BreathSource::Trace, "trace"},
                                                                 {BreathSource::Marker, "marker"},
                                                                 {BreathSource::Amm, "amm"},
                                                                 {BreathSource::OpenIce, "openice"}}}};

/// The name and the ':' its argument follows: "marker:" (a role), "openice:" (a metric).
inline std::string breath_source_prefix(BreathSource s) { return std::string(kBreathSourceNames.name(s)) + ':'; }

/// Every form a source is written in, for an error's "expected ...": "model", a trace file, "marker:ROLE",
/// "amm[@DOMAIN]" or "openice[:METRIC][@DOMAIN]".
inline std::string breath_source_forms() {
  auto quoted = [](BreathSource s, const char* rest) {
    return '"' + (kBreathSourceNames.name(s) + std::string(rest)) + '"';
  };
  return quoted(BreathSource::Model, "") + ", a trace file, " + quoted(BreathSource::Marker, ":ROLE") + ", " +
         quoted(BreathSource::Amm, "[@DOMAIN]") + " or " + quoted(BreathSource::OpenIce, "[:METRIC][@DOMAIN]");
}

}  // namespace lungar
