#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs one libFuzzer target for a given time and fails on any crash, sanitizer report, leak or
# timeout; prints libFuzzer's closing statistics (executions, corpus size).
#   fuzz-one.sh TARGET SECONDS SCRATCH_CORPUS SEED_CORPUS [DICTIONARY] [-- libFuzzer options...]
# New inputs go to SCRATCH_CORPUS (created); SEED_CORPUS, the committed one, is only read.
# Crash reproducers are written to SCRATCH_CORPUS/../artifacts-<target>/.
set -euo pipefail
target=$1 seconds=$2 scratch=$3 seeds=$4 dictionary=${5:-}
shift $(( $# >= 5 ? 5 : $# ))
[[ ${1:-} == -- ]] && shift
name=$(basename "$target")
artifacts=$(dirname "$scratch")/artifacts-$name
mkdir -p "$scratch" "$artifacts"
options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536
         -print_final_stats=1 -artifact_prefix="$artifacts/")
[[ -n $dictionary ]] && options+=(-dict="$dictionary")
# Leaks fail the run; UBSan findings are fatal in the builds made for fuzzing (-fno-sanitize-recover).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
log=$(dirname "$scratch")/$name.log
set +e
"$target" "${options[@]}" "$@" "$scratch" "$seeds" >"$log" 2>&1
status=$?
set -e
grep -E '^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::peak_rss_mb|^#[0-9]+.*DONE' "$log" || true
if ((status != 0)); then
  tail -n 60 "$log"
  echo "fuzz-one: $name failed (status $status); reproducers in $artifacts" >&2
  exit 1
fi
echo "fuzz-one: $name ran ${seconds} s without a finding"
