/// @file lung_scene.cpp
/// @brief Asset -> drawable -> renderer, once.
#include "platform/runtime/lung_scene.h"

namespace lungar::platform {

Result<std::shared_ptr<LungScene>> LungScene::create(sim::BakedAsset asset, std::string name,
                                                     const render::DrawableOptions& options) {
  sim::PatientState healthy = sim::PatientState::of(asset);
  return create(std::move(asset), std::move(healthy), std::move(name), options);
}

Result<std::shared_ptr<LungScene>> LungScene::create(sim::BakedAsset asset, sim::PatientState patient, std::string name,
                                                     const render::DrawableOptions& options) {
  if (patient.lungs.size() != asset.lungs.size())
    return fail("asset " + name + ": expected a patient state of its " + std::to_string(asset.lungs.size()) +
                " lungs, got " + std::to_string(patient.lungs.size()));
  std::shared_ptr<LungScene> scene(new LungScene());
  scene->asset_ = std::move(asset);
  scene->patient_ = std::move(patient);
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
