/// @file xr_view_targets.cpp
/// @brief Per-view swapchains and framebuffers, format choice, and the projection layer's views.
#include "platform/openxr/xr_view_targets.h"

#include <cstring>

#include "platform/openxr/xr_error.h"
#include "platform/openxr/xr_view_math.h"

#ifndef GL_FRAMEBUFFER_SRGB_EXT
#define GL_FRAMEBUFFER_SRGB_EXT 0x8DB9
#endif

namespace lungar::platform::openxr {
namespace {

bool has_gl_extension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (e != nullptr && std::strcmp(e, name) == 0) return true;
  }
  return false;
}

}  // namespace

Result<std::vector<std::int64_t>> ViewTargets::offered_formats(XrInstance instance, XrSession session) const {
  std::uint32_t count = 0;
  XrResult r = xrEnumerateSwapchainFormats(session, 0, &count, nullptr);
  if (XR_FAILED(r)) return fail(xr_error(instance, "xrEnumerateSwapchainFormats", r));
  std::vector<std::int64_t> formats(count);
  r = xrEnumerateSwapchainFormats(session, count, &count, formats.data());
  if (XR_FAILED(r)) return fail(xr_error(instance, "xrEnumerateSwapchainFormats", r));
  return formats;
}

Status ViewTargets::create(const Instance& instance, XrSession session) {
  clear();
  auto offered = offered_formats(instance.handle(), session);
  if (!offered) return fail(offered.error());
  const auto color = choose_color_format(*offered);
  if (!color) return fail("OpenXR: " + instance.runtime().text() + ": expected GL_SRGB8_ALPHA8 or GL_RGBA8 swapchains");
  // 0: no depth swapchain (the runtime takes no depth layers, or none of the formats lungar draws into).
  const std::int64_t depth = instance.depth_layer() ? choose_depth_format(*offered).value_or(0) : 0;
  srgb_ = *color == GL_SRGB8_ALPHA8;
  srgb_write_control_ = srgb_ && has_gl_extension("GL_EXT_sRGB_write_control");
  depth_attachment_ = depth == GL_DEPTH24_STENCIL8 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
  formats_ = std::string(gl_format_name(*color)) +
             (srgb_ ? (srgb_write_control_ ? " (values written as display values)" : " (encoded from linear)") : "") +
             ", depth " + (depth != 0 ? std::string(gl_format_name(depth)) + " (depth layer)" : "not submitted");
  width_ = instance.views()[0].recommendedImageRectWidth;
  height_ = instance.views()[0].recommendedImageRectHeight;
  views_.resize(kViews);
  for (std::size_t i = 0; i < kViews; ++i) {
    View& v = views_[i];
    auto c = Swapchain::create(instance.handle(), session, *color, width_, height_,
                               XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT, "colour");
    if (!c) return fail(c.error());
    v.color.emplace(c.take());
    if (depth != 0) {
      auto d = Swapchain::create(instance.handle(), session, depth, width_, height_,
                                 XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "depth");
      if (!d) return fail(d.error());
      v.depth.emplace(d.take());
    } else {
      v.depth_buffer = render::gl::Renderbuffer::create();
      glBindRenderbuffer(GL_RENDERBUFFER, v.depth_buffer.id());
      glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, static_cast<GLsizei>(width_),
                            static_cast<GLsizei>(height_));
    }
    v.framebuffer = render::gl::Framebuffer::create();
  }
  return ok();
}

void ViewTargets::clear() {
  views_.clear();  // swapchains first: the session that owns them may go next
}

Status ViewTargets::attach(View& v, GLuint color, GLuint depth) {
  glBindFramebuffer(GL_FRAMEBUFFER, v.framebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
  if (v.depth) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, depth_attachment_, GL_TEXTURE_2D, depth, 0);
  } else {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, v.depth_buffer.id());
  }
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char text[96];
    std::snprintf(text, sizeof text, "OpenXR: swapchain framebuffer: expected complete, got status 0x%04x", status);
    return fail(text);
  }
  return ok();
}

Status ViewTargets::bind(std::size_t view) {
  if (view >= views_.size()) return fail("OpenXR: view " + std::to_string(view) + ": expected fewer than 2");
  View& v = views_[view];
  if (!v.acquired) {
    auto color = v.color->acquire();
    if (!color) return fail(color.error());
    GLuint depth = 0;
    v.acquired = true;
    if (v.depth) {
      auto d = v.depth->acquire();
      if (!d) return fail(d.error());
      depth = *d;
    }
    if (auto attached = attach(v, *color, depth); !attached) return attached;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, v.framebuffer.id());
  glViewport(0, 0, static_cast<GLsizei>(width_), static_cast<GLsizei>(height_));
  if (srgb_write_control_) glDisable(GL_FRAMEBUFFER_SRGB_EXT);
  return ok();
}

Result<bool> ViewTargets::release_all() {
  bool all = !views_.empty();
  for (View& v : views_) {
    all = all && v.acquired;
    v.acquired = false;
    if (auto r = v.color->release(); !r) return fail(r.error());
    if (v.depth) {
      if (auto r = v.depth->release(); !r) return fail(r.error());
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return all;
}

std::span<const XrCompositionLayerProjectionView> ViewTargets::layer_views(std::span<const XrView> located,
                                                                            float near_mm, float far_mm) {
  for (std::size_t i = 0; i < views_.size() && i < located.size(); ++i) {
    XrCompositionLayerProjectionView& p = layer_views_[i];
    p = xr_struct<XrCompositionLayerProjectionView>(XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
    p.pose = located[i].pose;
    p.fov = located[i].fov;
    p.subImage.swapchain = views_[i].color->handle();
    p.subImage.imageRect = {{0, 0}, {static_cast<std::int32_t>(width_), static_cast<std::int32_t>(height_)}};
    if (views_[i].depth) {
      // The renderer's projection maps near to window depth 0 and far to 1 (glDepthRangef's default).
      XrCompositionLayerDepthInfoKHR& d = depth_infos_[i];
      d = xr_struct<XrCompositionLayerDepthInfoKHR>(XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR);
      d.subImage.swapchain = views_[i].depth->handle();
      d.subImage.imageRect = p.subImage.imageRect;
      d.minDepth = 0.f;
      d.maxDepth = 1.f;
      d.nearZ = near_mm / kMillimetresPerMetre;
      d.farZ = far_mm / kMillimetresPerMetre;
      p.next = &d;
    }
  }
  return {layer_views_.data(), views_.size()};
}

}  // namespace lungar::platform::openxr
