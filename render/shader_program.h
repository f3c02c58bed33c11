/// @file shader_program.h
/// @brief Compiles and links GLSL ES 3.00 programs from the embedded shaders, with defines prepended.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"
#include "render/gl_objects.h"

namespace lungar::render {

struct ProgramSource {
  std::string name;                       ///< for error messages, e.g. "deform.vert+points.frag"
  const char* vertex = nullptr;           ///< GLSL without #version
  const char* fragment = nullptr;
  std::string defines;                    ///< "#define X 1\n..." inserted after #version
  std::vector<const char*> captured;      ///< transform-feedback varyings (interleaved), empty for none
};

/// Compiles both stages and links them; the error names the program, the stage and quotes the GL log.
Result<gl::Program> build_program(const ProgramSource& source);

}  // namespace lungar::render
