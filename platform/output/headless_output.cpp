/// @file headless_output.cpp
/// @brief A surfaceless context and one framebuffer object.
#include "platform/output/headless_output.h"

#include <GLES3/gl3.h>

#include "render/png_snapshot.h"

namespace lungar::platform {

HeadlessOutput::HeadlessOutput(std::shared_ptr<EglContext> context, const HmdSettings& hmd,
                               render::FrameTarget target, double max_fps)
    : context_(std::move(context)),
      target_(std::move(target)),
      views_(hmd, target_->width(), target_->height()),
      pacer_(max_fps) {}

Result<std::unique_ptr<HeadlessOutput>> HeadlessOutput::create(const HmdSettings& hmd,
                                                               std::shared_ptr<EglContext> context, double max_fps) {
  if (!context) {
    auto made = EglContext::headless();
    if (!made) return made.with_context("display: ");
    context = made.take();
  } else if (Status current = context->make_current(); !current) {
    return current.with_context("display: ");
  }
  const auto [w, h] = HmdViews::target_size(hmd);
  auto target = render::FrameTarget::create(w, h);
  if (!target) return target.with_context("display: ");
  std::unique_ptr<HeadlessOutput> output(new HeadlessOutput(std::move(context), hmd, target.take(), max_fps));
  if (hmd.lens.enabled) {
    auto lens = LensPass::create(hmd, w, h);
    if (!lens) return lens.with_context("");
    output->lens_.emplace(lens.take());
  }
  return output;
}

void HeadlessOutput::bind_target(std::size_t) {
  if (lens_) {
    lens_->bind_scene();
  } else {
    target_->bind();
  }
}

Status HeadlessOutput::finish_scene(const FrameViews& views) {
  if (!lens_) return ok();
  target_->bind();
  return lens_->apply(views);
}

std::string HeadlessOutput::describe() const {
  return context_->describe() + " (headless, " + std::to_string(target_->width()) + "x" +
         std::to_string(target_->height()) + ")";
}

Status HeadlessOutput::end_frame() {
  glFinish();  // the frame is done when its pixels are
  return ok();
}

Status HeadlessOutput::snapshot(const std::string& png_path) {
  target_->bind();
  return render::snapshot_png(png_path, 0, 0, target_->width(), target_->height());
}

}  // namespace lungar::platform
