/// @file egl_context.cpp
/// @brief EGL display, config, context and surface set-up for the headless and X11 outputs.
#include "platform/egl/egl_context.h"

#include "platform/egl/x11_outputs.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
// Xlib defines Status (and more) as macros; Status is meant below.
#undef Status

#include <cstdio>

namespace lungar::platform {
namespace {

using ContextResult = Result<std::unique_ptr<EglContext>>;

std::string egl_error(const char* what) {
  char text[128];
  std::snprintf(text, sizeof text, "EGL: %s failed (error 0x%04x)", what, eglGetError());
  return text;
}

bool has_extension(const char* list, const std::string& name) {
  if (list == nullptr) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

// A surfaceless display (Mesa), else the first EGL device.
EGLDisplay headless_display(std::string& platform) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
      platform = "surfaceless";
      return d;
    }
  }
  if (has_extension(client, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (query_devices != nullptr && query_devices(8, devices, &count) && count > 0) {
      EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
      if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
        platform = "device";
        return d;
      }
    }
  }
  return EGL_NO_DISPLAY;
}

EGLContext create_es3_context(EGLDisplay display, EGLConfig config) {
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
}

/// An X window for `visual` at the options' place and size: decorated on a desktop, undecorated and above the
/// window manager's reach when full-screen on an HMD's output in extended mode. Asks for WM_DELETE_WINDOW.
Window create_x_window(Display* x, const WindowOptions& o, const XVisualInfo& visual, unsigned long& wm_delete) {
  const Window root = RootWindow(x, visual.screen);
  XSetWindowAttributes attributes{};
  attributes.colormap = XCreateColormap(x, root, visual.visual, AllocNone);
  attributes.event_mask = StructureNotifyMask | KeyPressMask | ExposureMask;
  attributes.background_pixel = 0;
  attributes.border_pixel = 0;
  attributes.override_redirect = o.fullscreen ? True : False;
  const unsigned long mask = CWColormap | CWEventMask | CWBackPixel | CWBorderPixel | CWOverrideRedirect;
  const Window w = XCreateWindow(x, root, o.x_px, o.y_px, static_cast<unsigned>(o.width_px),
                                 static_cast<unsigned>(o.height_px), 0, visual.depth, InputOutput, visual.visual, mask,
                                 &attributes);
  XStoreName(x, w, o.title.c_str());
  XSizeHints hints{};
  hints.flags = PPosition | PSize;  // ask the window manager to honour the configured position
  hints.x = o.x_px;
  hints.y = o.y_px;
  hints.width = o.width_px;
  hints.height = o.height_px;
  XSetWMNormalHints(x, w, &hints);
  Atom deleted = XInternAtom(x, "WM_DELETE_WINDOW", False);
  XSetWMProtocols(x, w, &deleted, 1);
  wm_delete = deleted;
  if (o.fullscreen) {
    Atom state = XInternAtom(x, "_NET_WM_STATE", False);
    Atom full = XInternAtom(x, "_NET_WM_STATE_FULLSCREEN", False);
    XChangeProperty(x, w, state, XA_ATOM, 32, PropModeReplace, reinterpret_cast<unsigned char*>(&full), 1);
  }
  XMapRaised(x, w);
  XMoveWindow(x, w, o.x_px, o.y_px);
  XFlush(x);
  return w;
}

}  // namespace

ContextResult EglContext::headless() {
  std::unique_ptr<EglContext> c(new EglContext());
  EGLDisplay display = headless_display(c->platform_);
  if (display == EGL_NO_DISPLAY) {
    return fail("EGL: headless display: expected EGL_MESA_platform_surfaceless or EGL_EXT_platform_device");
  }
  c->display_ = display;
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    return fail("EGL: headless display: expected EGL_KHR_surfaceless_context");
  }
  if (!eglBindAPI(EGL_OPENGL_ES_API)) return fail(egl_error("eglBindAPI(OpenGL ES)"));
  // EGL_SURFACE_TYPE defaults to EGL_WINDOW_BIT, which a surfaceless display has none of: ask for any.
  const EGLint wanted[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, wanted, &config, 1, &configs) || configs < 1) {
    return fail(egl_error("eglChooseConfig(OpenGL ES 3)"));
  }
  c->context_ = create_es3_context(display, config);
  c->config_ = config;
  if (c->context_ == EGL_NO_CONTEXT) return fail(egl_error("eglCreateContext(OpenGL ES 3.0)"));
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, c->context_)) {
    return fail(egl_error("eglMakeCurrent(surfaceless)"));
  }
  return c;
}

ContextResult EglContext::window(const WindowOptions& options) {
  WindowOptions o = options;
  if (o.width_px <= 0 || o.height_px <= 0) {
    return fail("window: size: expected positive width and height, got " + std::to_string(o.width_px) +
                           "x" + std::to_string(o.height_px));
  }
  std::unique_ptr<EglContext> c(new EglContext());
  Display* x = XOpenDisplay(o.display_name.empty() ? nullptr : o.display_name.c_str());
  if (x == nullptr) {
    return fail("window: X display '" + (o.display_name.empty() ? std::string("$DISPLAY") : o.display_name) +
                           "': cannot open (set DISPLAY, or use the headless output)");
  }
  c->x_display_ = x;
  c->platform_ = "x11";
  if (o.fullscreen && !o.output.empty()) {
    auto area = find_x11_output(x, o.output);
    if (!area) return fail("window: " + area.error());
    o.x_px = area->x;
    o.y_px = area->y;
    o.width_px = area->width;
    o.height_px = area->height;
  }
  EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, x, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    return fail(egl_error("eglGetPlatformDisplay(X11)"));
  }
  c->display_ = display;
  if (!eglBindAPI(EGL_OPENGL_ES_API)) return fail(egl_error("eglBindAPI(OpenGL ES)"));
  const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_RED_SIZE, 8,
                           EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, wanted, &config, 1, &configs) || configs < 1) {
    return fail(egl_error("eglChooseConfig(window, RGB8, depth 24, OpenGL ES 3)"));
  }
  EGLint visual_id = 0;
  eglGetConfigAttrib(display, config, EGL_NATIVE_VISUAL_ID, &visual_id);
  XVisualInfo templ{};
  templ.visualid = static_cast<VisualID>(visual_id);
  int visuals = 0;
  XVisualInfo* visual = XGetVisualInfo(x, VisualIDMask, &templ, &visuals);
  if (visual == nullptr) return fail("window: no X visual for the EGL config");

  c->window_ = create_x_window(x, o, *visual, c->wm_delete_);
  XFree(visual);
  c->width_ = o.width_px;
  c->height_ = o.height_px;
  c->x_ = o.x_px;
  c->y_ = o.y_px;

  Window native = c->window_;
  c->surface_ = eglCreatePlatformWindowSurface(display, config, &native, nullptr);
  if (c->surface_ == EGL_NO_SURFACE) return fail(egl_error("eglCreatePlatformWindowSurface(X11)"));
  c->context_ = create_es3_context(display, config);
  c->config_ = config;
  if (c->context_ == EGL_NO_CONTEXT) return fail(egl_error("eglCreateContext(OpenGL ES 3.0)"));
  if (!eglMakeCurrent(display, c->surface_, c->surface_, c->context_)) {
    return fail(egl_error("eglMakeCurrent(window)"));
  }
  eglSwapInterval(display, o.vsync ? 1 : 0);
  return c;
}

EglContext::~EglContext() {
  if (display_ != nullptr) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != nullptr) eglDestroyContext(display_, context_);
    if (surface_ != nullptr) eglDestroySurface(display_, surface_);
    // eglInitialize is not reference-counted: the surfaceless default display is shared by every headless context
    // in the process, so only a display of our own X connection is terminated.
    if (x_display_ != nullptr) eglTerminate(display_);
  }
  if (x_display_ != nullptr) {
    Display* x = static_cast<Display*>(x_display_);
    if (window_ != 0) XDestroyWindow(x, window_);
    XCloseDisplay(x);
  }
}

Status EglContext::make_current() {
  EGLSurface surface = surface_ != nullptr ? surface_ : EGL_NO_SURFACE;
  if (!eglMakeCurrent(display_, surface, surface, context_)) return fail(egl_error("eglMakeCurrent"));
  return ok();
}

Status EglContext::swap_buffers() {
  if (surface_ == nullptr) return ok();
  if (!eglSwapBuffers(display_, surface_)) return fail(egl_error("eglSwapBuffers"));
  return ok();
}

bool EglContext::process_events() {
  if (x_display_ == nullptr) return open_;
  Display* x = static_cast<Display*>(x_display_);
  while (XPending(x) > 0) {
    XEvent event;
    XNextEvent(x, &event);
    if (event.type == ClientMessage && static_cast<unsigned long>(event.xclient.data.l[0]) == wm_delete_) open_ = false;
    if (event.type == ConfigureNotify) {
      width_ = event.xconfigure.width;
      height_ = event.xconfigure.height;
    }
    if (event.type == KeyPress) {
      const KeySym key = XLookupKeysym(&event.xkey, 0);
      if (key == XK_Escape || key == XK_q) open_ = false;
      if (key >= XK_a && key <= XK_z && keys_.size() < 64) keys_ += static_cast<char>('a' + (key - XK_a));
      // Confirm and undo for screens that ask the user (lungar calibrate-display's crosshairs).
      if (key == XK_space && keys_.size() < 64) keys_ += ' ';
      if ((key == XK_Return || key == XK_KP_Enter) && keys_.size() < 64) keys_ += '\n';
      if (key == XK_BackSpace && keys_.size() < 64) keys_ += '\b';
    }
  }
  return open_;
}

namespace {

std::string gl_text(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s != nullptr ? s : "?";
}

}  // namespace

std::string EglContext::describe() const {
  return "EGL " + platform_ + ", " + gl_text(GL_VENDOR) + ", " + gl_text(GL_RENDERER) + ", " + gl_text(GL_VERSION);
}

EglContext::Versions EglContext::versions() const {
  const char* egl = eglQueryString(static_cast<EGLDisplay>(display_), EGL_VERSION);
  return {egl != nullptr ? egl : "?", gl_text(GL_VERSION), gl_text(GL_RENDERER)};
}

}  // namespace lungar::platform
