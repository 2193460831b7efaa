#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the test suite with AddressSanitizer (and LeakSanitizer) + UndefinedBehaviorSanitizer in
# build-sanitize/ and runs it; any sanitizer report fails the test that triggered it
# (-fno-sanitize-recover: UBSan findings abort; leaks fail at exit). With Clang 14 the build also
# has the libFuzzer targets of fuzz/, and ctest runs each for a short time on its corpus.
#
# Then builds the threaded tests alone with ThreadSanitizer in build-tsan/ and runs them; a data
# race (or any other TSan report) fails the test that ran into it.
#
#   scripts/run-sanitizers.sh [--reduced] [--fuzz-seconds N] [--jobs N] [--tsan-only]
#     --reduced         only the joint-detection tests (tests/geometry/joint, with the property
#                       test), the program's end-to-end tests and the fuzz targets
#     --fuzz-seconds N  seconds per fuzz target under ctest (default 20)
#     --tsan-only       only the ThreadSanitizer lane (it runs in full and reduced runs alike)
# Uses clang++-14 when installed (Debian clang-14, libclang-rt-14-dev), otherwise g++
# (no fuzz targets then). The Python and MATLAB/Octave bindings are left out: an instrumented
# extension needs an instrumented interpreter (python3, octave-cli); so is the Fortran binding:
# gfortran would link GCC's sanitizer runtime into programs whose libraries Clang instrumented.
# The C API they wrap is tested from C and C++ here.
set -euo pipefail
cd "$(dirname "$0")/.."
reduced=0 fuzz_seconds=20 jobs=2 tsan_only=0
while (($#)); do
  case $1 in
    --reduced) reduced=1 ;;
    --tsan-only) tsan_only=1 ;;
    --fuzz-seconds) fuzz_seconds=$2; shift ;;
    --jobs) jobs=$2; shift ;;
    *) echo "run-sanitizers: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done

# The ThreadSanitizer lane: the tests that run library code on several threads at once, built
# alone (a few minutes on two cores the first time, seconds when up to date) with the same
# compiler choice as below. TSan cannot share a process with ASan, hence its own folder.
#   ClearanceRevoluteJoint.GivesEveryThread...  one joint evaluated from four threads (its
#                                               workspace lock, the detection it calls)
#   CApi.ThreadsDetectingAtOnce...              cj_detect's per-thread scratch answer
#   ForEachChunk.*                              the Python package's batch runner
#                                               (bindings/python/src/parallel_chunks.hpp) and a
#                                               detection batch spread over its threads
# Python-level threading (several threads on one clearjoint.Simulator) needs an instrumented
# interpreter and is not covered here; the library code those threads reach is the first test's.
tsan_targets=(test_dynamics_clearance_revolute_joint test_c_api test_parallel_chunks)
tsan_tests='^(ClearanceRevoluteJoint[.]GivesEveryThreadEvaluatingItTheAnswerItGivesAlone|CApi[.]ThreadsDetectingAtOnceGetTheirOwnAnswers|ForEachChunk[.].*)$'
run_tsan_lane() {
  local tsan_flags="-fsanitize=thread -fno-omit-frame-pointer"
  local tsan_config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCLEARJOINT_BUILD_PYTHON=OFF -DCLEARJOINT_BUILD_MATLAB=OFF
                     -DCLEARJOINT_BUILD_FORTRAN=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF -DCLEARJOINT_BUILD_FUZZERS=OFF)
  if command -v clang++-14 >/dev/null; then
    tsan_config+=(-DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14
                  -DCLEARJOINT_WITH_SIMBODY=OFF -DCLEARJOINT_WITH_MUJOCO=OFF)
  fi
  if command -v ccache >/dev/null; then
    tsan_config+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  fi
  local start=$SECONDS
  mkdir -p build-tsan
  cmake -S . -B build-tsan "${tsan_config[@]}" -DCMAKE_CXX_FLAGS="$tsan_flags" -DCMAKE_C_FLAGS="$tsan_flags" \
        -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
        >build-tsan/configure.log 2>&1 || { cat build-tsan/configure.log; return 1; }
  cmake --build build-tsan -j"$jobs" --target "${tsan_targets[@]}"
  # halt_on_error: the first report ends the test with TSan's exit code 66, so ctest fails it;
  # a report at exit (a race no check noticed) fails it the same way.
  (cd build-tsan && TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
     ctest --output-on-failure -j"$jobs" -R "$tsan_tests" --no-tests=error)
  echo "run-sanitizers: ThreadSanitizer lane took $((SECONDS - start)) s"
}
if ((tsan_only)); then run_tsan_lane; exit; fi

flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
link_flags="-fsanitize=address,undefined"
config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCLEARJOINT_BUILD_PYTHON=OFF -DCLEARJOINT_BUILD_MATLAB=OFF
        -DCLEARJOINT_BUILD_FORTRAN=OFF)
if command -v clang++-14 >/dev/null; then
  config+=(-DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 -DCLEARJOINT_BUILD_FUZZERS=ON
           -DCLEARJOINT_FUZZ_SECONDS="$fuzz_seconds")
  # Simbody 3.7's headers do not compile with Clang 14 and libstdc++ 12 in C++20 (a std::vector of
  # the incomplete MultibodyGraphMaker::Mobilizer); the engine adapters are GCC's (docs/engines.md).
  config+=(-DCLEARJOINT_WITH_SIMBODY=OFF -DCLEARJOINT_WITH_MUJOCO=OFF)
  # C programs (the C API's tests, the packaging test's C consumer) load C++ libraries whose
  # UBSan vptr checks call into the C++ part of the sanitizer runtime, which clang links into
  # C++ programs only; that part needs libstdc++ on the link line.
  link_flags+=" -fsanitize-link-c++-runtime -lstdc++"
else
  echo "run-sanitizers: clang++-14 not found; building with g++ and without the fuzz targets" >&2
fi
if command -v ccache >/dev/null; then
  config+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# Said both ways: the folder's cache would otherwise keep a reduced run's OFF in a full run.
if ((reduced)); then config+=(-DCLEARJOINT_BUILD_BENCHMARKS=OFF); else config+=(-DCLEARJOINT_BUILD_BENCHMARKS=ON); fi

mkdir -p build-sanitize
cmake -S . -B build-sanitize "${config[@]}" -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="$link_flags" \
      -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >build-sanitize/configure.log 2>&1 ||
  { cat build-sanitize/configure.log; exit 1; }

# fast_unwind_on_malloc=0: Debian's libraries are built without frame pointers, so the fast
# unwinder stops a report's stack at the first library frame; the suppressions below match a
# leak by the library function that allocated it, which only the whole stack shows.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:fast_unwind_on_malloc=0
# Leaks inside third-party libraries, each named with its cause (scripts/lsan-suppressions.txt).
export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if ((reduced)); then
  # The program (its end-to-end tests run it), the targets of tests/geometry/joint and
  # tests/geometry/model (label joint), of tests/apps (the program's GoogleTest checks) and of
  # fuzz/ (building a folder of the Makefile build builds its targets).
  cmake --build build-sanitize -j"$jobs" --target clearjoint
  cmake --build build-sanitize/tests/geometry/joint -j"$jobs"
  cmake --build build-sanitize/tests/geometry/model -j"$jobs"
  cmake --build build-sanitize/tests/apps -j"$jobs"
  if [[ -d build-sanitize/fuzz ]]; then cmake --build build-sanitize/fuzz -j"$jobs"; fi
  (cd build-sanitize && ctest --output-on-failure -j"$jobs" -L 'joint|apps|fuzz')
else
  cmake --build build-sanitize -j"$jobs"
  (cd build-sanitize && ctest --output-on-failure -j"$jobs")
fi
run_tsan_lane
