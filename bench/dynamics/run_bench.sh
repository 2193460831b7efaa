#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds dynamics_slider_crank_bench (Release), runs it with interleaved repetitions, profiles the
# spatial slider-crank with its clearance joint when perf is installed, and writes
# docs/reports/benchmarks-dynamics.md from the JSON (bench/dynamics/make_report.py).
#
#   bash bench/dynamics/run_bench.sh [extra benchmark flags, e.g. --benchmark_filter=Derivative]
#
# BUILD_DIR (default: build) selects the build tree, REPETITIONS (default 5) the repetitions,
# REPORT (default docs/reports/benchmarks-dynamics.md) the page. Two cores: build with -j2.
set -euo pipefail
cd "$(dirname "$0")/../.."
build_dir=${BUILD_DIR:-build}
repetitions=${REPETITIONS:-5}
report=${REPORT:-docs/reports/benchmarks-dynamics.md}
bench="$build_dir/bench/dynamics/dynamics_slider_crank_bench"
json="$build_dir/dynamics_slider_crank_bench.json"
profile="$build_dir/dynamics_slider_crank_bench.perf.txt"

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCLEARJOINT_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build_dir" -j2 --target dynamics_slider_crank_bench

# Random interleaving runs the repetitions of all rows in a shuffled order, so that a change of
# machine load during the run falls on every row alike.
"$bench" --benchmark_repetitions="$repetitions" --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true --benchmark_out="$json" --benchmark_out_format=json "$@" |
  grep -v -E '_(mean|stddev|cv) '

profile_argument=()
if command -v perf >/dev/null &&
   perf record -e cpu-clock -o "$build_dir/dynamics.perf.data" -- \
     "$bench" --benchmark_filter=BM_IntegrateSpatialSliderCrankWithClearance >/dev/null 2>&1; then
  perf report -i "$build_dir/dynamics.perf.data" --stdio --no-children --sort dso,sym >"$profile" 2>/dev/null
  profile_argument=("$profile")
else
  echo "no perf profile (perf missing or not permitted): the page gets no profile table" >&2
fi

/usr/bin/python3 bench/dynamics/make_report.py "$json" "${profile_argument[@]}" "$report"
echo "wrote $report (JSON: $json)"
