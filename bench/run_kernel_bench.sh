#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds bench_intersections (Release) and runs it with 10 interleaved repetitions, medians only.
# JSON: build/bench_intersections.json (docs/benchmarks-kernel.md reads its table from it);
# the console table goes to stdout, then the certified/uncertified ratios of the medians.
#
#   bash bench/run_kernel_bench.sh [extra benchmark flags, e.g. --benchmark_filter=circle_plane]
#
# BUILD_DIR (default: build) selects the build tree, CMAKE_ARGS adds configure options
# (e.g. CMAKE_ARGS=-DCLEARJOINT_BUILD_DYNAMICS=OFF). Two cores: build with -j2, and keep the
# machine otherwise idle while it runs.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
json=build/bench_intersections.json

# shellcheck disable=SC2086  # CMAKE_ARGS is a list of options
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCLEARJOINT_BUILD_BENCHMARKS=ON ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j2 --target bench_intersections
mkdir -p "$(dirname "$json")"

console=build/bench_intersections.txt
# Random interleaving runs the repetitions of all benchmarks in a shuffled order, so that a
# change of machine load during the run falls on the certified and the plain pipelines alike and
# their ratio stays fair. The console shows the medians only (header lines kept); the full console output, with means,
# standard deviations and coefficients of variation, goes to $console, everything to $json.
"$build_dir/bench/geometry/bench_intersections" \
  --benchmark_repetitions=10 \
  --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$json" \
  --benchmark_out_format=json \
  "$@" | tee "$console" | grep -v -E '_(mean|stddev|cv) '

echo
echo "JSON: $json   full console output: $console"
if command -v python3 >/dev/null; then
  python3 - "$json" <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
# In registration order (the interleaved run reports them shuffled).
runs.sort(key=lambda r: r.get("family_index", 0))
median = {r["run_name"]: r for r in runs if r.get("aggregate_name") == "median"}
cv = {r["run_name"]: r for r in runs if r.get("aggregate_name") == "cv"}
print(f"\n{'benchmark (median of repetitions)':58s} {'CPU ns':>10s} {'real ns':>10s} {'CPU cv':>7s}")
for name, r in median.items():
    spread = f"{100 * cv[name]['cpu_time']:.1f}%" if name in cv else ""
    print(f"{name:58s} {r['cpu_time']:10.1f} {r['real_time']:10.1f} {spread:>7s}")
print("\nratios of median CPU times, same run:")
for name, r in median.items():
    stem, _, variant = name.rpartition("/")
    for other in ("uncertified", "no_exact_fallback", "plain_double_floor"):
        base = f"{stem}/{other}"
        if variant == "certified" and base in median:
            print(f"  {stem:40s} certified / {other:18s} {r['cpu_time'] / median[base]['cpu_time']:7.2f}")
PY
fi
