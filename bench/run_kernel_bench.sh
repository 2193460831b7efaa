#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds bench_intersections and bench_detect_contacts (Release), runs each with interleaved
# repetitions (medians only on the console), and writes docs/reports/benchmarks-kernel.md from their
# JSON (bench/make_kernel_report.py).
#
#   bash bench/run_kernel_bench.sh [extra benchmark flags, e.g. --benchmark_filter=circle_plane]
#
# BUILD_DIR (default: build) selects the build tree, CMAKE_ARGS adds configure options,
# REPETITIONS (default 10) the repetitions, REPORT (default docs/reports/benchmarks-kernel.md) the
# page.
# Two cores: build with -j2, and keep the machine otherwise idle while it runs.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
repetitions=${REPETITIONS:-10}
report=${REPORT:-docs/reports/benchmarks-kernel.md}

# shellcheck disable=SC2086  # CMAKE_ARGS is a list of options
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCLEARJOINT_BUILD_BENCHMARKS=ON ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j2 --target bench_intersections bench_detect_contacts
mkdir -p build

# Random interleaving runs the repetitions of all rows in a shuffled order, so that a change of
# machine load during the run falls on every row alike and their ratios stay fair.
for bench in bench_intersections bench_detect_contacts; do
  "$build_dir/bench/geometry/$bench" \
    --benchmark_repetitions="$repetitions" \
    --benchmark_enable_random_interleaving=true \
    --benchmark_report_aggregates_only=true \
    --benchmark_out="build/$bench.json" \
    --benchmark_out_format=json \
    "$@" | tee "build/$bench.txt" | grep -v -E '_(mean|stddev|cv) '
done

/usr/bin/python3 bench/make_kernel_report.py build/bench_intersections.json build/bench_detect_contacts.json "$report"
echo "wrote $report (JSON: build/bench_intersections.json, build/bench_detect_contacts.json)"
