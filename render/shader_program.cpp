/// @file shader_program.cpp
/// @brief GLSL compile and link with readable errors.
#include "render/shader_program.h"

#include <GLES3/gl3.h>

namespace lungar::render {
namespace {

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  if (is_program) glGetProgramInfoLog(object, length, nullptr, log.data());
  else glGetShaderInfoLog(object, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

// Returns the shader name, or 0 with `error` set.
GLuint compile(GLenum stage, const std::string& text, const std::string& what, std::string& error) {
  GLuint shader = glCreateShader(stage);
  const char* src = text.c_str();
  glShaderSource(shader, 1, &src, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    error = what + ": compile failed: " + info_log(shader, false);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

Result<gl::Program> build_program(const ProgramSource& source) {
  const std::string head = "#version 300 es\n" + source.defines + "#line 1\n";
  std::string error;
  GLuint vs = compile(GL_VERTEX_SHADER, head + source.vertex, source.name + " (vertex)", error);
  if (vs == 0) return fail(error);
  GLuint fs = compile(GL_FRAGMENT_SHADER, head + source.fragment, source.name + " (fragment)", error);
  if (fs == 0) {
    glDeleteShader(vs);
    return fail(error);
  }
  gl::Program program(glCreateProgram());
  glAttachShader(program.id(), vs);
  glAttachShader(program.id(), fs);
  if (!source.captured.empty()) {
    glTransformFeedbackVaryings(program.id(), static_cast<GLsizei>(source.captured.size()), source.captured.data(),
                                GL_INTERLEAVED_ATTRIBS);
  }
  glLinkProgram(program.id());
  glDeleteShader(vs);  // flagged; freed with the program
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) return fail(source.name + ": link failed: " + info_log(program.id(), true));
  return program;
}

}  // namespace lungar::render
