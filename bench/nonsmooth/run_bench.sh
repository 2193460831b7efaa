#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds nonsmooth_cost_bench (Release), runs it with interleaved repetitions and rewrites the
# generated cost table of docs/nonsmooth.md from its JSON (bench/nonsmooth/make_table.py).
#
#   bash bench/nonsmooth/run_bench.sh [extra benchmark flags, e.g. --benchmark_filter=Spatial]
#
# BUILD_DIR (default: build) selects the build tree, REPETITIONS (default 5) the repetitions.
set -euo pipefail
cd "$(dirname "$0")/../.."
build_dir=${BUILD_DIR:-build}
repetitions=${REPETITIONS:-5}
bench="$build_dir/bench/nonsmooth/nonsmooth_cost_bench"
json="$build_dir/nonsmooth_cost_bench.json"

cmake --build "$build_dir" -j2 --target nonsmooth_cost_bench

# OpenBLAS (which Siconos Numerics calls) starts a worker thread per core that spins for a while
# after the library loads; the contact problems here are far too small for threads, and the spin
# would land in the first row's process CPU time.
export OPENBLAS_NUM_THREADS=1
# Random interleaving runs the repetitions of all rows in a shuffled order, so that a change of
# machine load during the run falls on every row alike.
"$bench" --benchmark_repetitions="$repetitions" --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true --benchmark_out="$json" --benchmark_out_format=json "$@" |
  grep -v -E '_(mean|stddev|cv) '

/usr/bin/python3 bench/nonsmooth/make_table.py "$json" docs/nonsmooth.md
echo "rewrote the cost table of docs/nonsmooth.md (JSON: $json)"
