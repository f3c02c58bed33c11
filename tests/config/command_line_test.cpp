/// @file command_line_test.cpp
/// @brief lungar::exit_on_parse_error, the one end of every tool's refused command line: "TOOL: message (see
///        --help)" on one line and exit 2, where CLI11's own exit codes were 104-114 without the tool's name; --help
///        and --version still succeed.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "config/base/command_line.h"

namespace {

struct Ended {
  int rc = -1;
  std::string err;
};

/// `args` parsed by a small tool "lungar-x" with --count N and a --version flag; what exit_on_parse_error said.
Ended parse(std::vector<std::string> args) {
  CLI::App app{"a tool"};
  int count = 0;
  app.add_option("--count", count, "a number")->check(CLI::Range(1, 9));
  app.set_version_flag("--version", "lungar-x 1.0");
  std::reverse(args.begin(), args.end());  // CLI11 takes a reversed vector
  Ended e;
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  try {
    app.parse(args);
    e.rc = 0;
  } catch (const CLI::ParseError& error) {
    e.rc = lungar::exit_on_parse_error(app, error, "lungar-x");
  }
  (void)::testing::internal::GetCapturedStdout();
  e.err = ::testing::internal::GetCapturedStderr();
  return e;
}

}  // namespace

TEST(ExitOnParseError, ARefusedCommandLineIsOneLineNamingTheToolAndExitsTwo) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--no-such-option"}, {"--count", "12"}, {"--count", "many"}, {"--count"}}) {
    const Ended e = parse(args);
    EXPECT_EQ(e.rc, 2) << args.front() << ": " << e.err;
    EXPECT_EQ(e.err.rfind("lungar-x: ", 0), 0u) << e.err;
    const std::string end = " (see --help)\n";
    ASSERT_GT(e.err.size(), end.size()) << e.err;
    EXPECT_EQ(e.err.substr(e.err.size() - end.size()), end) << e.err;
    EXPECT_EQ(e.err.find('\n'), e.err.size() - 1) << "one line: " << e.err;
  }
}

TEST(ExitOnParseError, HelpAndVersionStillSucceed) {
  EXPECT_EQ(parse({"--help"}).rc, 0);
  EXPECT_EQ(parse({"--version"}).rc, 0);
  EXPECT_EQ(parse({"--count", "3"}).rc, 0);
}
