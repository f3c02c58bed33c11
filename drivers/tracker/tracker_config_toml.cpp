/// @file tracker_config_toml.cpp
/// @brief The [trackers] table from TOML text or a file, and back to text: visit() over the reader or the writer.
#include "drivers/tracker/tracker_config_toml.h"

#include "config/toml_layers.h"

namespace lungar::drivers {

namespace {

Result<TrackerConfig> read_trackers(const toml::table& tree, const std::string& name) {
  TrackerConfig t;
  try {
    config::TomlSection top(&tree, "", name);
    config::TomlSection trackers = top.section("trackers");
    visit(trackers, t);
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  return t;
}

}  // namespace

Result<TrackerConfig> tracker_config_from_toml(const std::string& text, const std::string& name) {
  auto parsed = config::parse_toml(text, name);
  if (!parsed) return parsed.with_context("");
  return read_trackers(*parsed, name);
}

Result<TrackerConfig> tracker_config_from_file(const std::string& path) {
  return tracker_config_from_files(std::vector<std::string>{path});
}

Result<TrackerConfig> tracker_config_from_files(const std::vector<std::string>& paths) {
  auto tree = config::parse_toml_files(paths, "config");
  if (!tree) return tree.with_context("");
  return read_trackers(*tree, config::join_paths(paths));
}

std::string tracker_config_to_toml(const TrackerConfig& t) {
  config::TomlWriter document;
  config::TomlWriter trackers = document.section("trackers");
  TrackerConfig fields = t;  // visit() takes what it may read into; the writer only reads it
  visit(trackers, fields);
  return document.str();
}

}  // namespace lungar::drivers
