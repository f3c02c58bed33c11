/// @file lungar_main.cpp
/// @brief The `lungar` entry point: parses the command line, loads the config, runs the runtime.
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "config/settings_load.h"
#include "lungar/version.h"

int main(int argc, char** argv) {
  CLI::App app{"lungar: breathing 3-D lungs superimposed on a patient simulator, for a head-mounted display"};
  app.set_version_flag("--version", std::string("lungar ") + LUNGAR_VERSION);
  std::string config_path;
  app.add_option("--config", config_path, "settings TOML (default: built-in defaults, see config/default.toml)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  lungar::config::Settings settings;
  if (!config_path.empty()) {
    auto loaded = lungar::config::load_settings(config_path);
    if (!loaded) {
      std::fprintf(stderr, "lungar: %s\n", loaded.error.c_str());
      return 2;
    }
    settings = *loaded.settings;
  }
  std::cout << lungar::config::summarize(settings) << "\n";
  return 0;
}
