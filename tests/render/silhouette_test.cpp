/// @file silhouette_test.cpp
/// @brief Upright breathing seen from the front: from FRC to end-inspiration the silhouette grows most at the base.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "render/frame_target.h"
#include "render/png_snapshot.h"
#include "render/renderer.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::render {
namespace {

struct Extent {
  int top = -1, bottom = -1;            // first and last lit rows (image rows, top first)
  std::vector<int> width;               // lit pixels per row
};

Extent silhouette(const std::vector<std::uint8_t>& rgba, int w, int h) {
  Extent e;
  e.width.assign(h, 0);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const std::uint8_t* p = &rgba[(static_cast<std::size_t>(r) * w + c) * 4];
      if (p[0] + p[1] + p[2] > 0) ++e.width[r];
    }
    if (e.width[r] > 0) {
      if (e.top < 0) e.top = r;
      e.bottom = r;
    }
  }
  return e;
}

class SilhouetteTest : public test::GlTest {};

TEST_F(SilhouetteTest, UprightInspirationGrowsMostAtTheBase) {
  // A local transfer and the upright force pattern: the pleural pressure is larger at the base (lower z, gravity
  // along -z in LPS), so f = a Y00 + b Y10 with b < 0 pushes the base out ~3x more than the apex
  // (docs/design.md, Applied force).
  auto asset = test::ellipsoid_pair(40000, 2, 3);
  test::set_local_transfer(asset, 1.f);
  asset.directions = asset.normals;  // the paper's model, whose force pattern this is: every vertex along its normal
  auto drawable = LungDrawable::create(asset);
  ASSERT_TRUE(drawable) << drawable.error();
  auto renderer = Renderer::create(*drawable);
  ASSERT_TRUE(renderer) << renderer.error();

  // Scale the pattern so that 500 mL moves the base by ~15 mm: D(base) = w A (a Y00 - b Y10n) with Y10n = 0.4886.
  const double area = asset.areas[0];
  const float b = static_cast<float>(-0.03 / (2.0 * area * 0.4886));
  const float a = static_cast<float>(-2.0 * b * 0.4886 / 0.2821);
  const std::vector<float> force = {a, 0.f, b, 0.f};

  constexpr int kW = 640, kH = 720;
  auto target = FrameTarget::create(kW, kH);
  ASSERT_TRUE(target) << target.error();
  HmdGeometry hmd;
  StereoView stereo(hmd);
  // The viewer stands in front of the patient (anterior is -y in LPS), head up along +z.
  const EyeView eye = stereo.mono(look_from({0.f, -900.f, 0.f}, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}), kW, kH);

  Extent extent[2];
  for (int phase = 0; phase < 2; ++phase) {
    const float dv = phase == 0 ? 0.f : 500.f;  // FRC, then end-inspiration
    const LungFrame lungs[2] = {{force, dv, {0.45f, 0.6f, 0.95f}}, {force, dv, {0.9f, 0.45f, 0.45f}}};
    FrameInputs f;
    f.lungs = lungs;
    f.eyes = std::span<const EyeView>(&eye, 1);
    f.level_of_detail = false;
    target->bind();
    Status s = renderer->draw(*drawable, f);
    ASSERT_TRUE(s) << s.error();
    std::vector<std::uint8_t> rgba;
    read_pixels_top_down(0, 0, kW, kH, rgba);
    extent[phase] = silhouette(rgba, kW, kH);
    ASSERT_GE(extent[phase].top, 0) << "nothing drawn";
    const std::string png = std::string(LUNGAR_BINARY_DIR) + (phase == 0 ? "/silhouette-frc.png" : "/silhouette-insp.png");
    EXPECT_TRUE(write_png(png, kW, kH, rgba));
  }
  const int grow_top = extent[0].top - extent[1].top;            // apex moves up
  const int grow_bottom = extent[1].bottom - extent[0].bottom;   // base moves down
  EXPECT_GT(grow_top, 0);
  EXPECT_GT(grow_bottom, 2 * grow_top) << "apex grew " << grow_top << " px, base " << grow_bottom << " px";

  // Widening: rows a fifth of the height from the base against rows a fifth from the apex (FRC rows).
  const int height = extent[0].bottom - extent[0].top;
  const int lower = extent[0].bottom - height / 5, upper = extent[0].top + height / 5;
  const int widen_lower = extent[1].width[lower] - extent[0].width[lower];
  const int widen_upper = extent[1].width[upper] - extent[0].width[upper];
  EXPECT_GT(widen_lower, widen_upper) << "lower rows widened " << widen_lower << " px, upper " << widen_upper;
}

}  // namespace
}  // namespace lungar::render
