# SPDX-License-Identifier: BSD-3-Clause
# Cross-compiling for 64-bit ARM Linux with Debian's multiarch packages: the g++-aarch64-linux-gnu
# compiler, the :arm64 development packages under /usr/lib/aarch64-linux-gnu, and qemu-user to run
# the test programs (gtest_discover_tests and ctest use CMAKE_CROSSCOMPILING_EMULATOR).
# scripts/cross-aarch64.sh installs them and uses this file.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64;-L;/usr/aarch64-linux-gnu)
# Headers and arch-independent packages (Eigen, CGAL's headers) live under /usr; libraries and
# their CMake configurations under /usr/lib/aarch64-linux-gnu. Programs (the emulator) come from
# the host.
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu /usr)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
