#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The detection suite (issue 5): accuracy of the paper's Newton baseline, clearjoint uncertified
# and clearjoint certified against an MPFR reference on five input families, their timings side by
# side (Google Benchmark), the robustness export, then docs/reports/benchmarks.md and its plots.
#
#   bash bench/run_detection_suite.sh            # full run, about 5 minutes on 2 cores
#   bash bench/run_detection_suite.sh --quick    # under a minute once built; writes to the build tree
#
# Full run: regenerates docs/reports/benchmarks.md and docs/figures/benchmarks-*.png. Quick run: the
# same report into $BUILD_DIR/detection-quick/ (the committed docs are left alone). Raw outputs go
# to $BUILD_DIR/detection[-quick]/: accuracy.json, timings.json (Google Benchmark), robustness/.
# BUILD_DIR (default: build) selects the build tree, CMAKE_ARGS adds configure options. Two cores:
# everything builds with -j2, the accuracy pass uses two threads, the timings one; keep the machine
# otherwise idle while the timings run (the report quotes the load average).
set -euo pipefail
cd "$(dirname "$0")/.."

mode=full
case "${1:-}" in
  "") ;;
  --quick) mode=quick ;;
  *) echo "usage: bash bench/run_detection_suite.sh [--quick]" >&2; exit 2 ;;
esac

build_dir=${BUILD_DIR:-build}
start=$(date +%s)
bash scripts/install-dependencies.sh   # includes python3-matplotlib for the plots

# shellcheck disable=SC2086  # CMAKE_ARGS is a list of options
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCLEARJOINT_BUILD_BENCHMARKS=ON ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j2 --target detection_suite bench_detection

if [[ $mode == full ]]; then
  out=$build_dir/detection
  markdown=docs/reports/benchmarks.md
  figures=docs/figures
  suite_flag=()
  repetitions=3
else
  out=$build_dir/detection-quick
  markdown=$out/benchmarks.md
  figures=$out/figures
  suite_flag=(--quick)
  repetitions=2
fi
mkdir -p "$out"
tools=$build_dir/bench/detection
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git status --porcelain --untracked-files=no -- geometry 2>/dev/null | wc -l)

echo "== accuracy ($mode) ==  $(uptime)"
accuracy_load=$(cut -d' ' -f1-3 /proc/loadavg)
"$tools/detection_suite" accuracy "${suite_flag[@]}" --threads 2 --out "$out/accuracy.json"

echo "== timings ($mode, $repetitions interleaved repetitions) ==  $(uptime)"
timing_load=$(cut -d' ' -f1-3 /proc/loadavg)
"$tools/bench_detection" --suite="$mode" \
  --benchmark_repetitions="$repetitions" \
  --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true \
  --benchmark_context=commit="$commit" \
  --benchmark_context=geometry_files_modified_since_commit="$dirty" \
  --benchmark_out="$out/timings.json.tmp" --benchmark_out_format=json >"$out/timings.txt.tmp"
mv "$out/timings.json.tmp" "$out/timings.json"   # complete files only, never half-written ones
mv "$out/timings.txt.tmp" "$out/timings.txt"
echo "timings: $out/timings.json (console: $out/timings.txt)"

echo "== robustness export ($mode) =="
"$tools/detection_suite" export "${suite_flag[@]}" --threads 2 --out-dir "$out/robustness"

echo "== report =="
# Debian's interpreter, which has python3-matplotlib (a pyenv or venv python3 may not).
python=${PYTHON:-/usr/bin/python3}
"$python" bench/detection/make_report.py \
  --accuracy "$out/accuracy.json" --timings "$out/timings.json" \
  --markdown "$markdown" --figures "$figures" \
  --mode "$mode" --commit "$commit" --geometry-dirty "$dirty" \
  --accuracy-load "$accuracy_load" --timing-load "$timing_load" \
  --elapsed "$(( $(date +%s) - start ))"
echo "done in $(( $(date +%s) - start )) s: $markdown, $figures/benchmarks-*.png"
