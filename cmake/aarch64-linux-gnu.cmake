# CMake toolchain for a 64-bit ARM Linux board (Debian arm64), cross-compiled on an amd64 Debian machine with
# crossbuild-essential-arm64 and the :arm64 dev packages (multiarch: libraries in /usr/lib/aarch64-linux-gnu).
# scripts/cross-aarch64 uses it; test binaries run under qemu-user-static.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
# pkg-config must read the arm64 .pc files only, never the build machine's.
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig")
# Tools run at build time (none today) and test discovery go through qemu; -L finds the arm64 loader and libc.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64-static -L /usr/aarch64-linux-gnu)
