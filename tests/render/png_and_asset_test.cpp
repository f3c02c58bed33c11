/// @file png_and_asset_test.cpp
/// @brief Bad input at render/'s boundaries: PNG writing leaves no partial file; malformed assets name the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render/lung_drawable.h"
#include "render/png_snapshot.h"
#include "tests/partial_files.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::render {
namespace {

TEST(PngTest, WrongPixelCountIsRefusedAndNothingWritten) {
  const std::string path = std::string(LUNGAR_BINARY_DIR) + "/bad.png";
  std::filesystem::remove(path);
  std::vector<std::uint8_t> pixels(10 * 10 * 4 - 1);
  Status s = write_png(path, 10, 10, pixels);
  EXPECT_FALSE(s);
  EXPECT_NE(s.error().find(path), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(lungar::testing::partial_files_beside(path), std::vector<std::string>{});
}

TEST(PngTest, UnwritableDirectoryIsAnError) {
  // A missing folder is made (as for every output); a folder that is a plain file cannot be, even as root.
  const std::string blocker = std::string(LUNGAR_BINARY_DIR) + "/png-blocker";
  std::ofstream(blocker) << "a file, not a folder";
  std::vector<std::uint8_t> pixels(4 * 4 * 4, 255);
  Status s = write_png(blocker + "/x.png", 4, 4, pixels);
  EXPECT_FALSE(s);
  EXPECT_NE(s.error().find(blocker + "/x.png"), std::string::npos);
  std::filesystem::remove(blocker);
}

TEST(PngTest, WritesAFileOfPlausibleSize) {
  const std::string path = std::string(LUNGAR_BINARY_DIR) + "/ok.png";
  std::vector<std::uint8_t> pixels(16 * 8 * 4);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 7);
  ASSERT_TRUE(write_png(path, 16, 8, pixels));
  EXPECT_GT(std::filesystem::file_size(path), 60u);
}

class AssetValidationTest : public test::GlTest {};

TEST_F(AssetValidationTest, MalformedArraysNameTheField) {
  const auto good = test::ellipsoid_pair(50, 4, 1);
  struct Breakage {
    const char* field;
    void (*apply)(sim::BakedAsset&);
  };
  const Breakage cases[] = {
      {"positions", [](sim::BakedAsset& a) { a.positions.pop_back(); }},
      {"normals", [](sim::BakedAsset& a) { a.normals.push_back(0.f); }},
      {"sh_coeffs", [](sim::BakedAsset& a) { a.sh_coeffs.resize(3); }},
      {"bands", [](sim::BakedAsset& a) { a.bands = 0; }},
      {"triangles", [](sim::BakedAsset& a) { a.triangles = {0, 1, 100000}; }},
      {"lungs[1]", [](sim::BakedAsset& a) { a.lungs[1].vertex_count = 1000; }},
      {"lungs", [](sim::BakedAsset& a) { a.lungs.clear(); }},
      {"lung_of_vertex", [](sim::BakedAsset& a) { a.lung_of_vertex[3] = 9; }},
  };
  for (const auto& c : cases) {
    auto a = good;
    c.apply(a);
    auto d = LungDrawable::create(a);
    ASSERT_FALSE(d) << c.field;
    EXPECT_NE(d.error().find(c.field), std::string::npos) << d.error();
  }
  EXPECT_TRUE(LungDrawable::create(good));
}

}  // namespace
}  // namespace lungar::render
