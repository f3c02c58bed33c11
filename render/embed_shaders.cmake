# Writes a C++ header holding each shader file as a string constant: cmake -DOUT=h -DSHADERS="a;b" -P this.
# render/shaders/deform.vert becomes lungar::render::shaders::deform_vert.
set(text "/// @file shaders.h\n/// @brief Generated from render/shaders/ by render/embed_shaders.cmake; edit those files, not this.\n")
string(APPEND text "#pragma once\n\nnamespace lungar::render::shaders {\n")
foreach(path ${SHADERS})
  get_filename_component(file ${path} NAME)
  string(REPLACE "." "_" symbol ${file})
  file(READ ${path} source)
  string(APPEND text "\ninline constexpr const char* ${symbol} = R\"lungar_glsl(${source})lungar_glsl\";\n")
endforeach()
string(APPEND text "\n}  // namespace lungar::render::shaders\n")
file(WRITE ${OUT}.tmp "${text}")
file(RENAME ${OUT}.tmp ${OUT})
