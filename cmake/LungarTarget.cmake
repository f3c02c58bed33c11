# Helpers shared by every folder's CMakeLists.txt.

# The project's own code builds with -Wall -Wextra -Werror (third-party headers come in as SYSTEM).
function(lungar_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror)
  # GCC 12 at -O3 (Release) reports -Wrestrict inside libstdc++'s own `"literal" + std::string&&` (GCC bug 105329,
  # a false positive fixed in GCC 13): every string-building error message would trip it.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()

# Precompiled headers in the sanitizer build: the standard library's and Eigen's, which nearly every file of the
# libraries includes, and GoogleTest's in the suites; 16 % off that build (docs/measurements.md, CI). Not in the
# -O2/-O3 builds: there GCC 12 then raises its std::string false positives (-Warray-bounds, -Wstringop-overflow,
# -Wstringop-overread inside char_traits.h) at every `std::string(...) + ...` chain.
# lungar_precompile(TARGET [EIGEN] [GTEST]): the standard headers, and Eigen's or GoogleTest's where the target
# has them.
function(lungar_precompile target)
  if(NOT LUNGAR_SANITIZE)
    return()
  endif()
  cmake_parse_arguments(P "EIGEN;GTEST" "" "" ${ARGN})
  set(headers <algorithm> <array> <cmath> <cstdint> <functional> <memory> <optional> <string> <vector>)
  if(P_EIGEN)
    list(APPEND headers <Eigen/Core> <Eigen/Geometry>)
  endif()
  if(P_GTEST)
    list(APPEND headers <gtest/gtest.h>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

if(LUNGAR_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# lungar_library(NAME FOLDER DEPS...): one static library from every .cpp under FOLDER,
# except *_main.cpp (tool entry points), *_fuzz.cpp (fuzz targets) and the sub-folders with a CMakeLists.txt of
# their own, which are libraries of their own (drivers/breath/).
function(lungar_library name folder)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${folder}/*.cpp)
  list(FILTER sources EXCLUDE REGEX ".*_(main|fuzz)\\.cpp$")
  file(GLOB_RECURSE own_lists CONFIGURE_DEPENDS ${folder}/*/CMakeLists.txt)
  foreach(own_list ${own_lists})
    get_filename_component(own_folder ${own_list} DIRECTORY)
    list(FILTER sources EXCLUDE REGEX "^${own_folder}/")
  endforeach()
  if(sources)
    add_library(${name} STATIC ${sources})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/generated)
    target_link_libraries(${name} PUBLIC ${ARGN})
    lungar_warnings(${name})
  else()  # a folder whose code has not landed yet: headers only
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/generated)
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()

# lungar_executable(NAME MAIN DEPS...): a command-line tool.
function(lungar_executable name main)
  add_executable(${name} ${main})
  target_link_libraries(${name} PRIVATE ${ARGN})
  lungar_warnings(${name})
  lungar_sanitized_main_at_o0(${name})
endfunction()

# A tool's main parses its options and calls the libraries, where the work is; under the sanitizers its CLI11
# templates were the slowest files of CI's second build (30-57 s each at -O1), so it is compiled at -O0 there
# (the last -O wins), which also keeps every check in place.
function(lungar_sanitized_main_at_o0 target)
  if(LUNGAR_SANITIZE)
    target_compile_options(${target} PRIVATE -O0)
  endif()
endfunction()
