/// @file lung_scene.cpp
/// @brief Asset -> drawable -> renderer, once.
#include "platform/runtime/lung_scene.h"

namespace lungar::platform {

Result<std::shared_ptr<LungScene>> LungScene::create(sim::BakedAsset asset, std::string name,
                                                     const render::DrawableOptions& options) {
  std::shared_ptr<LungScene> scene(new LungScene());
  scene->asset_ = std::move(asset);
  scene->name_ = std::move(name);
  auto drawable = render::LungDrawable::create(scene->asset_, options);
  if (!drawable) return drawable.with_context("asset " + scene->name_ + ": ");
  scene->drawable_.emplace(drawable.take());
  auto renderer = render::Renderer::create(*scene->drawable_);
  if (!renderer) return renderer.with_context("renderer: ");
  scene->renderer_.emplace(renderer.take());
  return scene;
}

}  // namespace lungar::platform
