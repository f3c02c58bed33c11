// The session record's writer and reader: a round trip, a torn last line and a corrupt line cut there and said, a bad
// header as one error, the file never overwritten, lines on the disk within the flush period, the debrief CSV, and
// the recorder's frame side allocating nothing.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../../sim/allocation_counter.h"
#include "config/base/clock.h"
#include "platform/record/session_record.h"
#include "platform/record/session_recorder.h"
#include "platform/record/timeline_csv.h"
#include "tests/file_text.h"

using namespace lungar;
using platform::record::SessionRecorder;

namespace {

/// A course that only says its pathologies (the recorder asks nothing else of it).
class LabelOnlyCourse final : public platform::LungCourse {
 public:
  const std::vector<sim::LungShape>& at(std::int64_t) override { return shapes_; }
  const std::string* pathologies_now() const override { return &label; }
  std::string label = "none";

 private:
  std::vector<sim::LungShape> shapes_;
};

/// The made-up session's time zero: now, so that the notes (stamped with the clock) fall among its frames.
const std::int64_t kMadeUpT0 = monotonic_ns();

/// Frame k of a made-up session at 50 Hz: dV a sine, the patient turning slowly.
platform::FrameState made_up_frame(int k) {
  platform::FrameState f;
  f.now_ns = kMadeUpT0 + static_cast<std::int64_t>(k) * 20'000'000;
  f.breath.t_s = k * 0.02;
  f.breath.dv_ml = 200.0 + 200.0 * std::sin(k * 0.1);
  f.breath.v_ml = 2400.0 + f.breath.dv_ml;
  f.breath.v_frc_ml = 2400.0;
  f.breath.p_cmh2o = 5.0 + k * 0.01;
  f.breath.phase = k % 50 < 25 ? sim::BreathPhase::Inspiration : sim::BreathPhase::Expiration;
  f.breath.breath = k / 50;
  f.lung_dv_ml = {f.breath.dv_ml * 0.45, f.breath.dv_ml * 0.55};
  f.patient.role = drivers::Role::Patient;
  f.patient.flags = drivers::kPoseValid;
  f.patient.set_position({10.0 + k, -20.0, 30.5});
  f.patient.set_orientation(Eigen::Quaterniond(Eigen::AngleAxisd(k * 0.01, Eigen::Vector3d::UnitX())));
  f.lung_origin_mm = Eigen::Vector3d(1.0, 2.0 + k, 3.0);
  f.lung_in_world = Eigen::Quaterniond(Eigen::AngleAxisd(k * 0.02, Eigen::Vector3d::UnitZ()));
  return f;
}

platform::record::SessionHeader made_up_header() {
  platform::record::SessionHeader h;
  h.station = "instructor";
  h.role = "instructor";
  h.classroom = "ward";
  h.started_utc = "2026-11-29T19:12:16Z";
  h.started_unix_s = 1795979536.25;
  h.lungar_version = "test";
  h.asset_path = "/data/lungs.lungbake";
  h.asset_name = "lungs.lungbake";
  h.nodes = 2032;
  h.lungs = {"left", "right"};
  h.pathologies = {"ards:0.5"};
  h.registration_translation_mm = {1.5, -2.0, 3.0};
  h.registration_rotation_wxyz = {0.0, 1.0, 0.0, 0.0};
  return h;
}

/// The index of the line of frame `k` among `lines`.
std::size_t line_of_frame(const std::vector<std::string>& lines, int k) {
  const std::string key = "{\"type\":\"frame\",\"i\":" + std::to_string(k) + ",";
  for (std::size_t n = 0; n < lines.size(); ++n)
    if (lines[n].find(key) != std::string::npos) return n;
  return lines.size();
}

/// The file's lines (each without its newline).
std::vector<std::string> record_lines(const std::filesystem::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

class SessionRecordFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = std::filesystem::temp_directory_path() /
          ("lungar_record_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
           std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    path = (dir / "class.lungarsession").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  /// 100 frames, the pathologies changing at frame 40, a timeline, two events and the stations; closed.
  void write_made_up_session() {
    auto course = std::make_shared<LabelOnlyCourse>();
    auto made = SessionRecorder::create(path, made_up_header(), kMadeUpT0, course);
    ASSERT_TRUE(made) << made.error();
    std::shared_ptr<SessionRecorder> r = made.take();
    r->note_timeline({{"ards:0.5"}, {{1.0, 2.0, "pneumothorax:right:30:tension", ""}}});
    for (int k = 0; k < 100; ++k) {
      if (k == 40) course->label = "ards:0.5, pneumothorax:right:30:tension (coming)";
      r->on_frame(made_up_frame(k));
    }
    r->note_event(1.25, "marker", "dr, smith", "trainee 2 palpated the \"apex\"");
    r->note_stations({{{"name", "trainee-1"}, {"state", "in_sync"}}});
    ASSERT_TRUE(r->close().ok());
  }

  std::filesystem::path dir;
  std::string path;
};

}  // namespace

TEST_F(SessionRecordFile, WhatIsWrittenIsReadBack) {
  write_made_up_session();
  auto read = platform::record::read_session_record(path);
  ASSERT_TRUE(read) << read.error();
  const auto& r = *read;
  EXPECT_TRUE(r.cut.empty()) << r.cut;
  EXPECT_TRUE(r.ended);
  EXPECT_EQ(r.dropped_frames, 0u);
  EXPECT_EQ(r.header.station, "instructor");
  EXPECT_EQ(r.header.nodes, 2032u);
  EXPECT_EQ(r.header.lungs, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(r.header.pathologies, std::vector<std::string>{"ards:0.5"});
  EXPECT_EQ(r.header.registration_rotation_wxyz[1], 1.0);
  EXPECT_EQ(r.header.registration_translation_mm[0], 1.5);
  ASSERT_EQ(r.frames.size(), 100u);
  for (int k = 0; k < 100; ++k) {
    SCOPED_TRACE(k);
    const platform::FrameState want = made_up_frame(k);
    const auto& got = r.frames[k];
    EXPECT_EQ(got.index, k);
    EXPECT_NEAR(got.s, k * 0.02, 1e-6);
    EXPECT_NEAR(got.breath.t_s, want.breath.t_s, 1e-6);
    EXPECT_NEAR(got.breath.dv_ml, want.breath.dv_ml, 1e-6);
    EXPECT_NEAR(got.lung_dv_ml[1], want.lung_dv_ml[1], 1e-6);
    EXPECT_NEAR(got.breath.p_cmh2o, want.breath.p_cmh2o, 1e-6);
    EXPECT_EQ(got.breath.phase, want.breath.phase);
    EXPECT_EQ(got.breath.breath, want.breath.breath);
    EXPECT_TRUE(std::isnan(got.breath.lung_dv_ml[0])) << "the source measured no lung: null, read as NaN";
    EXPECT_NEAR((got.patient.position() - want.patient.position()).norm(), 0.0, 1e-4);
    EXPECT_NEAR(got.patient.orientation().angularDistance(want.patient.orientation()), 0.0, 1e-8);
    EXPECT_NEAR((got.lung_origin_mm - want.lung_origin_mm).norm(), 0.0, 1e-4);
    EXPECT_NEAR(got.lung_in_world.angularDistance(want.lung_in_world), 0.0, 1e-8);
    EXPECT_EQ(got.pathologies, k < 40 ? "none" : "ards:0.5, pneumothorax:right:30:tension (coming)");
  }
  ASSERT_EQ(r.timelines.size(), 1u);
  EXPECT_EQ(r.timelines[0].timeline.events.at(0).add, "pneumothorax:right:30:tension");
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].user, "dr, smith");
  EXPECT_EQ(r.events[0].text, "trainee 2 palpated the \"apex\"");
  EXPECT_DOUBLE_EQ(r.events[0].t_s, 1.25);
  ASSERT_EQ(r.stations.size(), 1u);
  EXPECT_EQ(r.stations[0].stations[0]["name"], "trainee-1");
  // The pathologies are written when they change, not every frame: the record stays small.
  const std::string text = lungar::testing::file_text(path);
  std::size_t said = 0;
  for (std::size_t at = text.find("\"pathologies\":\""); at != std::string::npos;
       at = text.find("\"pathologies\":\"", at + 1))
    ++said;
  EXPECT_EQ(said, 2u);
}

TEST_F(SessionRecordFile, ATornLastLineIsCutOffAndSaid) {
  write_made_up_session();
  // A kill in the middle of frame 60's line.
  const std::vector<std::string> lines = record_lines(path);
  const std::size_t torn = line_of_frame(lines, 60);
  ASSERT_LT(torn, lines.size());
  std::size_t keep = 0;
  for (std::size_t k = 0; k < torn; ++k) keep += lines[k].size() + 1;
  std::filesystem::resize_file(path, keep + lines[torn].size() / 2);
  auto read = platform::record::read_session_record(path);
  ASSERT_TRUE(read) << "a torn last line is what a killed station leaves: not an error";
  EXPECT_EQ(read->frames.size(), 60u);
  EXPECT_FALSE(read->ended);
  EXPECT_NE(read->cut.find("line " + std::to_string(torn + 1) + ": torn"), std::string::npos) << read->cut;
}

TEST_F(SessionRecordFile, ACorruptLineInTheMiddleEndsTheRecordThere) {
  write_made_up_session();
  std::vector<std::string> lines = record_lines(path);
  const std::size_t corrupt = line_of_frame(lines, 29);
  ASSERT_LT(corrupt, lines.size());
  std::string& line = lines[corrupt];
  const std::size_t digit = line.find("\"dv_ml\":") + 9;
  line[digit] = line[digit] == '1' ? '2' : '1';  // one digit of dV changed: its CRC no longer matches
  std::ofstream out(path, std::ios::trunc | std::ios::binary);
  for (const std::string& l : lines) out << l << '\n';
  out.close();
  auto read = platform::record::read_session_record(path);
  ASSERT_TRUE(read) << read.error();
  EXPECT_EQ(read->frames.size(), 29u) << "nothing after a corrupt line is trusted";
  EXPECT_NE(read->cut.find("line " + std::to_string(corrupt + 1) + ": corrupt"), std::string::npos) << read->cut;
  EXPECT_FALSE(read->ended);
}

TEST_F(SessionRecordFile, ABadHeaderIsOneErrorNamingTheFileTheLineAndTheField) {
  const auto header_with = [&](const std::function<void(nlohmann::ordered_json&)>& change) {
    nlohmann::ordered_json j = platform::record::header_json(made_up_header());
    change(j);
    std::ofstream(path, std::ios::trunc) << platform::record::session_line(j.dump());
    auto read = platform::record::read_session_record(path);
    EXPECT_FALSE(read);
    return read ? std::string() : read.error();
  };
  const std::string version = header_with([](auto& j) { j["version"] = 2; });
  EXPECT_EQ(version.find(path + ":1: field 'version': expected 1"), 0u) << version;
  const std::string rotation = header_with([](auto& j) { j["registration"]["rotation_wxyz"] = "up"; });
  EXPECT_EQ(rotation.find(path + ":1: field 'registration.rotation_wxyz': expected an array of 4 numbers"), 0u)
      << rotation;
  const std::string nodes = header_with([](auto& j) { j["asset"].erase("nodes"); });
  EXPECT_EQ(nodes.find(path + ":1: field 'asset.nodes': expected an integer"), 0u) << nodes;
  for (const std::string& e : {version, rotation, nodes}) EXPECT_EQ(e.find('\n'), std::string::npos) << e;

  std::ofstream(path, std::ios::trunc) << "t_s,value\n0.0,1.0\n";  // a breath trace given by mistake
  auto not_one = platform::record::read_session_record(path);
  ASSERT_FALSE(not_one);
  EXPECT_EQ(not_one.error().find(path + ":1: not a lungar session record"), 0u) << not_one.error();
}

TEST_F(SessionRecordFile, ARecordIsNeverOverwritten) {
  std::ofstream(path) << "another class\n";
  auto made = SessionRecorder::create(path, made_up_header(), kMadeUpT0);
  ASSERT_FALSE(made);
  EXPECT_NE(made.error().find(path + ": cannot create the session record: File exists"), std::string::npos)
      << made.error();
  EXPECT_EQ(lungar::testing::file_text(path), "another class\n");
  auto nowhere = SessionRecorder::create((dir / "no-such-folder" / "x.lungarsession").string(), made_up_header(), 0);
  EXPECT_FALSE(nowhere);
}

TEST_F(SessionRecordFile, FramesReachTheFileWithinTheFlushPeriodWithoutAClose) {
  // What a SIGKILL would leave: the lines the writer handed to the kernel, read while the recorder still runs.
  auto made = SessionRecorder::create(path, made_up_header(), kMadeUpT0);
  ASSERT_TRUE(made) << made.error();
  for (int k = 0; k < 10; ++k) (*made)->on_frame(made_up_frame(k));
  std::this_thread::sleep_for(std::chrono::duration<double>(2 * SessionRecorder::kFlushS + 0.02));
  auto read = platform::record::read_session_record(path);
  ASSERT_TRUE(read) << read.error();
  EXPECT_EQ(read->frames.size(), 10u);
  EXPECT_FALSE(read->ended);
  EXPECT_TRUE(read->cut.empty()) << "every line handed over is whole: " << read->cut;
}

TEST_F(SessionRecordFile, TheDebriefSheetListsTheEventsInTimeOrderWithDvAndThePathologies) {
  write_made_up_session();
  auto read = platform::record::read_session_record(path);
  ASSERT_TRUE(read) << read.error();
  const std::string csv = platform::record::timeline_csv(*read);
  std::istringstream in(csv);
  std::vector<std::string> rows;
  for (std::string row; std::getline(in, row);) rows.push_back(row);
  ASSERT_GE(rows.size(), 4u) << csv;
  EXPECT_EQ(rows[0], "session_s,breath_s,kind,user,text,pathologies,dv_ml");
  // The pathologies drawn at frame 40 (0.8 s), quoted for their comma, and the marker with its quotes doubled.
  EXPECT_NE(csv.find("0.800,0.800,pathologies drawn,,\"ards:0.5, pneumothorax:right:30:tension (coming)\""),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find(",marker,\"dr, smith\",\"trainee 2 palpated the \"\"apex\"\"\","), std::string::npos) << csv;
  EXPECT_NE(csv.find(",pathology timeline,,\"ards:0.5, then pneumothorax:right:30:tension comes at 1.0 s over 2.0 s\""),
            std::string::npos)
      << csv;
  for (std::size_t k = 2; k < rows.size(); ++k)
    EXPECT_LE(std::stod(rows[k - 1]), std::stod(rows[k])) << "in time order: " << csv;
}

TEST_F(SessionRecordFile, TheRecordersFrameSideAllocatesNothing) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer owns operator new";
#else
  auto course = std::make_shared<LabelOnlyCourse>();
  course->label = "ards:0.5, pneumothorax:right:30:tension (coming), and a long enough label to need the heap";
  auto made = SessionRecorder::create(path, made_up_header(), kMadeUpT0, course);
  ASSERT_TRUE(made) << made.error();
  std::vector<platform::FrameState> frames;
  for (int k = 0; k < 300; ++k) frames.push_back(made_up_frame(k));
  SessionRecorder& recorder = **made;
  const long before = lungar::testing::g_thread_allocations;
  for (const platform::FrameState& f : frames) recorder.on_frame(f);
  EXPECT_EQ(lungar::testing::g_thread_allocations - before, 0);
  ASSERT_TRUE(recorder.close().ok());
  auto read = platform::record::read_session_record(path);
  ASSERT_TRUE(read) << read.error();
  EXPECT_EQ(read->frames.size(), 300u);
#endif
}
