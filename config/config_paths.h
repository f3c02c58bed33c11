/// @file config_paths.h
/// @brief Where lungar looks for its settings and puts its files, as a Debian program does (XDG base directories):
/// `--config` wins (repeated: the files merged, later over earlier), then `$XDG_CONFIG_HOME/lungar/lungar.toml`, then
/// `/etc/lungar/lungar.toml`, then the built-in defaults; baked assets in `$XDG_CACHE_HOME/lungar/`, snapshots, stats
/// and recordings in `$XDG_STATE_HOME/lungar/`.
/// @ingroup config
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::config {

/// The folders the lookup depends on, read once from the environment (tests make their own).
struct XdgDirs {
  std::string home;           ///< $HOME
  std::string config_home;    ///< $XDG_CONFIG_HOME as set; empty or relative: unset (the spec ignores relative ones)
  std::string cache_home;     ///< $XDG_CACHE_HOME
  std::string state_home;     ///< $XDG_STATE_HOME
  std::string cache_override; ///< $LUNGAR_CACHE_DIR: the cache folder itself, for tests and CI
  std::string system_config_dir = "/etc/lungar";

  static XdgDirs from_environment();
};

/// `$XDG_CONFIG_HOME/lungar/lungar.toml`, or `~/.config/lungar/lungar.toml`.
std::string user_config_file(const XdgDirs& d);
/// `/etc/lungar/lungar.toml` (system_config_dir).
std::string system_config_file(const XdgDirs& d);
/// `$LUNGAR_CACHE_DIR`, else `$XDG_CACHE_HOME/lungar`, else `~/.cache/lungar`: baked assets.
std::string cache_dir(const XdgDirs& d);
/// `$XDG_STATE_HOME/lungar`, else `~/.local/state/lungar`: snapshots, stats, recordings with no path given.
std::string state_dir(const XdgDirs& d);

/// Which settings files a run uses and why; none means the built-in defaults. Of several (`--config` repeated),
/// a later file's keys win over an earlier one's.
struct ConfigChoice {
  std::vector<std::string> paths;
  std::string reason;  ///< e.g. "--config", "$XDG_CONFIG_HOME", "/etc/lungar", "none of ... exists"
  /// The files joined ("a.toml + b.toml"), or "built-in defaults".
  std::string files() const;
  /// The start-up log line: "config: /etc/lungar/lungar.toml (no ~/.config/lungar/lungar.toml)".
  std::string describe() const;
};

/// `--config` (when given, once or more) wins even when a file does not exist (loading then names it); otherwise
/// the first of the user's and the system's file that exists; otherwise the defaults.
ConfigChoice choose_config(const std::vector<std::string>& cli_paths, const XdgDirs& d);
/// One `--config` (empty: none given).
ConfigChoice choose_config(const std::string& cli_path, const XdgDirs& d);

}  // namespace lungar::config
