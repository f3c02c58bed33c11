/// @file gl_objects.h
/// @brief Move-only RAII owners of GLES 3 object names (buffers, vertex arrays, textures, framebuffers, ...).
///
/// Each owner deletes its name on destruction; the GL context that created it must be current then.
#pragma once

#include <GLES3/gl3.h>

#include <utility>

namespace lungar::render::gl {

/// One GL name with its delete function; GenFn/DeleteFn are glGen*/glDelete* of the same kind.
template <void (*Gen)(GLsizei, GLuint*), void (*Delete)(GLsizei, const GLuint*)>
class Name {
 public:
  Name() = default;
  static Name create() {
    Name n;
    Gen(1, &n.id_);
    return n;
  }
  ~Name() { reset(); }
  Name(Name&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Name& operator=(Name&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Name(const Name&) = delete;
  Name& operator=(const Name&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Delete(1, &id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
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

/// A linked program; deleted with glDeleteProgram.
class Program {
 public:
  Program() = default;
  explicit Program(GLuint id) : id_(id) {}
  ~Program() {
    if (id_ != 0) glDeleteProgram(id_);
  }
  Program(Program&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Program& operator=(Program&& o) noexcept {
    if (this != &o) {
      if (id_ != 0) glDeleteProgram(id_);
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace lungar::render::gl
