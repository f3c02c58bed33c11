/// @file gl_objects.h
/// @brief Move-only RAII owners of GLES 3 object names (buffers, vertex arrays, textures, framebuffers, ...).
///
/// Each owner deletes its name on destruction; the GL context that created it must be current then.
#pragma once

#include <GLES3/gl3.h>

#include <initializer_list>
#include <utility>

namespace lungar::render::gl {

/// One owned GL object id, released by `Free` when the owner is destroyed or reset; move-only.
template <void (*Free)(GLuint)>
class Owned {
 public:
  Owned() = default;
  explicit Owned(GLuint id) : id_(id) {}
  ~Owned() { reset(); }
  Owned(Owned&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Owned& operator=(Owned&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Free(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
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

// The GL entry points are functions in libGLESv2, so their addresses are constant expressions.
inline void gen_buffers(GLsizei n, GLuint* ids) { glGenBuffers(n, ids); }
inline void delete_buffers(GLsizei n, const GLuint* ids) { glDeleteBuffers(n, ids); }
inline void gen_vertex_arrays(GLsizei n, GLuint* ids) { glGenVertexArrays(n, ids); }
inline void delete_vertex_arrays(GLsizei n, const GLuint* ids) { glDeleteVertexArrays(n, ids); }
inline void gen_textures(GLsizei n, GLuint* ids) { glGenTextures(n, ids); }
inline void delete_textures(GLsizei n, const GLuint* ids) { glDeleteTextures(n, ids); }
inline void gen_framebuffers(GLsizei n, GLuint* ids) { glGenFramebuffers(n, ids); }
inline void delete_framebuffers(GLsizei n, const GLuint* ids) { glDeleteFramebuffers(n, ids); }
inline void gen_renderbuffers(GLsizei n, GLuint* ids) { glGenRenderbuffers(n, ids); }
inline void delete_renderbuffers(GLsizei n, const GLuint* ids) { glDeleteRenderbuffers(n, ids); }
inline void gen_transform_feedbacks(GLsizei n, GLuint* ids) { glGenTransformFeedbacks(n, ids); }
inline void delete_transform_feedbacks(GLsizei n, const GLuint* ids) { glDeleteTransformFeedbacks(n, ids); }

using Buffer = Name<gen_buffers, delete_buffers>;
using VertexArray = Name<gen_vertex_arrays, delete_vertex_arrays>;
using Texture = Name<gen_textures, delete_textures>;
using Framebuffer = Name<gen_framebuffers, delete_framebuffers>;
using Renderbuffer = Name<gen_renderbuffers, delete_renderbuffers>;
using TransformFeedback = Name<gen_transform_feedbacks, delete_transform_feedbacks>;

inline void delete_program(GLuint id) { glDeleteProgram(id); }

/// A linked program; deleted with glDeleteProgram.
class Program : public Owned<delete_program> {
 public:
  using Owned::Owned;
  GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }
  /// Looks up each (slot, name) pair: -1 where the program has no such active uniform.
  void find_uniforms(std::initializer_list<std::pair<GLint*, const char*>> slots) const {
    for (const auto& [slot, name] : slots) *slot = uniform(name);
  }
};

}  // namespace lungar::render::gl
