/// @file renderer_test.cpp
/// @brief Frame drawing: strategies agree, CPU-uploaded positions agree with the shader, level of detail keeps the
/// coverage with fewer points, modes and overlay draw, bad inputs are refused with a message.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "render/frame_target.h"
#include "render/png_snapshot.h"
#include "render/renderer.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::render {
namespace {

constexpr int kEyeW = 320, kEyeH = 360;

class RendererTest : public test::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    asset_ = test::ellipsoid_pair(20000, 4, 21);
    force_.assign(16, 0.f);
    for (std::size_t k = 0; k < force_.size(); ++k) force_[k] = 0.03f * static_cast<float>((k % 5) + 1) / 5.f;
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(drawable_, LungDrawable::create(asset_)));
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(renderer_, Renderer::create(*drawable_)));
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(target_, FrameTarget::create(2 * kEyeW, kEyeH)));
    eyes_ = test::stereo_eyes(kEyeW, kEyeH, {0.f, -600.f, 50.f});
    lungs_[0] = {force_, 400.f, {0.45f, 0.6f, 0.95f}};
    lungs_[1] = {force_, 400.f, {0.9f, 0.45f, 0.45f}};
    frame_.lungs = lungs_;
    frame_.eyes = eyes_;
  }

  std::vector<std::uint8_t> draw(const FrameInputs& f, FrameStats* stats = nullptr) {
    target_->bind();
    Status s = renderer_->draw(*drawable_, f, stats);
    EXPECT_TRUE(s) << s.error();
    std::vector<std::uint8_t> rgba;
    read_pixels_top_down(0, 0, target_->width(), target_->height(), rgba);
    return rgba;
  }

  static double lit_fraction(const std::vector<std::uint8_t>& rgba) {
    std::size_t lit = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) lit += (rgba[i] + rgba[i + 1] + rgba[i + 2]) > 0;
    return static_cast<double>(lit) / static_cast<double>(rgba.size() / 4);
  }

  static double differing_fraction(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); i += 4) {
      int d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int{a[i + k]} - int{b[i + k]}));
      differ += d > 2;
    }
    return static_cast<double>(differ) / static_cast<double>(a.size() / 4);
  }

  sim::BakedAsset asset_;
  std::vector<float> force_;
  std::optional<LungDrawable> drawable_;
  std::optional<Renderer> renderer_;
  std::optional<FrameTarget> target_;
  std::array<EyeView, 2> eyes_;
  LungFrame lungs_[2];
  FrameInputs frame_;
};

TEST_F(RendererTest, PerEyeAndDeformOnceDrawTheSameImage) {
  FrameInputs f = frame_;
  f.strategy = StereoStrategy::PerEye;
  const auto per_eye = draw(f);
  f.strategy = StereoStrategy::DeformOnce;
  FrameStats stats;
  const auto once = draw(f, &stats);
  EXPECT_GT(lit_fraction(once), 0.02);
  EXPECT_LT(differing_fraction(per_eye, once), 0.002);
  EXPECT_GE(stats.points_deformed, std::max(stats.points_drawn[0], stats.points_drawn[1]));
}

TEST_F(RendererTest, OneEyeDeformsInItsDrawWhateverTheStrategy) {
  FrameInputs f = frame_;
  f.eyes = std::span<const EyeView>(eyes_.data(), 1);
  f.strategy = StereoStrategy::PerEye;
  const auto per_eye = draw(f);
  f.strategy = StereoStrategy::DeformOnce;
  FrameStats stats;
  stats.points_deformed = 1;
  const auto once = draw(f, &stats);
  EXPECT_GT(lit_fraction(once), 0.01);
  EXPECT_LT(differing_fraction(per_eye, once), 0.002);
  EXPECT_EQ(stats.points_deformed, 0u) << "no transform-feedback pass for a single eye";
  EXPECT_GT(stats.points_drawn[0], 0u);
}

TEST_F(RendererTest, CpuDeformedUploadDrawsLikeTheShader) {
  FrameInputs f = frame_;
  const auto shader = draw(f);
  const auto cpu = test::deform_eq7(asset_, {force_, force_}, {400.f, 400.f});
  std::vector<float> xyz(cpu.begin(), cpu.end());
  ASSERT_TRUE(drawable_->upload_positions(xyz));
  f.source = PositionSource::Uploaded;
  const auto uploaded = draw(f);
  EXPECT_LT(differing_fraction(shader, uploaded), 0.002);
  // The rest shape is a different picture: the comparison can fail.
  f.source = PositionSource::Rest;
  EXPECT_GT(differing_fraction(shader, draw(f)), 0.005);
  EXPECT_FALSE(drawable_->upload_positions(std::span<const float>(xyz.data(), 3)));
}

TEST_F(RendererTest, LevelOfDetailDrawsFewerPointsAtEqualCoverage) {
  FrameInputs f = frame_;
  f.level_of_detail = false;
  FrameStats all, lod;
  const auto full_image = draw(f, &all);
  f.level_of_detail = true;
  const auto lod_image = draw(f, &lod);
  const double full = lit_fraction(full_image), reduced = lit_fraction(lod_image);
  EXPECT_TRUE(write_png(std::string(LUNGAR_BINARY_DIR) + "/render-test-full.png", 2 * kEyeW, kEyeH, full_image));
  EXPECT_TRUE(write_png(std::string(LUNGAR_BINARY_DIR) + "/render-test-lod.png", 2 * kEyeW, kEyeH, lod_image));
  std::printf("level of detail: %u of %u points in the left eye, coverage %.4f vs %.4f\n", lod.points_drawn[0],
              all.points_drawn[0], reduced, full);
  EXPECT_LT(lod.points_drawn[0], all.points_drawn[0] / 2);
  // Small lungs (60 px wide here) make the silhouette's 2.5-pixel edge band a large share of the picture; that band
  // is all the reduced set loses (interior holes would cost far more), hence the 5 %.
  EXPECT_GT(reduced, 0.95 * full) << "coverage " << reduced << " vs " << full;
  // Farther away, fewer points still.
  FrameStats far_stats;
  std::array<EyeView, 2> far = eyes_;
  for (auto& e : far) e.view = e.view * glm::translate(glm::mat4(1.f), glm::vec3(0.f, 800.f, 0.f));
  f.eyes = far;
  draw(f, &far_stats);
  EXPECT_LT(far_stats.points_drawn[0], lod.points_drawn[0]);
}

TEST_F(RendererTest, BackFaceCullingKeepsTheFrontPicture) {
  FrameInputs f = frame_;
  f.level_of_detail = false;
  const auto culled = draw(f);
  f.cull_back_facing = false;
  const auto all = draw(f);
  // Depth testing hides the back either way; culling only removes hidden work (edges may differ by a point).
  EXPECT_LT(differing_fraction(culled, all), 0.01);
}

TEST_F(RendererTest, BackFaceCullingDropsTheBackPoints) {
  // The near plane through the lungs' centre clips their front half away, so the back half shows from inside.
  // Culled, those back-facing points are never drawn and little but the limb remains; without culling, they are.
  FrameInputs f = frame_;
  f.level_of_detail = false;
  std::array<EyeView, 2> cut = eyes_;
  for (auto& e : cut) {
    e.projection = glm::perspective(glm::radians(60.f), static_cast<float>(kEyeW) / kEyeH, 600.f, 5000.f);
  }
  f.eyes = cut;
  const double culled = lit_fraction(draw(f));
  f.cull_back_facing = false;
  const double all = lit_fraction(draw(f));
  EXPECT_GT(all, 0.02);
  EXPECT_LT(culled, 0.5 * all) << "culled " << culled << ", all " << all;
}

TEST_F(RendererTest, OverlayShowsTheRestShapeInGrey) {
  FrameInputs f = frame_;
  for (auto& l : lungs_) l.volume_change_ml = -400.f;  // deflated: the rest shape shows around it
  f.overlay_rest = true;
  const auto rgba = draw(f);
  std::size_t grey = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) grey += rgba[i] > 0 && rgba[i] == rgba[i + 1] && rgba[i] == rgba[i + 2];
  EXPECT_GT(grey, 1000u);
}

TEST_F(RendererTest, TheVentilationMapColoursEachPointByTheAirItsSurfaceSweptOverTheLastBreath) {
  // The ramp's zero has no green (render/ventilation_ramp.h) and the green grows along it: a lung that swept
  // nothing has no green pixel, one that swept a breath has, and more for a deeper breath. The map off draws the
  // lungs' own colours, both with green.
  auto green = [](const std::vector<std::uint8_t>& rgba, std::size_t& count) {
    double sum = 0;
    count = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4)
      if (rgba[i + 1] > 10) sum += rgba[i + 1], ++count;
    return count > 0 ? sum / static_cast<double>(count) : 0.0;
  };
  std::size_t lit = 0, still = 0, one = 0, deeper = 0;
  FrameInputs f = frame_;
  lungs_[0].sweep_ml = 0.f;
  lungs_[1].sweep_ml = 0.f;
  green(draw(f), lit);
  EXPECT_GT(lit, 5000u) << "map off: the lungs' own colours";
  f.ventilation_full_scale_mm = 2.f;
  green(draw(f), still);
  EXPECT_EQ(still, 0u) << "no lung swept anything: all at the ramp's zero";
  lungs_[0].sweep_ml = 500.f;
  const auto image = draw(f);
  const double mean_one = green(image, one);
  EXPECT_GT(one, lit / 5) << "one lung breathed: its points climb the ramp";
  EXPECT_LT(one, lit * 3 / 4) << "the other did not";
  lungs_[0].sweep_ml = 1500.f;
  EXPECT_GT(green(draw(f), deeper), mean_one + 5.0) << "a deeper breath is further up the ramp";
  f.strategy = StereoStrategy::DeformOnce;  // the map needs the deformation in the draw: drawn per eye anyway
  lungs_[0].sweep_ml = 500.f;
  EXPECT_LT(differing_fraction(draw(f), image), 0.001);
}

TEST_F(RendererTest, MeshModeFillsTheSilhouette) {
  const auto mesh_asset = test::ellipsoid_pair_mesh(48, 64, 4, 5);
  auto mesh = LungDrawable::create(mesh_asset);
  ASSERT_TRUE(mesh) << mesh.error();
  FrameInputs f = frame_;
  f.mode = DrawMode::Mesh;
  target_->bind();
  EXPECT_TRUE(renderer_->draw(*mesh, f));
  std::vector<std::uint8_t> rgba;
  read_pixels_top_down(0, 0, target_->width(), target_->height(), rgba);
  EXPECT_GT(lit_fraction(rgba), 0.02);
  // A point asset has no triangles: mesh mode is refused, not drawn wrong.
  Status refused = renderer_->draw(*drawable_, f);
  EXPECT_FALSE(refused);
  EXPECT_NE(refused.error().find("mesh"), std::string::npos);
}

TEST_F(RendererTest, RefusesInputsThatDoNotFit) {
  FrameInputs f = frame_;
  const std::vector<float> short_force(5, 0.f);
  LungFrame bad[2] = {{short_force, 1.f, {}}, lungs_[1]};
  f.lungs = bad;
  Status s = renderer_->draw(*drawable_, f);
  EXPECT_FALSE(s);
  EXPECT_NE(s.error().find("lungs[0].force"), std::string::npos) << s.error();
  f.lungs = std::span<const LungFrame>(lungs_, 1);
  EXPECT_FALSE(renderer_->draw(*drawable_, f));
  f = frame_;
  f.eyes = {};
  EXPECT_FALSE(renderer_->draw(*drawable_, f));
  // The CPU path needs no force at all.
  f = frame_;
  f.source = PositionSource::Uploaded;
  f.lungs = bad;
  EXPECT_TRUE(renderer_->draw(*drawable_, f));
}

TEST_F(RendererTest, SnapshotWritesAPng) {
  draw(frame_);
  const std::string path = std::string(LUNGAR_BINARY_DIR) + "/render-test-snapshot.png";
  std::remove(path.c_str());
  ASSERT_TRUE(snapshot_png(path, 0, 0, target_->width(), target_->height()));
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

}  // namespace
}  // namespace lungar::render
