/// @file plus_sequence_writer_test.cpp
/// @brief Writing PLUS sequences: what lungar writes reads back (our reader and the header Slicer's reader needs:
///        every tool in every frame, the placeholder image's bytes), and a recorded .trk becomes one frame per
///        record holding each tool's newest pose, INVALID once it went silent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "drivers/decode/decoder.h"
#include "drivers/decode/report_layout.h"
#include "drivers/plus/plus_sequence.h"
#include "drivers/plus/plus_sequence_writer.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "tests/drivers/test_data.h"

namespace lungar::drivers {
namespace {

Eigen::Matrix4d pose(double angle, double x, double y, double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t.matrix();
}

TEST(PlusSequenceWriter, WhatItWritesReadsBackFrameForFrame) {
  PlusSequence seq;
  for (int f = 0; f < 4; ++f) {
    PlusFrame frame;
    frame.timestamp_s = 0.016 * f;
    frame.transforms.push_back({"Reference", "Tracker", true, pose(0.1, 100, 200, 300)});
    if (f != 2) frame.transforms.push_back({"Stylus", "Tracker", f != 1, pose(0.2 * f, 10.0 * f, -5.5, 40.25)});
    seq.frames.push_back(frame);
  }
  const auto path =
      std::filesystem::temp_directory_path() / ("lungar_plus_writer_" + std::to_string(::getpid()) + ".igs.mha");
  ASSERT_TRUE(write_plus_sequence(path.string(), seq));
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  std::filesystem::remove(path);
  EXPECT_NE(text.find("DimSize = 1 1 4\n"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 4), std::string(4, '\0')) << "one placeholder byte a frame after the header";
  EXPECT_NE(text.find("Seq_Frame0002_StylusToTrackerTransformStatus = INVALID"), std::string::npos)
      << "a tool missing from a frame is there, INVALID";
  std::istringstream back(text);
  auto read = parse_plus_sequence(back, "written.igs.mha");
  ASSERT_TRUE(read) << read.error();
  ASSERT_EQ(read->frames.size(), 4u);
  EXPECT_EQ(read->invalid_transforms, 2);  // frame 1 (INVALID as given) and frame 2 (missing)
  for (int f = 0; f < 4; ++f) {
    const PlusFrame& r = read->frames[static_cast<std::size_t>(f)];
    EXPECT_NEAR(r.timestamp_s, 0.016 * f, 1e-6);
    const PlusTransform* ref = r.find("Reference");
    ASSERT_NE(ref, nullptr);
    EXPECT_TRUE(ref->valid);
    EXPECT_TRUE(ref->matrix.isApprox(pose(0.1, 100, 200, 300), 1e-8));
    const PlusTransform* stylus = r.find("Stylus");
    ASSERT_NE(stylus, nullptr);
    EXPECT_EQ(stylus->valid, f == 0 || f == 3) << f;
    if (stylus->valid) {
      EXPECT_TRUE(stylus->matrix.isApprox(pose(0.2 * f, 10.0 * f, -5.5, 40.25), 1e-8)) << f;
    }
  }
}

TEST(PlusSequenceWriter, ARecordedLogBecomesOneFramePerRecordWithEachToolsNewestPose) {
  auto log = load_trk(testing::tracker_data("upright_to_supine.trk"));
  ASSERT_TRUE(log) << log.error();
  int skipped = -1;
  auto seq = plus_from_trk(*log, "upright_to_supine.trk", TrackerConfig{}, skipped);
  ASSERT_TRUE(seq) << seq.error();
  EXPECT_EQ(seq->frames.size() + static_cast<std::size_t>(skipped), log->records.size());
  // The last frame holds, for the patient, the pose of the last record that carried one.
  TrackerConfig trackers;
  if (!log->header.layout_toml.empty()) trackers = *tracker_config_from_toml(log->header.layout_toml, "header");
  const ReportLayout layout = *make_layout(trackers);
  Eigen::Matrix4d last_patient = Eigen::Matrix4d::Zero();
  for (const TrkRecord& rec : log->records) {
    const DecodedReport r = decode_report(rec.report, layout);
    for (int k = 0; k < r.count; ++k)
      if (r.poses[static_cast<std::size_t>(k)].role == Role::Patient)
        last_patient = r.poses[static_cast<std::size_t>(k)].transform().matrix();
  }
  const PlusTransform* reference = seq->frames.back().find("Reference");
  ASSERT_NE(reference, nullptr);
  EXPECT_TRUE(reference->matrix.isApprox(last_patient, 1e-9));
  EXPECT_NEAR(seq->frames.front().timestamp_s, 0.0, 1e-12);
  for (std::size_t i = 1; i < seq->frames.size(); ++i)
    ASSERT_GE(seq->frames[i].timestamp_s, seq->frames[i - 1].timestamp_s) << i;
}

TEST(PlusSequenceWriter, AToolSilentForMoreThanATenthOfASecondIsInvalid) {
  auto log = load_trk(testing::tracker_data("upright_to_supine.trk"));
  ASSERT_TRUE(log) << log.error();
  TrackerConfig trackers;
  if (!log->header.layout_toml.empty()) trackers = *tracker_config_from_toml(log->header.layout_toml, "header");
  const ReportLayout layout = *make_layout(trackers);
  const auto tools_of = [&](const TrkRecord& rec) {
    std::set<std::string> tools;
    const DecodedReport r = decode_report(rec.report, layout);
    for (int k = 0; k < r.count; ++k) tools.insert(plus_tool_of(r.poses[static_cast<std::size_t>(k)].role));
    return tools;
  };
  // The first record, and the next that feeds a tool the first did not, 0.5 s later.
  TrkLog two;
  two.header = log->header;
  two.records.push_back(log->records[0]);
  for (const TrkRecord& rec : log->records)
    if (tools_of(rec) != tools_of(log->records[0])) {
      two.records.push_back(rec);
      break;
    }
  ASSERT_EQ(two.records.size(), 2u);
  two.records[1].t_arrival_ns = two.records[0].t_arrival_ns + 500'000'000;
  int skipped = 0;
  auto seq = plus_from_trk(two, "two.trk", TrackerConfig{}, skipped);
  ASSERT_TRUE(seq) << seq.error();
  ASSERT_EQ(seq->frames.size(), 2u);
  const std::set<std::string> now = tools_of(two.records[1]);
  for (const PlusTransform& t : seq->frames[1].transforms)
    EXPECT_EQ(t.valid, now.count(t.tool) == 1) << t.name() << ": OK only when fed within 0.1 s";
  EXPECT_GT(seq->frames[1].transforms.size(), now.size()) << "the silent tool is still in the frame";
}

}  // namespace
}  // namespace lungar::drivers
