/// @file lung_scene.h
/// @brief The lungs on the GPU: the baked asset (never written once loaded), the patient as loaded (the
/// pathologies given at load: sim/patient/patient_state.h), the asset's drawable (vertex buffers, coefficients)
/// and the renderer's programs, built once per GL context and shared by every Runtime that draws them (the bench builds
/// one Runtime per measured configuration over one scene).
/// @ingroup platform
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "config/base/result.h"
#include "render/lung_drawable.h"
#include "render/renderer.h"
#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::platform {

class LungScene {
 public:
  /// Uploads `asset`; needs a current GLES 3 context. `patient` is the patient as loaded (one state per lung of
  /// the asset), where a run starts from. `name` says what is drawn (a file, a cache entry) in the stats JSON's
  /// `asset`.
  static Result<std::shared_ptr<LungScene>> create(sim::BakedAsset asset, sim::PatientState patient, std::string name,
                                                   const render::DrawableOptions& options = {});
  /// `asset` with the healthy patient.
  static Result<std::shared_ptr<LungScene>> create(sim::BakedAsset asset, std::string name,
                                                   const render::DrawableOptions& options = {});

  const sim::BakedAsset& asset() const { return asset_; }
  const sim::PatientState& patient_at_load() const { return patient_; }
  render::LungDrawable& drawable() { return *drawable_; }
  render::Renderer& renderer() { return *renderer_; }
  const std::string& name() const { return name_; }

 private:
  LungScene() = default;
  sim::BakedAsset asset_;
  sim::PatientState patient_;
  std::string name_;
  std::optional<render::LungDrawable> drawable_;
  std::optional<render::Renderer> renderer_;
};

}  // namespace lungar::platform
