/// @file command_line.h
/// @brief The one way every tool ends on a command line CLI11 refuses: "TOOL: message (see --help)" on one line of
/// stderr and exit 2 (a usage error, as the tools' own checks of their options exit), instead of CLI11's own
/// message without the tool's name and its exit codes 104-114; --help and --version still print and exit 0.
/// Header only: the tools that include it link CLI11 already (lungar_base does not).
/// @ingroup base
#pragma once

#include <cstdio>
#include <iostream>
#include <string_view>

#include <CLI/App.hpp>
#include <CLI/Error.hpp>

namespace lungar {

/// The exit status of a command line that did not parse, as usage errors exit.
inline constexpr int kUsageExitCode = 2;

/// For `catch (const CLI::ParseError& e)` around `app.parse(argc, argv)`: --help and --version (CLI11's "errors"
/// that succeed) print as CLI11 prints them and return 0; any other prints "TOOL: message (see --help)" on stderr
/// and returns kUsageExitCode.
inline int exit_on_parse_error(const CLI::App& app, const CLI::ParseError& e, std::string_view tool) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e, std::cout, std::cerr);
  std::fprintf(stderr, "%.*s: %s (see --help)\n", static_cast<int>(tool.size()), tool.data(), e.what());
  return kUsageExitCode;
}

}  // namespace lungar
