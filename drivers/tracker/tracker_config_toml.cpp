/// @file tracker_config_toml.cpp
/// @brief The [trackers] table from TOML text or a file, and back to text: visit() over the reader or the writer.
#include "drivers/tracker/tracker_config_toml.h"

namespace lungar::drivers {

Result<TrackerConfig> tracker_config_from_toml(const std::string& text, const std::string& name) {
  auto parsed = config::parse_toml(text, name);
  if (!parsed) return parsed.with_context("");
  TrackerConfig t;
  try {
    config::TomlSection top(&*parsed, "", name);
    config::TomlSection trackers = top.section("trackers");
    visit(trackers, t);
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  return t;
}

Result<TrackerConfig> tracker_config_from_file(const std::string& path) {
  auto text = config::read_toml_file(path, "config");
  if (!text) return text.with_context("");
  return tracker_config_from_toml(*text, path);
}

std::string tracker_config_to_toml(const TrackerConfig& t) {
  config::TomlWriter document;
  config::TomlWriter trackers = document.section("trackers");
  TrackerConfig fields = t;  // visit() takes what it may read into; the writer only reads it
  visit(trackers, fields);
  return document.str();
}

}  // namespace lungar::drivers
