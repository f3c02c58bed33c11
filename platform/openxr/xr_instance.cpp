/// @file xr_instance.cpp
/// @brief Instance creation with the extensions lungar needs, the HMD system and its stereo views.
#include "platform/openxr/xr_instance.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "platform/openxr/xr_error.h"

namespace lungar::platform::openxr {
namespace {

Result<std::vector<std::string>> offered_extensions() {
  std::uint32_t count = 0;
  XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
  if (XR_FAILED(r)) return fail(xr_error(XR_NULL_HANDLE, "xrEnumerateInstanceExtensionProperties", r));
  std::vector<XrExtensionProperties> properties(count, xr_struct<XrExtensionProperties>(XR_TYPE_EXTENSION_PROPERTIES));
  r = xrEnumerateInstanceExtensionProperties(nullptr, count, &count, properties.data());
  if (XR_FAILED(r)) return fail(xr_error(XR_NULL_HANDLE, "xrEnumerateInstanceExtensionProperties", r));
  std::vector<std::string> names;
  for (const auto& p : properties) names.emplace_back(p.extensionName);
  return names;
}

std::string version_text(XrVersion v) {
  return std::to_string(XR_VERSION_MAJOR(v)) + "." + std::to_string(XR_VERSION_MINOR(v)) + "." +
         std::to_string(XR_VERSION_PATCH(v));
}

}  // namespace

Result<Instance> Instance::create(const InstanceOptions& options) {
  // The loader prints its own errors on stderr (several lines for a missing runtime); lungar says it in one.
  // XR_LOADER_DEBUG=error (or info, all) set by the user brings them back.
  setenv("XR_LOADER_DEBUG", "none", /*overwrite=*/0);
  auto offered = offered_extensions();
  if (!offered) return fail(offered.error());
  auto has = [&](const char* name) { return std::find(offered->begin(), offered->end(), name) != offered->end(); };
  // EGL + GLES on Linux: XR_KHR_opengl_es_enable alone binds only Android's EGL; XR_MNDX_egl_enable takes any EGL
  // context. The ES extension is still needed for its requirements call and its swapchain image structure.
  std::vector<const char*> wanted;
  if (options.headless) {
    wanted.push_back(XR_MND_HEADLESS_EXTENSION_NAME);
  } else {
    wanted.push_back(XR_MNDX_EGL_ENABLE_EXTENSION_NAME);
    wanted.push_back(XR_KHR_OPENGL_ES_ENABLE_EXTENSION_NAME);
  }
  for (const char* name : wanted) {
    if (!has(name)) return fail("OpenXR: runtime: expected the extension " + std::string(name) + ", not offered");
  }
  Instance out;
  out.headless_ = options.headless;
  out.depth_layer_ = !options.headless && has(XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
  if (out.depth_layer_) wanted.push_back(XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
  const bool timespec = has(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
  if (timespec) wanted.push_back(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);

  std::vector<const char*> layers;
  for (const auto& l : options.api_layers) layers.push_back(l.c_str());
  auto info = xr_struct<XrInstanceCreateInfo>(XR_TYPE_INSTANCE_CREATE_INFO);
  std::snprintf(info.applicationInfo.applicationName, sizeof info.applicationInfo.applicationName, "%s",
                options.application.c_str());
  std::snprintf(info.applicationInfo.engineName, sizeof info.applicationInfo.engineName, "lungar");
  info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;  // 1.0.20, the headers' (and loader's) version
  info.enabledExtensionCount = static_cast<std::uint32_t>(wanted.size());
  info.enabledExtensionNames = wanted.data();
  info.enabledApiLayerCount = static_cast<std::uint32_t>(layers.size());
  info.enabledApiLayerNames = layers.data();
  if (XrResult r = xrCreateInstance(&info, out.instance_.out()); XR_FAILED(r)) {
    return fail(xr_error(XR_NULL_HANDLE, "xrCreateInstance", r));
  }
  auto properties = xr_struct<XrInstanceProperties>(XR_TYPE_INSTANCE_PROPERTIES);
  if (XrResult r = xrGetInstanceProperties(out.instance_.get(), &properties); XR_FAILED(r)) {
    return fail(xr_error(out.instance_.get(), "xrGetInstanceProperties", r));
  }
  out.runtime_.name = properties.runtimeName;
  out.runtime_.version = version_text(properties.runtimeVersion);
  if (timespec) {
    auto to = out.function("xrConvertTimeToTimespecTimeKHR");
    auto from = out.function("xrConvertTimespecTimeToTimeKHR");
    if (to && from) {
      out.to_timespec_ = reinterpret_cast<PFN_xrConvertTimeToTimespecTimeKHR>(*to);
      out.from_timespec_ = reinterpret_cast<PFN_xrConvertTimespecTimeToTimeKHR>(*from);
    }
  }
  if (auto picked = out.pick_system(); !picked) return fail(picked.error());
  return out;
}

Status Instance::pick_system() {
  auto get = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
  get.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  if (XrResult r = xrGetSystem(instance_.get(), &get, &system_); XR_FAILED(r)) {
    return fail(xr_error(instance_.get(), "xrGetSystem(head-mounted display)", r) +
                (r == XR_ERROR_FORM_FACTOR_UNAVAILABLE ? "; is the headset connected and on?" : ""));
  }
  auto properties = xr_struct<XrSystemProperties>(XR_TYPE_SYSTEM_PROPERTIES);
  if (XrResult r = xrGetSystemProperties(instance_.get(), system_, &properties); XR_FAILED(r)) {
    return fail(xr_error(instance_.get(), "xrGetSystemProperties", r));
  }
  runtime_.system_name = properties.systemName;
  std::uint32_t count = 0;
  XrResult r = xrEnumerateViewConfigurationViews(instance_.get(), system_, kViewConfiguration, 0, &count, nullptr);
  if (XR_FAILED(r)) return fail(xr_error(instance_.get(), "xrEnumerateViewConfigurationViews(primary stereo)", r));
  views_.assign(count, xr_struct<XrViewConfigurationView>(XR_TYPE_VIEW_CONFIGURATION_VIEW));
  r = xrEnumerateViewConfigurationViews(instance_.get(), system_, kViewConfiguration, count, &count, views_.data());
  if (XR_FAILED(r)) return fail(xr_error(instance_.get(), "xrEnumerateViewConfigurationViews(primary stereo)", r));
  if (views_.size() != 2) {
    return fail("OpenXR: " + runtime_.system_name + ": primary stereo: expected 2 views, got " +
                std::to_string(views_.size()));
  }
  return ok();
}

std::int64_t Instance::to_monotonic_ns(XrTime time) const {
  timespec ts{};
  if (to_timespec_ != nullptr && XR_SUCCEEDED(to_timespec_(instance_.get(), time, &ts))) {
    return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
  }
  return time;
}

XrTime Instance::from_monotonic_ns(std::int64_t ns) const {
  const timespec ts{static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
  XrTime time = 0;
  if (from_timespec_ != nullptr && XR_SUCCEEDED(from_timespec_(instance_.get(), &ts, &time))) return time;
  return ns;
}

Result<PFN_xrVoidFunction> Instance::function(const char* name) const {
  PFN_xrVoidFunction f = nullptr;
  if (XrResult r = xrGetInstanceProcAddr(instance_.get(), name, &f); XR_FAILED(r) || f == nullptr) {
    return fail(xr_error(instance_.get(), (std::string("xrGetInstanceProcAddr(") + name + ")").c_str(), r));
  }
  return f;
}

}  // namespace lungar::platform::openxr
