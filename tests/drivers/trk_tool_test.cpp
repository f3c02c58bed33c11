// Tests of the lungar-trk tool as a user runs it: synth -> info -> dump -> cut, and one-line errors.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "drivers/igtl/igtl_messages.h"
#include "drivers/plus/plus_sequence.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_reader.h"
#include "drivers/trk/trk_writer.h"

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
  // The rate is each sensor's, as the header's rate_hz=100 (it was the records', twice that).
  const std::size_t rate = r.out.find("\nrate_hz: ");
  ASSERT_NE(rate, std::string::npos) << r.out;
  EXPECT_NEAR(std::stod(r.out.substr(rate + 10)), 100.0, 1.5) << r.out;
  EXPECT_NE(r.out.find("each sensor's reports per second: head "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("records_per_s: "), std::string::npos) << r.out;
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
  ASSERT_TRUE(log) << log.error();
  EXPECT_EQ(log->records.size(), 50u);  // ticks 25..49, two reports each
  EXPECT_EQ(log->header.description.find("trajectory=head_orbit") != std::string::npos, true);
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
  EXPECT_EQ(r.out, "lungar-trk: --trajectory: expected static | upright_to_supine | head_orbit | bedside, got \"cartwheel\"\n");
  EXPECT_FALSE(fs::exists(dir() / "x.trk"));
  r = run("--version");
  EXPECT_EQ(r.rc, 0);
  EXPECT_EQ(r.out.rfind("lungar-trk ", 0), 0u);
}

// An orientation-only profile: synth writes reports without position bytes, and dump shows each role's fixed
// position in the position columns (read back through the log's own layout).
TEST(TrkTool, DumpOfAnOrientationOnlyLogShowsTheFixedPosition) {
  const std::string a = (dir() / "imu.trk").string();
  const std::string profile = std::string(LUNGAR_SOURCE_DIR) + "/config/trackers/sparkfun-9dof-razor.toml";
  ToolRun r = run("synth " + a + " --config " + profile + " --trajectory head_orbit --seconds 0.1 --rate-hz 100");
  ASSERT_EQ(r.rc, 0) << r.out;
  r = run("dump " + a + " --format csv");
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find(",head,ok,0.0000,-700.0000,1300.0000,"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("patient"), std::string::npos) << r.out;  // the profile feeds the head only
}

// OpenIGTLink records (source igtl) decode as messages, each row saying what became of its message.
TEST(TrkTool, DumpDecodesOpenIgtlinkRecordsAsMessages) {
  namespace d = lungar::drivers;
  const std::string a = (dir() / "igtl.trk").string();
  d::TrkWriter w;
  d::TrkHeader h;
  h.description = "source=igtl\n";
  h.layout_toml = d::tracker_config_to_toml(d::TrackerConfig{});
  ASSERT_EQ(w.open(a, h, d::TrkWriter::Mode::Atomic).error(), "");
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topRightCorner<3, 1>() = Eigen::Vector3d(10, -20, 1000);
  const auto time = d::IgtlTime::from_ns(1'700'000'000'000'000'000ull);
  ASSERT_TRUE(w.append(d::TrkSource::Igtl, 1'000'000'000, d::igtl_transform_message("PatientToTracker", m, time)));
  ASSERT_TRUE(w.append(d::TrkSource::Igtl, 1'016'000'000, d::igtl_status_message("Server", time)));
  ASSERT_TRUE(w.append(d::TrkSource::Igtl, 1'032'000'000, d::igtl_transform_message("ProbeToTracker", m, time)));
  ASSERT_EQ(w.commit().error(), "");
  ToolRun r = run("dump " + a + " --format csv");
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find("\n0,1000000000,0,patient,ok,10.0000,-20.0000,1000.0000,1.000000,0.000000,0.000000,0.000000\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n1,1016000000,,,unknown message type,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n2,1032000000,,,ignored,"), std::string::npos) << r.out;
  r = run("info " + a);
  EXPECT_NE(r.out.find("source igtl: 3"), std::string::npos) << r.out;
}

TEST(TrkTool, ServeIgtlStopsAfterItsSecondsAndBadOptionsAreOneLine) {
  ToolRun r = run("serve-igtl --port 0 --seconds 0.2");
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find("serving OpenIGTLink on 127.0.0.1:"), std::string::npos) << r.out;
  r = run("serve-igtl --port 0 --trajectory cartwheel");
  EXPECT_EQ(r.rc, 1);
  EXPECT_EQ(r.out, "lungar-trk: --trajectory: expected static | upright_to_supine | head_orbit | bedside, got \"cartwheel\"\n");
  r = run("serve-igtl --address 300.1.2.3 --port 0");
  EXPECT_EQ(r.rc, 1);
  EXPECT_EQ(r.out, "lungar-trk: 300.1.2.3:0: expected an IPv4 address and a port in [0, 65535]\n");
}

TEST(TrkTool, ToPlusWritesASequenceOfEveryRecordAndRefusesAMissingLog) {
  const fs::path trk = dir() / "synth.trk", mha = dir() / "synth.igs.mha";
  ASSERT_EQ(run("synth " + trk.string() + " --seconds 2").rc, 0);
  const auto log = lungar::drivers::load_trk(trk.string());
  ASSERT_TRUE(log) << log.error();
  const ToolRun converted = run("to-plus " + trk.string() + " " + mha.string());
  ASSERT_EQ(converted.rc, 0) << converted.out;
  const auto seq = lungar::drivers::read_plus_sequence(mha.string());
  ASSERT_TRUE(seq) << seq.error();
  EXPECT_EQ(seq->frames.size(), log->records.size());
  EXPECT_NE(converted.out.find(std::to_string(log->records.size()) + " frames"), std::string::npos) << converted.out;
  const ToolRun missing = run("to-plus " + (dir() / "none.trk").string() + " " + (dir() / "none.igs.mha").string());
  EXPECT_EQ(missing.rc, 1) << missing.out;
  EXPECT_FALSE(fs::exists(dir() / "none.igs.mha"));
}
