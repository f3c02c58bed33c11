/// @file plus_sequence_test.cpp
/// @brief PLUS tracked sequences (.igs.mha): the header read, INVALID transforms counted and never applied, bad
///        files refused in one line naming the line and the field, and the sequence replayed as a tracker.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "drivers/plus/plus_replay.h"
#include "drivers/plus/plus_sequence.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "tests/drivers/test_data.h"
#include "tests/drivers/tracker_test_support.h"

namespace lungar::drivers {
namespace {

/// A row-major 4 x 4 as PLUS writes it: a rotation of `angle` about z and a translation.
std::string matrix_text(double angle, double x, double y, double z) {
  std::ostringstream o;
  o << std::cos(angle) << " " << -std::sin(angle) << " 0 " << x << " " << std::sin(angle) << " " << std::cos(angle)
    << " 0 " << y << " 0 0 1 " << z << " 0 0 0 1";
  return o.str();
}

/// Five frames of a Reference and a Stylus tracked by the tracker; the stylus is INVALID in frame 2.
std::string sequence_text() {
  std::ostringstream o;
  o << "ObjectType = Image\nNDims = 3\nAnatomicalOrientation = RAI\nBinaryData = True\nCompressedData = False\n"
       "DimSize = 1 1 5\nElementSpacing = 1 1 1\nOffset = 0 0 0\nTransformMatrix = 1 0 0 0 1 0 0 0 1\n"
       "ElementType = MET_UCHAR\nKw:Size = 1 1\nUltrasoundImageOrientation = MF\n";
  for (int f = 0; f < 5; ++f) {
    char n[16];
    std::snprintf(n, sizeof n, "%04d", f);
    o << "Seq_Frame" << n << "_FrameNumber = " << f << "\n";
    o << "Seq_Frame" << n << "_ReferenceToTrackerTransform = " << matrix_text(0.1, 100, 200, 300) << "\n";
    o << "Seq_Frame" << n << "_ReferenceToTrackerTransformStatus = OK\n";
    o << "Seq_Frame" << n << "_StylusToTrackerTransform = " << matrix_text(0.2 * f, 10.0 * f, -5, 40) << "\n";
    o << "Seq_Frame" << n << "_StylusToTrackerTransformStatus = " << (f == 2 ? "INVALID" : "OK") << "\n";
    o << "Seq_Frame" << n << "_Timestamp = " << 1000.0 + 0.05 * f << "\n";
    o << "Seq_Frame" << n << "_ImageStatus = INVALID\n";
  }
  o << "ElementDataFile = LOCAL\n";
  return o.str() + std::string(5, '\0');  // the 1 x 1 x 5 placeholder image
}

struct TempFile {
  std::filesystem::path path;
  explicit TempFile(const std::string& text, const std::string& name = "s.igs.mha") {
    const auto dir = std::filesystem::temp_directory_path() / ("lungar_plus_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    path = dir / name;
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempFile() { std::filesystem::remove_all(path.parent_path()); }
};

TEST(PlusSequence, ReadsFramesTransformsAndStatuses) {
  TempFile f(sequence_text());
  auto seq = read_plus_sequence(f.path.string());
  ASSERT_TRUE(seq) << seq.error();
  ASSERT_EQ(seq->frames.size(), 5u);
  EXPECT_EQ(seq->invalid_transforms, 1);
  EXPECT_DOUBLE_EQ(seq->frames[3].timestamp_s, 1000.15);
  const PlusTransform* stylus = seq->frames[3].find("Stylus");
  ASSERT_NE(stylus, nullptr);
  EXPECT_EQ(stylus->frame, "Tracker");
  EXPECT_DOUBLE_EQ(stylus->matrix(0, 3), 30.0);
  EXPECT_NEAR(stylus->matrix(1, 0), std::sin(0.6), 1e-6);
  EXPECT_FALSE(seq->frames[2].find("Stylus")->valid);
  EXPECT_TRUE(seq->frames[2].find("Reference")->valid);
}

// The shipped sample (also the fuzzer's seed), as PLUS writes it: three frames, the stylus INVALID in the second.
TEST(PlusSequence, TheShippedSampleReads) {
  auto seq = read_plus_sequence(lungar::testing::tracker_data("two_tools.igs.mha"));
  ASSERT_TRUE(seq) << seq.error();
  EXPECT_EQ(seq->frames.size(), 3u);
  EXPECT_EQ(seq->invalid_transforms, 1);
  EXPECT_DOUBLE_EQ(seq->frames[2].find("Reference")->matrix(2, 3), 300.0);
}

TEST(PlusSequence, BadFilesAreRefusedNamingTheLineAndTheField) {
  const std::string good = sequence_text();
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const std::pair<std::string, std::string> cases[] = {
      {replaced("_StylusToTrackerTransform = 1 ", "_StylusToTrackerTransform = "),
       "Seq_Frame0000_StylusToTrackerTransform: expected 16 finite numbers"},
      {replaced("TransformStatus = INVALID", "TransformStatus = MAYBE"), "expected OK or INVALID"},
      {replaced("Seq_Frame0004_Timestamp", "Seq_Frame0004_Timestump"), "Seq_Frame4_Timestamp: expected one"},
      {replaced("ObjectType = Image", "ObjectType = Mesh"), ":1: ObjectType: expected Image"},
      {replaced("NDims = 3", "NDims 3"), ":2: expected 'Key = Value'"},
      {good.substr(0, good.find("ElementDataFile")), "ElementDataFile: expected the header to end with it"}};
  for (const auto& [text, why] : cases) {
    TempFile f(text);
    auto seq = read_plus_sequence(f.path.string());
    ASSERT_FALSE(seq) << why;
    EXPECT_NE(seq.error().find(f.path.string()), std::string::npos) << seq.error();
    EXPECT_NE(seq.error().find(why), std::string::npos) << seq.error();
  }
}

TEST(PlusSequence, ReplaysAsATrackerSkippingInvalidFramesWithNoMalformedOnes) {
  TempFile f(sequence_text());
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.replay_file = f.path.string();
  t.replay_realtime = false;
  testing::Collector got;
  auto tracker = make_tracker(t, testing::collecting(got));
  ASSERT_TRUE(tracker) << tracker.error();
  ASSERT_TRUE(testing::eventually([&] { return (*tracker)->finished(); }));
  (*tracker)->stop();
  EXPECT_EQ((*tracker)->stats().malformed, 0u);
  int stylus = 0, patient = 0;
  std::vector<std::int64_t> stylus_ns;
  for (const PoseSample& s : got.copy()) {
    if (s.role == Role::Stylus) {
      ++stylus;
      stylus_ns.push_back(s.t_device_ns);
      EXPECT_NE(s.position().x(), 20.0) << "frame 2's INVALID stylus is never applied";
      EXPECT_NEAR(s.position().y(), -5.0, 1e-3);
    }
    patient += s.role == Role::Patient;
  }
  EXPECT_EQ(stylus, 4);
  EXPECT_EQ(patient, 5);
  ASSERT_EQ(stylus_ns.size(), 4u);
  EXPECT_NEAR(static_cast<double>(stylus_ns.back() - stylus_ns.front()), 0.2e9, 1e3)
      << "the device clock is the frames' timestamps: frames 0 to 4, 50 ms apart";
  // A tool that feeds no role is refused as a whole sequence, in one line.
  std::string other = sequence_text();
  for (const char* tool : {"Reference", "Stylus"}) {
    for (std::size_t at = other.find(tool); at != std::string::npos; at = other.find(tool)) other.replace(at, std::strlen(tool), "Probe");
  }
  TempFile g(other);
  t.replay_file = g.path.string();
  auto none = make_tracker(t, testing::quiet());
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find("expected transforms of Reference"), std::string::npos) << none.error();
}

// Only tools given relative to the Reference get the identity patient: a stylus relative to the tracker, with no
// patient tool, is replayed alone.
TEST(PlusSequence, NoPatientIsMadeUpForAToolRelativeToTheTracker) {
  std::string stylus_only = sequence_text();
  for (std::size_t at = stylus_only.find("_ReferenceToTracker"); at != std::string::npos;
       at = stylus_only.find("_ReferenceToTracker")) {
    const std::size_t start = stylus_only.rfind('\n', at) + 1;
    stylus_only.erase(start, stylus_only.find('\n', at) + 1 - start);
  }
  TempFile f(stylus_only);
  auto seq = read_plus_sequence(f.path.string());
  ASSERT_TRUE(seq) << seq.error();
  auto replay = plus_replay(*seq, TrackerConfig{}, "stylus.igs.mha");
  ASSERT_TRUE(replay) << replay.error();
  EXPECT_EQ(replay->log.records.size(), 4u) << "the four valid stylus transforms, and no patient";
}

// A transform's name splits at the first "To" after the tool's first letter: a one-letter tool is a tool.
TEST(PlusSequence, AOneLetterToolSplitsAfterItsLetter) {
  std::string text = sequence_text();
  for (std::size_t at = text.find("Stylus"); at != std::string::npos; at = text.find("Stylus"))
    text.replace(at, 6, "X");
  TempFile f(text);
  auto seq = read_plus_sequence(f.path.string());
  ASSERT_TRUE(seq) << seq.error();
  const PlusTransform* x = seq->frames[3].find("X");
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->frame, "Tracker");
}

// [trackers.plus] renames the tools: a phantom's marker called "Phantom" and a pointer called "Pointer" feed the
// patient and the stylus; with PLUS's names they feed nothing.
TEST(PlusSequence, TheToolsNamedInTrackersPlusFeedTheirRoles) {
  std::string renamed = sequence_text();
  for (const auto& [from, to] : {std::pair<const char*, const char*>{"Reference", "Phantom"}, {"Stylus", "Pointer"}}) {
    for (std::size_t at = renamed.find(from); at != std::string::npos; at = renamed.find(from))
      renamed.replace(at, std::strlen(from), to);
  }
  TempFile f(renamed);
  auto seq = read_plus_sequence(f.path.string());
  ASSERT_TRUE(seq) << seq.error();
  TrackerConfig t;
  EXPECT_FALSE(plus_replay(*seq, t, "renamed.igs.mha")) << "PLUS's own names find neither tool";
  t.plus.patient = "Phantom";
  t.plus.stylus = "Pointer";
  auto replay = plus_replay(*seq, t, "renamed.igs.mha");
  ASSERT_TRUE(replay) << replay.error();
  EXPECT_NE(replay->describe.find("Phantom -> patient"), std::string::npos) << replay->describe;
  EXPECT_NE(replay->describe.find("Pointer -> stylus"), std::string::npos) << replay->describe;
  EXPECT_EQ(plus_tool_role("StylusTip", t.plus), std::nullopt) << "PLUS's alias only at PLUS's names";
  EXPECT_EQ(plus_tool_role("StylusTip"), Role::Stylus);
}

}  // namespace
}  // namespace lungar::drivers
