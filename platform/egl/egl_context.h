/// @file egl_context.h
/// @brief An OpenGL ES 3.0 context through EGL: headless (surfaceless Mesa, or EGL_EXT_platform_device, rendering
/// into framebuffer objects) or an X11 window with an EGL window surface (desktop, or full-screen at a given
/// position and size for an HMD in extended mode).
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "config/base/result.h"

namespace lungar::platform {

struct WindowOptions {
  int x_px = 0, y_px = 0;          ///< position in the X screen (an HMD output's origin in extended mode)
  int width_px = 1280, height_px = 720;
  bool fullscreen = false;         ///< undecorated, above everything, covering x, y, width, height
  /// With fullscreen: the X output (RandR monitor, e.g. "HDMI-1") to cover; its position and size replace x, y,
  /// width and height. Empty: use those.
  std::string output;
  bool vsync = true;
  std::string title = "lungar";
  std::string display_name;        ///< X display; empty: $DISPLAY
};

class EglContext {
 public:
  /// A context with no window: draw into render::FrameTarget. Tries EGL_PLATFORM_SURFACELESS_MESA, then
  /// EGL_EXT_platform_device.
  static Result<std::unique_ptr<EglContext>> headless();
  /// An X11 window with an EGL window surface; its default framebuffer is what swap_buffers() shows.
  static Result<std::unique_ptr<EglContext>> window(const WindowOptions& options);

  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  bool has_window() const { return window_ != 0; }
  int width() const { return width_; }    ///< window size (0 headless)
  int height() const { return height_; }
  int x() const { return x_; }            ///< where the window was put in the X screen (0 headless)
  int y() const { return y_; }
  /// Makes this context (and its window surface) current on the calling thread.
  Status make_current();
  /// Presents the window's back buffer; a no-op headless.
  Status swap_buffers();
  /// Handles pending window events; false once the window was closed or Escape/q pressed.
  bool process_events();
  /// The letter keys pressed since the last call (lower-case), and Space, Enter and Backspace as ' ', '\n' and
  /// '\b', collected by process_events().
  std::string take_keys() { return std::exchange(keys_, {}); }
  /// "EGL platform, GL_VENDOR, GL_RENDERER, GL_VERSION", for logs.
  std::string describe() const;
  /// What `lungar doctor` reports of the context: EGL_VERSION, GL_VERSION and GL_RENDERER ("?" where one is missing).
  struct Versions {
    std::string egl, gl, renderer;
  };
  Versions versions() const;
  /// The EGLDisplay, EGLConfig and EGLContext, for a runtime that takes the context (OpenXR's XR_MNDX_egl_enable).
  void* egl_display() const { return display_; }
  void* egl_config() const { return config_; }
  void* egl_context() const { return context_; }

 private:
  EglContext() = default;
  void* display_ = nullptr;    // EGLDisplay
  void* context_ = nullptr;    // EGLContext
  void* config_ = nullptr;     // EGLConfig the context was made with
  void* surface_ = nullptr;    // EGLSurface (window only)
  void* x_display_ = nullptr;  // Display*
  unsigned long window_ = 0;   // Window
  unsigned long wm_delete_ = 0;
  int width_ = 0, height_ = 0;
  int x_ = 0, y_ = 0;
  bool open_ = true;
  std::string keys_;
  std::string platform_;
};

}  // namespace lungar::platform
