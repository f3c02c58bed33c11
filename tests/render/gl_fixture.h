/// @file gl_fixture.h
/// @brief One headless GLES 3 context (Mesa llvmpipe through surfaceless EGL) shared by a test suite.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "platform/egl/egl_context.h"

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

}  // namespace lungar::test
