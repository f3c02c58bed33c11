/// @file config_paths.cpp
/// @brief The XDG lookup of settings, cache and state folders (config_paths.h).
#include "config/config_paths.h"

#include <cstdlib>
#include <filesystem>

#include "config/toml_layers.h"

namespace lungar::config {

namespace {

/// An XDG variable as the base-directory spec reads it: unset, empty or relative means "use the default".
std::string absolute_env(const char* name) {
  const char* v = std::getenv(name);
  if (v == nullptr || v[0] != '/') return "";
  return v;
}

/// `xdg` when set, else `$HOME/fallback`; "" when neither is known.
std::string base_dir(const std::string& xdg, const std::string& home, const char* fallback) {
  if (!xdg.empty()) return xdg;
  if (home.empty()) return "";
  return home + "/" + fallback;
}

bool is_file(const std::string& path) {
  std::error_code ec;
  return !path.empty() && std::filesystem::is_regular_file(path, ec);
}

}  // namespace

XdgDirs XdgDirs::from_environment() {
  XdgDirs d;
  if (const char* h = std::getenv("HOME")) d.home = h;
  d.config_home = absolute_env("XDG_CONFIG_HOME");
  d.cache_home = absolute_env("XDG_CACHE_HOME");
  d.state_home = absolute_env("XDG_STATE_HOME");
  if (const char* c = std::getenv("LUNGAR_CACHE_DIR")) d.cache_override = c;
  return d;
}

std::string user_config_file(const XdgDirs& d) {
  const std::string base = base_dir(d.config_home, d.home, ".config");
  return base.empty() ? "" : base + "/lungar/lungar.toml";
}

std::string system_config_file(const XdgDirs& d) { return d.system_config_dir + "/lungar.toml"; }

std::string cache_dir(const XdgDirs& d) {
  if (!d.cache_override.empty()) return d.cache_override;
  const std::string base = base_dir(d.cache_home, d.home, ".cache");
  // No HOME at all (a bare service): a private folder under the temporary directory rather than the working one.
  return base.empty() ? (std::filesystem::temp_directory_path() / "lungar-cache").string() : base + "/lungar";
}

std::string state_dir(const XdgDirs& d) {
  const std::string base = base_dir(d.state_home, d.home, ".local/state");
  return base.empty() ? (std::filesystem::temp_directory_path() / "lungar-state").string() : base + "/lungar";
}

std::string ConfigChoice::files() const { return paths.empty() ? "built-in defaults" : join_paths(paths); }

std::string ConfigChoice::describe() const { return "config: " + files() + " (" + reason + ")"; }

ConfigChoice choose_config(const std::string& cli_path, const XdgDirs& d) {
  return choose_config(cli_path.empty() ? std::vector<std::string>{} : std::vector<std::string>{cli_path}, d);
}

ConfigChoice choose_config(const std::vector<std::string>& cli_paths, const XdgDirs& d) {
  if (!cli_paths.empty()) return {cli_paths, "--config"};
  const std::string user = user_config_file(d);
  const std::string system = system_config_file(d);
  if (is_file(user)) return {{user}, d.config_home.empty() ? "the user's, ~/.config" : "the user's, $XDG_CONFIG_HOME"};
  const std::string no_user = "no " + (user.empty() ? std::string("$HOME") : user);
  if (is_file(system)) return {{system}, "the system's; " + no_user};
  return {{}, "no --config, " + no_user + ", no " + system};
}

}  // namespace lungar::config
