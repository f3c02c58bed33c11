/// @file asset_io_test.cpp
/// @brief `.lungbake`: a round trip keeps every field; damaged files are refused with a line naming the file
///        and what was wrong; a failed write leaves nothing under the final name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cstring>
#include <iterator>

#include "sim/asset/asset_io.h"
#include "config/base/crc32.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::small_asset;
using test::small_bake;
using test::TempDir;

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(Crc32, MatchesTheStandardCheckValue) {
  EXPECT_EQ(crc32("123456789", 9), 0xCBF43926u);
  EXPECT_EQ(crc32("", 0), 0u);
}

TEST(AssetIo, TheSlidingModelsDirectionsSurviveTheRoundTrip) {
  TempDir dir;
  const BakedAsset& a = test::sliding_asset();
  ASSERT_TRUE(write_asset(a, dir.file("s.lungbake")));
  const Result<BakedAsset> b = load_asset(dir.file("s.lungbake"));
  ASSERT_TRUE(b) << b.error();
  EXPECT_EQ(b->motion_model, MotionModel::sliding);
  EXPECT_EQ(b->directions, a.directions);
  EXPECT_NE(b->directions, b->normals);
}

TEST(AssetIo, AVersionOneAssetLoadsAsThePapersModel) {
  // tests/data/hil_lungs.lungbake was written by asset version 1 (no MODL, no MDIR section).
  const Result<BakedAsset> a = load_asset(std::string(LUNGAR_SOURCE_DIR) + "/tests/data/hil_lungs.lungbake");
  ASSERT_TRUE(a) << a.error();
  EXPECT_EQ(a->motion_model, MotionModel::paper);
  EXPECT_EQ(a->directions, a->normals);
  EXPECT_FALSE(a->has_sphere_dirs()) << "older assets hold no sphere points";
}

TEST(AssetIo, AnUnknownMotionModelIsRefusedByName) {
  TempDir dir;
  const std::string path = dir.file("m.lungbake");
  ASSERT_TRUE(write_asset(small_asset(), path));
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t at = bytes.find("MODL");
  ASSERT_NE(at, std::string::npos);
  const std::uint32_t model = 7;
  std::memcpy(&bytes[at + 12], &model, 4);
  const std::uint32_t crc = crc32(&bytes[at + 12], 4);
  std::memcpy(&bytes[at + 16], &crc, 4);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  const Result<BakedAsset> b = load_asset(path);
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().find("'MODL'"), std::string::npos) << b.error();
  EXPECT_NE(b.error().find("motion model 7"), std::string::npos) << b.error();
}

TEST(AssetIo, RoundTripKeepsEveryField) {
  TempDir dir;
  const BakedAsset& a = small_bake().asset;
  const std::string path = dir.file("pair.lungbake");
  ASSERT_TRUE(write_asset(a, path)) << write_asset(a, path).error();
  EXPECT_EQ(dir.entries(), 1u) << "no temporary file left behind";
  const Result<BakedAsset> b = load_asset(path);
  ASSERT_TRUE(b) << b.error();
  EXPECT_EQ(b->bands, a.bands);
  EXPECT_EQ(b->p0, a.p0);
  EXPECT_EQ(b->gamma_per_mm, a.gamma_per_mm);
  EXPECT_EQ(b->decay_length_mm, a.decay_length_mm);
  EXPECT_EQ(b->transfer_epsilon, a.transfer_epsilon);
  EXPECT_EQ(b->positions, a.positions);
  EXPECT_EQ(b->normals, a.normals);
  EXPECT_EQ(b->directions, a.directions);
  ASSERT_EQ(a.sphere_dirs.size(), a.positions.size()) << "the bake keeps each vertex's point on the SH sphere";
  EXPECT_EQ(b->sphere_dirs, a.sphere_dirs);
  EXPECT_EQ(b->motion_model, a.motion_model);
  EXPECT_EQ(b->areas, a.areas);
  EXPECT_EQ(b->lung_of_vertex, a.lung_of_vertex);
  EXPECT_EQ(b->sh_coeffs, a.sh_coeffs);
  EXPECT_EQ(b->linear_coeffs, a.linear_coeffs);
  EXPECT_EQ(b->triangles, a.triangles);
  EXPECT_EQ(b->transfer_row_ptr, a.transfer_row_ptr);
  EXPECT_EQ(b->transfer_cols, a.transfer_cols);
  EXPECT_EQ(b->transfer_vals, a.transfer_vals);
  ASSERT_EQ(b->lungs.size(), a.lungs.size());
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    const BakedLung &x = a.lungs[l], &y = b->lungs[l];
    EXPECT_EQ(y.name, x.name);
    EXPECT_EQ(y.centre, x.centre);
    EXPECT_EQ(y.first_vertex, x.first_vertex);
    EXPECT_EQ(y.vertex_count, x.vertex_count);
    EXPECT_EQ(y.first_index, x.first_index);
    EXPECT_EQ(y.index_count, x.index_count);
    EXPECT_EQ(y.rest_volume_ml, x.rest_volume_ml);
    EXPECT_EQ(y.volume_share, x.volume_share);
    EXPECT_EQ(y.force_const, x.force_const);
    EXPECT_EQ(y.force_grad, x.force_grad);
    EXPECT_EQ(y.volume_const, x.volume_const);
    EXPECT_EQ(y.volume_grad, x.volume_grad);
    EXPECT_EQ(y.paper_force, x.paper_force);
  }
}

TEST(AssetIo, BakedLesionsSurviveTheRoundTripAndABadOneIsNamed) {
  TempDir dir;
  BakedAsset a = small_asset();
  a.lesions = {{"tumour", 1, {-40.5, -120.25, -250.0}, 7.5, true}, {"nodule-2", 0, {30, -100, -200}, 3, false}};
  const std::string path = dir.file("l.lungbake");
  ASSERT_TRUE(write_asset(a, path));
  const Result<BakedAsset> b = load_asset(path);
  ASSERT_TRUE(b) << b.error();
  ASSERT_EQ(b->lesions.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(b->lesions[k].name, a.lesions[k].name);
    EXPECT_EQ(b->lesions[k].lung, a.lesions[k].lung);
    EXPECT_EQ(b->lesions[k].centre_mm, a.lesions[k].centre_mm);
    EXPECT_EQ(b->lesions[k].radius_mm, a.lesions[k].radius_mm);
    EXPECT_EQ(b->lesions[k].from_label, a.lesions[k].from_label);
  }
  // What the writer refuses: a lung that is not there, a name twice, a radius out of range.
  for (auto [field, damage] : std::initializer_list<std::pair<const char*, void (*)(BakedLesion&)>>{
           {"lung 9; expected below 2", [](BakedLesion& l) { l.lung = 9; }},
           {"expected each name once", [](BakedLesion& l) { l.name = "tumour"; }},
           {"radius: expected above 0 and at most 50 mm", [](BakedLesion& l) { l.radius_mm = 0; }}}) {
    BakedAsset bad = a;
    damage(bad.lesions[1]);
    const Status refused = write_asset(bad, dir.file("bad.lungbake"));
    ASSERT_FALSE(refused) << field;
    EXPECT_NE(refused.error().find(field), std::string::npos) << refused.error();
  }
  EXPECT_EQ(dir.entries(), 1u) << "no partial file beside the good one";
  // The most an asset may hold: 64 lesions with names of 32 characters load; a 65th is refused.
  BakedAsset most = a;
  most.lesions.clear();
  for (int k = 0; k < 64; ++k) {
    std::string name = "lesion-" + std::to_string(k);
    name.resize(32, 'x');
    most.lesions.push_back({name, static_cast<std::uint32_t>(k % 2), {0, 0, double(k)}, 5, k % 3 == 0});
  }
  ASSERT_TRUE(write_asset(most, dir.file("most.lungbake")));
  const Result<BakedAsset> loaded = load_asset(dir.file("most.lungbake"));
  ASSERT_TRUE(loaded) << loaded.error();
  ASSERT_EQ(loaded->lesions.size(), 64u);
  EXPECT_EQ(loaded->lesions[63].name, most.lesions[63].name);
  most.lesions.push_back({"one-more", 0, {0, 0, 0}, 5, false});
  const Status too_many = write_asset(most, dir.file("more.lungbake"));
  ASSERT_FALSE(too_many);
  EXPECT_NE(too_many.error().find("lesions: expected at most 64"), std::string::npos) << too_many.error();
  std::filesystem::remove(dir.file("most.lungbake"));
  // What the reader refuses in the file itself: unknown flags, named by section and lesion.
  std::string bytes = read_bytes(path);
  const std::size_t at = bytes.rfind("LESN");
  ASSERT_NE(at, std::string::npos);
  std::uint64_t length = 0;
  std::memcpy(&length, &bytes[at + 4], 8);
  const std::size_t flags_at = at + 12 + 4 + 4 + std::string("tumour").size() + 4;
  const std::uint32_t flags = 5;
  std::memcpy(&bytes[flags_at], &flags, 4);
  const std::uint32_t crc = crc32(&bytes[at + 12], length);
  std::memcpy(&bytes[at + 12 + length], &crc, 4);
  write_bytes(path, bytes);
  const Result<BakedAsset> c = load_asset(path);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().find("section 'LESN': lesion 0: flags 5; expected 0 or 1"), std::string::npos) << c.error();
}

TEST(AssetIo, WithoutTransferRowsToo) {
  TempDir dir;
  BakedAsset a = small_asset();
  a.transfer_row_ptr.clear();
  a.transfer_cols.clear();
  a.transfer_vals.clear();
  ASSERT_TRUE(write_asset(a, dir.file("a.lungbake")));
  const Result<BakedAsset> b = load_asset(dir.file("a.lungbake"));
  ASSERT_TRUE(b) << b.error();
  EXPECT_FALSE(b->has_transfer_rows());
}

class DamagedAsset : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = dir_.file("a.lungbake");
    ASSERT_TRUE(write_asset(small_asset(), path_));
    bytes_ = read_bytes(path_);
  }
  /// Loads `bytes` and returns the error, which must name the file.
  std::string error_for(const std::string& bytes) {
    write_bytes(path_, bytes);
    const Result<BakedAsset> r = load_asset(path_);
    EXPECT_FALSE(r) << "a damaged asset was accepted";
    EXPECT_NE(r.error().find(path_), std::string::npos) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos) << "one line";
    return r.error();
  }
  TempDir dir_;
  std::string path_, bytes_;
};

TEST_F(DamagedAsset, TruncatedAnywhereIsRefused) {
  for (std::size_t keep : {std::size_t{0}, std::size_t{5}, std::size_t{11}, std::size_t{40}, bytes_.size() / 3,
                           bytes_.size() / 2, bytes_.size() - 5, bytes_.size() - 1}) {
    const std::string e = error_for(bytes_.substr(0, keep));
    EXPECT_TRUE(e.find("truncated") != std::string::npos || e.find("need more bytes") != std::string::npos ||
                e.find("length") != std::string::npos)
        << "kept " << keep << ": " << e;
  }
}

TEST_F(DamagedAsset, FlippedBitsFailTheirSectionsCrc) {
  for (std::size_t at : {bytes_.size() / 2, bytes_.size() / 4, bytes_.size() - 100}) {
    std::string damaged = bytes_;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    const std::string e = error_for(damaged);
    EXPECT_NE(e.find("section '"), std::string::npos) << e;
  }
  std::string payload_flip = bytes_;
  payload_flip[12 + 4 + 8 + 2] ^= 0x01;  // inside HEAD's payload: the bands field
  EXPECT_NE(error_for(payload_flip).find("CRC-32 mismatch"), std::string::npos);
}

TEST_F(DamagedAsset, WrongVersionIsNamed) {
  std::string damaged = bytes_;
  damaged[8] = 7;
  const std::string e = error_for(damaged);
  EXPECT_NE(e.find("version: expected 1 to " + std::to_string(kAssetVersion) + ", found 7"), std::string::npos) << e;
}

TEST_F(DamagedAsset, WrongMagicIsNamed) {
  std::string damaged = bytes_;
  damaged.replace(0, 8, "PNG\r\n\x1a\n\0", 8);
  const std::string e = error_for(damaged);
  EXPECT_NE(e.find("magic"), std::string::npos) << e;
  EXPECT_NE(error_for("").find("magic"), std::string::npos);
}

TEST_F(DamagedAsset, TrailingBytesAreRefused) {
  EXPECT_NE(error_for(bytes_ + "x").find("unexpected bytes"), std::string::npos);
}

TEST(AssetIo, MissingFileAndUnwritableFolder) {
  TempDir dir;
  const Result<BakedAsset> r = load_asset(dir.file("none.lungbake"));
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("none.lungbake"), std::string::npos);
  // A missing folder is made (as for every output), but not under a plain file: that write must fail cleanly.
  std::ofstream(dir.file("blocker")) << "a file, not a folder";
  const Status s = write_asset(small_asset(), dir.file("blocker/a.lungbake"));
  EXPECT_FALSE(s);
  EXPECT_NE(s.error().find("a.lungbake"), std::string::npos);
  EXPECT_EQ(dir.entries(), 1u) << "only the blocking file; no partial asset beside it";
}

TEST(AssetIo, AnUnsoundAssetIsNotWritten) {
  TempDir dir;
  BakedAsset a = small_asset();
  a.triangles.back() = a.vertex_count() + 5;
  const Status s = write_asset(a, dir.file("bad.lungbake"));
  EXPECT_FALSE(s);
  EXPECT_NE(s.error().find("triangles"), std::string::npos) << s.error();
  EXPECT_EQ(dir.entries(), 0u);
}

}  // namespace
}  // namespace lungar::sim
