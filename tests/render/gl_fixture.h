/// @file gl_fixture.h
/// @brief One headless GLES 3 context (Mesa llvmpipe through surfaceless EGL) shared by a test suite.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include "config/base/result.h"
#include "platform/egl/egl_context.h"
#include "render/stereo_view.h"

namespace lungar::test {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (context_ != nullptr) return;
    auto c = platform::EglContext::headless();
    ASSERT_TRUE(c) << c.error();
    context_ = c.take().release();  // lives to the end of the process: llvmpipe dislikes teardown at exit
  }
  // Another suite may have made its own context current (the window test): take the shared one back.
  void SetUp() override { ASSERT_TRUE(context_->make_current()); }
  static platform::EglContext* context_;
};

/// What a GL object's create() made, into `into`; a test failure naming its error otherwise (call it under
/// ASSERT_NO_FATAL_FAILURE, or check `into` after).
template <class T>
void emplace_or_fail(std::optional<T>& into, Result<T> made) {
  ASSERT_TRUE(made) << made.error();
  into.emplace(made.take());
}

/// Both eyes of an HMD with `eye_w` x `eye_h` pixels per eye (the rest of its geometry the defaults), the head at
/// `from` looking at the origin with +z up.
inline std::array<render::EyeView, 2> stereo_eyes(int eye_w, int eye_h, const glm::vec3& from) {
  render::HmdGeometry hmd;
  hmd.eye_width_px = eye_w;
  hmd.eye_height_px = eye_h;
  return render::StereoView(hmd).eyes(render::look_from(from, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}));
}

}  // namespace lungar::test
