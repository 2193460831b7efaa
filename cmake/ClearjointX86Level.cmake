# SPDX-License-Identifier: BSD-3-Clause
# CLEARJOINT_X86_64_V2: compile the geometry kernel for the x86-64-v2 level (SSE4.1, SSE4.2,
# SSSE3, POPCNT; every x86-64 processor of the last fifteen years or so, and the baseline of
# RHEL 9), not the original x86-64 that Debian's compilers target by default. With it GCC 12
# writes the kernel's lane selects (pair_lanes.hpp) as SSE4.1 blends, a few per cent faster in
# the contact cases (docs/reports/benchmarks-kernel.md). The level has no fused multiply-add (that
# is x86-64-v3), and the kernel is compiled with -ffp-contract=off anyway, so every result is the
# same bit for bit (scripts/compare-answers.sh).
#   OFF (default):  the compiler's default target, so that an installed library runs anywhere;
#   ON:             on (a library built so stops with an illegal instruction on an older x86-64);
#   AUTO:           on when the compiler takes -march=x86-64-v2 and a program built with it
#                   runs on the build machine and finds SSE4.2, SSSE3 and POPCNT there.
set(CLEARJOINT_X86_64_V2 OFF CACHE STRING
    "Compile the geometry kernel for x86-64-v2 (SSE4.2, SSSE3, POPCNT): OFF, ON or AUTO")
set_property(CACHE CLEARJOINT_X86_64_V2 PROPERTY STRINGS AUTO ON OFF)

# Sets `out` to the compile options that CLEARJOINT_X86_64_V2 asks for (empty or -march=x86-64-v2).
function(clearjoint_x86_64_v2_options out)
  set(${out} "" PARENT_SCOPE)
  if(NOT CLEARJOINT_X86_64_V2 MATCHES "^(AUTO|ON|OFF)$")
    message(FATAL_ERROR "CLEARJOINT_X86_64_V2 = '${CLEARJOINT_X86_64_V2}': must be AUTO, ON or OFF")
  endif()
  if(CLEARJOINT_X86_64_V2 STREQUAL "OFF")
    return()
  endif()
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=x86-64-v2 CLEARJOINT_COMPILER_TAKES_X86_64_V2)
  if(NOT CLEARJOINT_COMPILER_TAKES_X86_64_V2)
    if(CLEARJOINT_X86_64_V2 STREQUAL "ON")
      message(FATAL_ERROR "CLEARJOINT_X86_64_V2 = ON, but the compiler does not take -march=x86-64-v2")
    endif()
    return()
  endif()
  if(CLEARJOINT_X86_64_V2 STREQUAL "AUTO")
    # Built with the flag itself: on a machine without the level the program may stop with an
    # illegal instruction before main, which fails the check too. Cross builds cannot run it:
    # AUTO is then off.
    include(CheckCXXSourceRuns)
    set(CMAKE_REQUIRED_FLAGS -march=x86-64-v2)
    check_cxx_source_runs([[
      int main() {
        __builtin_cpu_init();
        return __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("ssse3") &&
                       __builtin_cpu_supports("popcnt")
                   ? 0
                   : 1;
      }]] CLEARJOINT_BUILD_MACHINE_HAS_X86_64_V2)
    unset(CMAKE_REQUIRED_FLAGS)
    if(NOT CLEARJOINT_BUILD_MACHINE_HAS_X86_64_V2)
      return()
    endif()
  endif()
  set(${out} -march=x86-64-v2 PARENT_SCOPE)
endfunction()
