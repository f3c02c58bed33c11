/// @file toml_visit.h
/// @brief The field-list idiom of the settings: one visit(Io&, Table&) per table names each key once, with its range
/// and unit, and runs over config::TomlSection (reading over the defaults; every problem one error naming file,
/// line and key) or over config::TomlWriter (writing every key, doubles at full precision), so that what is written
/// reads back equal. kReads<Io> guards what only reading does: the checks across keys and the parsing of text.
/// @ingroup config
#pragma once

#include <type_traits>

#include "config/toml_section.h"
#include "config/toml_writer.h"

namespace lungar::config {

/// True when a visit() runs over a TOML section being read, false when it writes.
template <class Io>
inline constexpr bool kReads = std::is_same_v<Io, TomlSection>;

}  // namespace lungar::config
