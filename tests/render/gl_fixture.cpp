/// @file gl_fixture.cpp
/// @brief The shared context's storage.
#include "tests/render/gl_fixture.h"

namespace lungar::test {
platform::EglContext* GlTest::context_ = nullptr;
}  // namespace lungar::test
