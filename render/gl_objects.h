/// @file gl_objects.h
/// @brief Move-only RAII owners of GLES 3 object names (buffers, vertex arrays, textures, framebuffers, ...).
///
/// Each owner deletes its name on destruction; the GL context that created it must be current then.
#pragma once

#include <GLES3/gl3.h>

#include <initializer_list>
#include <utility>

#include "config/base/unique_handle.h"

namespace lungar::render::gl {

/// One owned GL object id, released by `Free` when the owner is destroyed or reset; move-only.
template <void (*Free)(GLuint)>
class Owned : public UniqueHandle<GLuint, Free> {
 public:
  using UniqueHandle<GLuint, Free>::UniqueHandle;
  GLuint id() const { return this->get(); }
};

/// Frees one name made by glGen*: the glDelete* of the same kind, for a count of one.
template <void (*Delete)(GLsizei, const GLuint*)>
void delete_one(GLuint id) {
  Delete(1, &id);
}

/// One GL name of a glGen*/glDelete* kind.
template <void (*Gen)(GLsizei, GLuint*), void (*Delete)(GLsizei, const GLuint*)>
class Name : public Owned<delete_one<Delete>> {
 public:
  using Owned<delete_one<Delete>>::Owned;
  static Name create() {
    GLuint id = 0;
    Gen(1, &id);
    return Name(id);
  }
};

// The GL entry points are functions in libGLESv2 (no loader), so their addresses are constant expressions.
using Buffer = Name<glGenBuffers, glDeleteBuffers>;
using VertexArray = Name<glGenVertexArrays, glDeleteVertexArrays>;
using Texture = Name<glGenTextures, glDeleteTextures>;
using Framebuffer = Name<glGenFramebuffers, glDeleteFramebuffers>;
using Renderbuffer = Name<glGenRenderbuffers, glDeleteRenderbuffers>;
using TransformFeedback = Name<glGenTransformFeedbacks, glDeleteTransformFeedbacks>;

/// A linked program; deleted with glDeleteProgram.
class Program : public Owned<glDeleteProgram> {
 public:
  using Owned::Owned;
  GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }
  /// Looks up each (slot, name) pair: -1 where the program has no such active uniform.
  void find_uniforms(std::initializer_list<std::pair<GLint*, const char*>> slots) const {
    for (const auto& [slot, name] : slots) *slot = uniform(name);
  }
};

}  // namespace lungar::render::gl
