/// @file gl_objects.cpp
/// @brief The GL calls behind gl_objects.h's owners: one glGen*/glDelete* per kind of name.
#include "render/gl_objects.h"

#include <GLES3/gl3.h>

#include <type_traits>

namespace lungar::render::gl {

// The owners hold GL's names and uniform locations in fixed-width types; they are GL's own types on every
// platform GLES 3 runs on (khrplatform.h), so no value is converted on its way to or from GL.
static_assert(std::is_same_v<GLuint, std::uint32_t>);
static_assert(std::is_same_v<GLint, std::int32_t>);

std::uint32_t generate(Kind kind) {
  GLuint id = 0;
  switch (kind) {
    case Kind::Buffer:
      glGenBuffers(1, &id);
      break;
    case Kind::VertexArray:
      glGenVertexArrays(1, &id);
      break;
    case Kind::Texture:
      glGenTextures(1, &id);
      break;
    case Kind::Framebuffer:
      glGenFramebuffers(1, &id);
      break;
    case Kind::Renderbuffer:
      glGenRenderbuffers(1, &id);
      break;
    case Kind::TransformFeedback:
      glGenTransformFeedbacks(1, &id);
      break;
    case Kind::Program:
      id = glCreateProgram();
      break;
  }
  return id;
}

void release(Kind kind, std::uint32_t id) {
  switch (kind) {
    case Kind::Buffer:
      glDeleteBuffers(1, &id);
      break;
    case Kind::VertexArray:
      glDeleteVertexArrays(1, &id);
      break;
    case Kind::Texture:
      glDeleteTextures(1, &id);
      break;
    case Kind::Framebuffer:
      glDeleteFramebuffers(1, &id);
      break;
    case Kind::Renderbuffer:
      glDeleteRenderbuffers(1, &id);
      break;
    case Kind::TransformFeedback:
      glDeleteTransformFeedbacks(1, &id);
      break;
    case Kind::Program:
      glDeleteProgram(id);
      break;
  }
}

std::int32_t Program::uniform(const char* name) const { return glGetUniformLocation(id(), name); }

}  // namespace lungar::render::gl
