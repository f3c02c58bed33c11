# CMake toolchain for a 64-bit ARM Linux board (Debian arm64), cross-compiled on an amd64 Debian machine with
# crossbuild-essential-arm64 against a sysroot of Debian's arm64 dev packages, which scripts/cross-aarch64 unpacks
# with mmdebstrap into build-aarch64/sysroot (LUNGAR_AARCH64_SYSROOT). A sysroot rather than dpkg's multiarch:
# some of them (Cyclone DDS's libddsc0, libopenigtlink-dev) cannot be installed beside their amd64 twins.
# Test binaries run under qemu-user-static.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
if(NOT LUNGAR_AARCH64_SYSROOT)
  set(LUNGAR_AARCH64_SYSROOT "${CMAKE_CURRENT_LIST_DIR}/../build-aarch64/sysroot")
endif()
get_filename_component(LUNGAR_AARCH64_SYSROOT "${LUNGAR_AARCH64_SYSROOT}" ABSOLUTE)
# try_compile projects see the same sysroot.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LUNGAR_AARCH64_SYSROOT)
set(CMAKE_SYSROOT "${LUNGAR_AARCH64_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH "${LUNGAR_AARCH64_SYSROOT}")
# Libraries, headers and CMake packages from the sysroot only; programs run at build time (idlc) from this machine.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# pkg-config reads the sysroot's arm64 .pc files only, never this machine's.
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${LUNGAR_AARCH64_SYSROOT}")
set(ENV{PKG_CONFIG_LIBDIR}
    "${LUNGAR_AARCH64_SYSROOT}/usr/lib/aarch64-linux-gnu/pkgconfig:${LUNGAR_AARCH64_SYSROOT}/usr/share/pkgconfig")
# The sysroot's shared libraries load each other by their run-time paths: tell the linker where they are.
string(APPEND CMAKE_EXE_LINKER_FLAGS_INIT
       " -Wl,-rpath-link,${LUNGAR_AARCH64_SYSROOT}/usr/lib/aarch64-linux-gnu"
       " -Wl,-rpath-link,${LUNGAR_AARCH64_SYSROOT}/lib/aarch64-linux-gnu")
# Test discovery goes through qemu; -L finds the arm64 loader and every library in the sysroot.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64-static -L "${LUNGAR_AARCH64_SYSROOT}")
