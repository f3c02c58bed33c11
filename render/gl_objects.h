/// @file gl_objects.h
/// @brief Move-only RAII owners of GLES 3 object names (buffers, vertex arrays, textures, framebuffers, ...), held
/// without the GL header: a name is a std::uint32_t (GLuint), and making and deleting one happen in gl_objects.cpp.
/// So the render headers that keep such owners as members do not hand GL to the rest of the program.
///
/// Each owner deletes its name on destruction; the GL context that created it must be current then.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <utility>

#include "config/base/unique_handle.h"

namespace lungar::render::gl {

/// The kinds of GL object an owner holds, each with its own glGen*/glDelete* (glCreateProgram/glDeleteProgram).
enum class Kind { Buffer, VertexArray, Texture, Framebuffer, Renderbuffer, TransformFeedback, Program };

/// Makes one name of `kind`; needs a current context.
std::uint32_t generate(Kind kind);
/// Deletes one name of `kind`.
void release(Kind kind, std::uint32_t id);

template <Kind K>
void release_one(std::uint32_t id) {
  release(K, id);
}

/// One owned GL name of kind K, deleted when the owner is destroyed or reset; move-only.
template <Kind K>
class Name : public UniqueHandle<std::uint32_t, release_one<K>> {
 public:
  using UniqueHandle<std::uint32_t, release_one<K>>::UniqueHandle;
  static Name create() { return Name(generate(K)); }
  std::uint32_t id() const { return this->get(); }
};

using Buffer = Name<Kind::Buffer>;
using VertexArray = Name<Kind::VertexArray>;
using Texture = Name<Kind::Texture>;
using Framebuffer = Name<Kind::Framebuffer>;
using Renderbuffer = Name<Kind::Renderbuffer>;
using TransformFeedback = Name<Kind::TransformFeedback>;

/// A linked program; its uniforms are found by name (a location, GLint; -1 for none).
class Program : public Name<Kind::Program> {
 public:
  using Name::Name;
  std::int32_t uniform(const char* name) const;
  /// Looks up each (slot, name) pair: -1 where the program has no such active uniform.
  void find_uniforms(std::initializer_list<std::pair<std::int32_t*, const char*>> slots) const {
    for (const auto& [slot, name] : slots) *slot = uniform(name);
  }
};

}  // namespace lungar::render::gl
