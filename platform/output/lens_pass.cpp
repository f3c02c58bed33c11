/// @file lens_pass.cpp
/// @brief The scene target, the per-channel coefficients and each eye's lens centre, set once.
#include "platform/output/lens_pass.h"

#include "platform/output/hmd_views.h"

namespace lungar::platform {

Result<LensPass> LensPass::create(const HmdSettings& hmd, int width, int height) {
  auto scene = render::FrameTarget::create(width, height);
  if (!scene) return scene.with_context("lens distortion: ");
  auto pass = render::LensDistortion::create();
  if (!pass) return pass.with_context("lens distortion: ");
  LensPass lens(scene.take(), pass.take());
  for (int c = 0; c < 3; ++c) {
    lens.params_.k1[c] = static_cast<float>(hmd.lens.k1[c]);
    lens.params_.k2[c] = static_cast<float>(hmd.lens.k2[c]);
  }
  const render::HmdGeometry geometry = hmd_geometry(hmd);
  lens.centres_ = {render::lens_centre(geometry, true), render::lens_centre(geometry, false)};
  if (hmd.view == View::Mono) lens.centres_[0] = {0.5f, 0.5f};
  return lens;
}

Status LensPass::apply(const FrameViews& views) const {
  const auto centres = std::span<const std::array<float, 2>>(centres_.data(), views.count);
  if (Status warped = pass_.apply(scene_, views.span(), centres, params_); !warped) {
    return warped.with_context("lens distortion: ");
  }
  return ok();
}

}  // namespace lungar::platform
