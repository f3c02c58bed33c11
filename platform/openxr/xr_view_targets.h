/// @file xr_view_targets.h
/// @brief What each view is drawn into: its colour swapchain (sRGB preferred), its depth swapchain when the runtime
/// takes depth layers (else a plain depth buffer), one framebuffer; and the projection-layer views that hand them
/// back to the compositor.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "platform/openxr/xr_headers.h"
#include "platform/openxr/xr_instance.h"
#include "platform/openxr/xr_swapchain.h"
#include "render/gl_objects.h"

namespace lungar::platform::openxr {

class ViewTargets {
 public:
  static constexpr std::size_t kViews = 2;

  /// Chooses the formats among those the session offers and makes each view's swapchains at the runtime's
  /// recommended size. Needs lungar's context current.
  Status create(const Instance& instance, XrSession session);
  /// Destroys the swapchains and framebuffers (before the session goes).
  void clear();

  /// Acquires view i's images on the first call of a frame, attaches them, binds the framebuffer, viewport.
  Status bind(std::size_t view);
  /// Releases every acquired image; returns whether every view was drawn this frame.
  Result<bool> release_all();
  /// The projection layer's views for `located` (poses and fields of view as located), with their depth.
  std::span<const XrCompositionLayerProjectionView> layer_views(std::span<const XrView> located, float near_mm,
                                                                 float far_mm);

  std::size_t count() const { return views_.size(); }
  int width() const { return static_cast<int>(width_); }
  int height() const { return static_cast<int>(height_); }
  const std::string& formats() const { return formats_; }
  GLuint framebuffer(std::size_t view) const { return views_[view].framebuffer.id(); }

 private:
  struct View {
    std::optional<Swapchain> color;
    std::optional<Swapchain> depth;          ///< with XR_KHR_composition_layer_depth
    render::gl::Renderbuffer depth_buffer;   ///< without it
    render::gl::Framebuffer framebuffer;
    bool acquired = false;
  };
  Result<std::vector<std::int64_t>> offered_formats(XrInstance instance, XrSession session) const;
  Status attach(View& v, GLuint color, GLuint depth);

  std::vector<View> views_;
  std::uint32_t width_ = 0, height_ = 0;
  bool srgb_write_control_ = false;  ///< GL_EXT_sRGB_write_control: write display values into an sRGB image as-is
  bool srgb_ = false;
  GLenum depth_attachment_ = GL_DEPTH_ATTACHMENT;
  std::string formats_;
  std::array<XrCompositionLayerProjectionView, kViews> layer_views_{};
  std::array<XrCompositionLayerDepthInfoKHR, kViews> depth_infos_{};
};

}  // namespace lungar::platform::openxr
