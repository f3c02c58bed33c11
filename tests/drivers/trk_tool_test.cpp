// Tests of the lungar-trk tool as a user runs it: synth -> info -> dump -> cut, and one-line errors.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "drivers/trk/trk_reader.h"

namespace fs = std::filesystem;

namespace {

const std::string kTool = std::string(LUNGAR_BINARY_DIR) + "/drivers/lungar-trk";

struct ToolRun {
  int rc;
  std::string out;  // stdout and stderr
};

ToolRun run(const std::string& args) {
  ToolRun r{-1, {}};
  FILE* p = ::popen((kTool + " " + args + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

fs::path dir() {
  const fs::path d = fs::temp_directory_path() / ("lungar_trk_tool_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(TrkTool, SynthInfoDumpCut) {
  const std::string a = (dir() / "a.trk").string(), b = (dir() / "b.trk").string();
  ToolRun r = run("synth " + a + " --trajectory head_orbit --seconds 1 --rate-hz 100");
  ASSERT_EQ(r.rc, 0) << r.out;
  r = run("info " + a);
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find("records: 200"), std::string::npos) << r.out;  // 2 sensors x 100 ticks
  EXPECT_NE(r.out.find("trajectory=head_orbit"), std::string::npos) << r.out;
  r = run("dump " + a + " --format csv");
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_EQ(r.out.rfind("record,t_arrival_ns,t_device_ns,role,status,", 0), 0u);
  std::size_t lines = 0;
  for (char c : r.out) lines += c == '\n';
  EXPECT_EQ(lines, 201u);
  r = run("dump " + a + " --format jsonl");
  EXPECT_NE(r.out.find("\"role\":\"patient\",\"status\":\"ok\""), std::string::npos);
  r = run("cut " + a + " " + b + " --from 0.25 --to 0.5");
  ASSERT_EQ(r.rc, 0) << r.out;
  auto log = lungar::drivers::load_trk(b);
  ASSERT_TRUE(log.log) << log.error;
  EXPECT_EQ(log.log->records.size(), 50u);  // ticks 25..49, two reports each
  EXPECT_EQ(log.log->header.description.find("trajectory=head_orbit") != std::string::npos, true);
}

TEST(TrkTool, BadInputIsOneLineAndExitOne) {
  const std::string bad = (dir() / "bad.trk").string();
  std::FILE* f = std::fopen(bad.c_str(), "wb");
  ASSERT_TRUE(f);
  std::fputs("not a tracker log at all", f);
  std::fclose(f);
  ToolRun r = run("info " + bad);
  EXPECT_EQ(r.rc, 1);
  EXPECT_EQ(r.out, "lungar-trk: " + bad + ": expected the magic \"LUNGATRK\": not a .trk log, at byte 0\n");
  r = run("synth " + (dir() / "x.trk").string() + " --trajectory cartwheel");
  EXPECT_EQ(r.rc, 1);
  EXPECT_EQ(r.out, "lungar-trk: --trajectory: expected static | upright_to_supine | head_orbit, got \"cartwheel\"\n");
  EXPECT_FALSE(fs::exists(dir() / "x.trk"));
  r = run("--version");
  EXPECT_EQ(r.rc, 0);
  EXPECT_EQ(r.out.rfind("lungar-trk ", 0), 0u);
}
