#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# usage: run_package_test.sh BUILD_DIR CONSUMER_SOURCE SCRATCH_DIR
set -euo pipefail
build_dir=$1 consumer=$2 scratch=$3
rm -rf "$scratch"
cmake --install "$build_dir" --prefix "$scratch/prefix" > "$scratch.install.log" 2>&1 ||
  { cat "$scratch.install.log"; exit 1; }
cmake -S "$consumer" -B "$scratch/consumer-build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$scratch/prefix"
cmake --build "$scratch/consumer-build" -j2
# The installed shared libraries are found through the consumers' build RPATH (and the dynamics
# library finds the geometry library beside it through its own RUNPATH).
"$scratch/consumer-build/consumer"
"$scratch/consumer-build/dynamics_consumer"
