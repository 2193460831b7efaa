#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The bindings' costs: bench_c_api (the C API against the C++ call, 10 interleaved repetitions)
# and, when the MEX files are built, octave_batch_cost.m (Octave's per-pose cost on 1e5 poses).
# Writes build/bench_c_api.json, build/bench_octave_batch.json and, from them,
# docs/reports/benchmarks-bindings.md (make_bindings_table.py). Keep the machine otherwise idle.
#
#   bash bench/bindings/run_bindings_bench.sh
#
# BUILD_DIR (default: build) selects the build tree.
set -euo pipefail
cd "$(dirname "$0")/../.."
build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCLEARJOINT_BUILD_BENCHMARKS=ON >/dev/null
targets=(bench_c_api)
if grep -q "^CLEARJOINT_OCTAVE_CLI:FILEPATH=/" "$build_dir/CMakeCache.txt"; then targets+=(clearjoint_mex); fi
cmake --build "$build_dir" -j2 --target "${targets[@]}"
mkdir -p build

# Interleaved repetitions: a change of machine load falls on the C and the C++ rows alike.
"$build_dir/bench/bindings/bench_c_api" \
  --benchmark_repetitions=10 \
  --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true \
  --benchmark_out=build/bench_c_api.json \
  --benchmark_out_format=json | grep -E '_median|^Benchmark|^---'

octave_json=
if [[ -f "$build_dir/bindings/matlab/cj_detect_many.mex" ]]; then
  octave_json=build/bench_octave_batch.json
  # Octave's own start-up files stay out of the measurement.
  HOME="$PWD/$build_dir" octave-cli --norc --no-history --no-gui --quiet --eval \
    "addpath('$PWD/$build_dir/bindings/matlab', '$PWD/bench/bindings'); octave_batch_cost('$PWD/$octave_json')"
  cat "$octave_json"
fi
report=docs/reports/benchmarks-bindings.md
/usr/bin/python3 bench/bindings/make_bindings_table.py build/bench_c_api.json $octave_json > "$report"
echo "$report written"
