// Tests of drivers/trk: write/read round trip, a truncated tail losing only the last record, corruption named
// with its offset, atomic writes leaving nothing under the final name, and the header's layout text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "config/base/crc32.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_reader.h"
#include "drivers/trk/trk_writer.h"
#include "tests/partial_files.h"

using namespace lungar;
using namespace lungar::drivers;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("lungar_trk_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::vector<std::uint8_t> read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TrkHeader header() {
  TrkHeader h;
  h.description = "source=hid\nvendor_id=0x1234\nserial=SN0001\n";
  h.layout_toml = tracker_config_to_toml(TrackerConfig{});
  return h;
}

/// Three records of lengths 3, 5 and 7 whose bytes encode their index.
fs::path write_three(const fs::path& path, TrkWriter::Mode mode) {
  TrkWriter w;
  EXPECT_EQ(w.open(path.string(), header(), mode).error(), "");
  for (int k = 0; k < 3; ++k) {
    std::vector<std::uint8_t> r(static_cast<std::size_t>(3 + 2 * k), static_cast<std::uint8_t>(k + 10));
    EXPECT_EQ(w.append(TrkSource::Hid, 1000 + k, r).error(), "");
  }
  EXPECT_EQ(w.commit().error(), "");
  return path;
}

}  // namespace

TEST(Crc32, MatchesTheStandardCheckValue) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(s.data()), s.size())),
            0xCBF43926u);
}

TEST(Trk, RoundTripKeepsHeaderAndRecords) {
  const auto path = write_three(temp_dir() / "a.trk", TrkWriter::Mode::AppendLog);
  auto r = load_trk(path.string());
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->header.field("serial"), "SN0001");
  EXPECT_EQ(r->header.field("nothing"), "");
  EXPECT_EQ(r->header.layout_toml, header().layout_toml);
  ASSERT_EQ(r->records.size(), 3u);
  EXPECT_FALSE(r->truncated_tail);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(r->records[k].t_arrival_ns, 1000 + k);
    EXPECT_EQ(r->records[k].report.size(), static_cast<std::size_t>(3 + 2 * k));
    EXPECT_EQ(r->records[k].report[0], k + 10);
  }
}

TEST(Trk, ATruncatedTailLosesOnlyTheLastRecord) {
  const auto path = write_three(temp_dir() / "b.trk", TrkWriter::Mode::AppendLog);
  const auto bytes = read_file(path);
  // Every cut inside the last record (21 + 7 bytes) leaves the first two.
  for (std::size_t cut = 1; cut < kTrkRecordOverhead + 7; ++cut) {
    auto r = parse_trk(std::vector<std::uint8_t>(bytes.begin(), bytes.end() - static_cast<long>(cut)), "b.trk");
    ASSERT_TRUE(r) << cut << ": " << r.error();
    EXPECT_EQ(r->records.size(), 2u) << cut;
    EXPECT_TRUE(r->truncated_tail) << cut;
  }
}

TEST(Trk, CorruptionIsAnErrorNamingFileRecordAndOffset) {
  const auto path = write_three(temp_dir() / "c.trk", TrkWriter::Mode::AppendLog);
  auto bytes = read_file(path);
  const std::size_t header_size = parse_trk_header(bytes)->size;
  auto flipped = bytes;
  flipped[header_size + 14] ^= 0x01;  // first record's first report byte
  EXPECT_EQ(parse_trk(flipped, "c.trk").error(),
            "c.trk: record 0: record CRC mismatch, at byte " + std::to_string(header_size));
  auto desync = bytes;
  desync[header_size + kTrkRecordOverhead + 3] = 0;  // second record's sync
  EXPECT_EQ(parse_trk(desync, "c.trk").error(), "c.trk: record 1: expected a record sync 0x4B52, at byte " +
                                                    std::to_string(header_size + kTrkRecordOverhead + 3));
  auto bad_header = bytes;
  bad_header[20] ^= 0xFF;
  EXPECT_EQ(parse_trk(bad_header, "c.trk").error().rfind("c.trk: header CRC mismatch: the header is damaged", 0), 0u);
  EXPECT_EQ(parse_trk({'n', 'o', 'p', 'e', 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "x.trk").error(),
            "x.trk: expected the magic \"LUNGATRK\": not a .trk log, at byte 0");
  auto huge = bytes;
  huge[12] = 0xFF;
  huge[13] = 0xFF;
  huge[14] = 0xFF;
  EXPECT_NE(parse_trk(huge, "c.trk").error().find("expected a text of at most"), std::string::npos);
  EXPECT_EQ(load_trk((temp_dir() / "missing.trk").string()).error(),
            (temp_dir() / "missing.trk").string() + ": cannot open the tracker log: expected a readable .trk file");
}

TEST(Trk, AtomicWriterLeavesNothingUnderTheFinalNameUntilCommit) {
  const fs::path path = temp_dir() / "d.trk";
  fs::remove(path);
  {
    TrkWriter w;
    ASSERT_TRUE(w.open(path.string(), header(), TrkWriter::Mode::Atomic));
    const std::uint8_t r[4] = {1, 2, 3, 4};
    ASSERT_TRUE(w.append(TrkSource::Synth, 5, r));
    EXPECT_FALSE(fs::exists(path));
    EXPECT_EQ(lungar::testing::partial_files_beside(path).size(), 1u) << "the records go to a partial file";
  }  // destroyed without commit
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(lungar::testing::partial_files_beside(path), std::vector<std::string>{});
  write_three(path, TrkWriter::Mode::Atomic);
  EXPECT_TRUE(fs::exists(path));
  EXPECT_EQ(lungar::testing::partial_files_beside(path), std::vector<std::string>{});
}

TEST(Trk, AppendLogHasAReadableHeaderFromTheStart) {
  const fs::path path = temp_dir() / "e.trk";
  TrkWriter w;
  ASSERT_TRUE(w.open(path.string(), header(), TrkWriter::Mode::AppendLog));
  auto r = load_trk(path.string());  // a crash right after open: an empty but valid log
  ASSERT_TRUE(r) << r.error();
  EXPECT_TRUE(r->records.empty());
  const std::uint8_t rep[2] = {9, 9};
  ASSERT_TRUE(w.append(TrkSource::Hid, 1, rep));
  r = load_trk(path.string());  // each record is on disk as soon as append returns
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->records.size(), 1u);
}

TEST(Trk, WriterErrorsNameTheFile) {
  TrkWriter w;
  const Status opened = w.open("/nonexistent-dir/x.trk", header(), TrkWriter::Mode::AppendLog);
  EXPECT_FALSE(opened);
  EXPECT_EQ(opened.error().rfind("/nonexistent-dir/x.trk: cannot create the tracker log", 0), 0u) << opened.error();
}

TEST(LayoutToml, RoundTripsTheLayout) {
  TrackerConfig t;
  t.report.endian = Endian::Big;
  t.report.orientation = OrientationKind::Euler;
  t.report.orientation_components = "z,-y,x";
  t.report.position_scale = 0.1234567890123;
  t.axis_remap = "x,-z,y";
  t.stylus.enabled = true;
  auto back = tracker_config_from_toml(tracker_config_to_toml(t), "t");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->report.endian, t.report.endian);
  EXPECT_EQ(back->report.orientation, t.report.orientation);
  EXPECT_EQ(back->report.orientation_components, t.report.orientation_components);
  EXPECT_DOUBLE_EQ(back->report.position_scale, t.report.position_scale);
  EXPECT_EQ(back->axis_remap, t.axis_remap);
  EXPECT_TRUE(back->stylus.enabled);
  EXPECT_EQ(tracker_config_from_toml("[trackers.report]\nlength = \"x\"\n", "h").error(),
            "h:2: key 'trackers.report.length': expected an integer in [1, 1024] bytes, got the string \"x\"");
}
