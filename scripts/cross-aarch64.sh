#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Cross-build the geometry kernel and its tests for aarch64 (64-bit ARM Linux) and run the
# tests under qemu-user: a check that the kernel builds and answers correctly off x86-64 (the
# lanes are then NEON registers, or the portable struct with CLEARJOINT_LANES=PORTABLE).
#
# Usage: bash scripts/cross-aarch64.sh [--no-install] [extra cmake arguments...]
#   --no-install  skip the Debian packages (already installed)
# Environment: BUILD_DIR (default build-aarch64), JOBS (default 2).
#
# Needs Debian 12 and root (or sudo) for the packages: the arm64 architecture is added to dpkg,
# then g++-aarch64-linux-gnu, qemu-user and the :arm64 development packages of CGAL, GMP, MPFR,
# Boost and GoogleTest (Eigen is architecture-independent). Only the geometry module and its tests
# are built (no dynamics, programs, bindings or benchmarks).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build-aarch64}"
jobs="${JOBS:-2}"

install=1
if [[ "${1:-}" == "--no-install" ]]; then
  install=0
  shift
fi

if ((install)); then
  sudo_cmd=()
  if [[ "$(id -u)" != 0 ]]; then sudo_cmd=(sudo); fi
  if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    "${sudo_cmd[@]}" dpkg --add-architecture arm64
  fi
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    g++-aarch64-linux-gnu qemu-user cmake make libeigen3-dev \
    libcgal-dev:arm64 libgmp-dev:arm64 libmpfr-dev:arm64 libboost-dev:arm64 libgtest-dev:arm64
fi

echo "cross-aarch64: configuring in $build"
cmake -S "$root" -B "$build" \
  -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/aarch64-linux-gnu.cmake" \
  -DCMAKE_BUILD_TYPE=Release \
  -DCLEARJOINT_BUILD_DYNAMICS=OFF -DCLEARJOINT_BUILD_APPS=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF \
  -DCLEARJOINT_BUILD_PYTHON=OFF -DCLEARJOINT_BUILD_MATLAB=OFF -DCLEARJOINT_BUILD_FORTRAN=OFF \
  "$@"

echo "cross-aarch64: building the geometry library and its tests"
start=$(date +%s)
# tests/support: the check of the multiprecision reference the geometry tests compare with.
for folder in tests/geometry tests/support; do cmake --build "$build/$folder" -j "$jobs"; done
echo "cross-aarch64: built in $(($(date +%s) - start)) s"

echo "cross-aarch64: running the geometry tests under qemu-aarch64"
start=$(date +%s)
for folder in tests/geometry tests/support; do ctest --test-dir "$build/$folder" -j "$jobs" --output-on-failure; done
echo "cross-aarch64: tests ran in $(($(date +%s) - start)) s"
