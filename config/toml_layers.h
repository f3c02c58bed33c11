/// @file toml_layers.h
/// @brief Several TOML files read as one: each later file's keys over the earlier ones', tables merged key by key,
/// every value keeping the file and line it came from (so an error, and a relative path, still name their own file).
/// @ingroup config
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "config/base/result.h"

namespace lungar::config {

/// Moves `over`'s keys into `base`: a table into a table merges, anything else replaces (arrays whole).
void merge_toml(toml::table& base, toml::table&& over);

/// The files parsed in order and merged (merge_toml); the first unreadable or malformed one is the error.
/// `what` names them in a read error ("config").
Result<toml::table> parse_toml_files(const std::vector<std::string>& paths, const char* what);

/// The file a node was read from (its source), or `fallback` when it was made in memory.
std::string source_file(const toml::node& node, const std::string& fallback);

/// The paths joined as they are named in a log line or an error: "a.toml + b.toml".
std::string join_paths(const std::vector<std::string>& paths);

}  // namespace lungar::config
