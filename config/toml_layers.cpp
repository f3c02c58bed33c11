/// @file toml_layers.cpp
/// @brief Several TOML files merged into one tree, keeping each value's source (toml_layers.h).
#include "config/toml_layers.h"

#include <utility>

#include "config/toml_section.h"

namespace lungar::config {

void merge_toml(toml::table& base, toml::table&& over) {
  for (auto&& [key, value] : over) {
    toml::table* below = base[key.str()].as_table();
    if (below != nullptr && value.is_table()) {
      merge_toml(*below, std::move(*value.as_table()));
    } else {
      // Moving (not copying) keeps the node's source: a copy would forget which file and line it came from.
      base.insert_or_assign(key, std::move(value));
    }
  }
}

Result<toml::table> parse_toml_files(const std::vector<std::string>& paths, const char* what) {
  toml::table merged;
  for (const std::string& path : paths) {
    auto text = read_toml_file(path, what);
    if (!text) return text.with_context("");
    auto parsed = parse_toml(*text, path);
    if (!parsed) return parsed.with_context("");
    merge_toml(merged, std::move(*parsed));
  }
  return merged;
}

std::string source_file(const toml::node& node, const std::string& fallback) {
  const auto& path = node.source().path;
  return path && !path->empty() ? *path : fallback;
}

std::string join_paths(const std::vector<std::string>& paths) {
  std::string joined;
  for (const std::string& p : paths) joined += (joined.empty() ? "" : " + ") + p;
  return joined;
}

}  // namespace lungar::config
