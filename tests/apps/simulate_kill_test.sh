#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The output folder of `clearjoint simulate` is published as one unit (docs/command-line.md,
# "Output folder"): runs into one --out are killed with SIGKILL at random moments, and after each
# kill the folder must hold the complete result of the earlier run or the complete result of the
# killed one, never a mix, a partial file or nothing.
#   simulate_kill_test.sh CLEARJOINT WORK_DIR [KILLS]
set -euo pipefail
clearjoint=$1 work=$2 kills=${3:-40}
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "simulate_kill_test: $*" >&2; exit 1; }

# Two models with different results and different files (B has a second body): a run takes a
# few tenths of a second, long enough to be killed while writing, while publishing or after.
model() {  # model GRAVITY EXTRA_BODY
  cat <<JSON
{"name": "kill", "gravity": [0, 0, $1],
 "bodies": [{"name": "ball", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0], "velocity": [1, 0, 0]}$2],
 "solver": {"end_time": 1, "report_step": 2e-5}}
JSON
}
model -9.81 "" >a.json
model -1.62 ', {"name": "moon", "mass": 2, "inertia": [1, 1, 1], "position": [5, 0, 0]}' >b.json

# The complete result of each, for comparison.
for m in a b; do
  "$clearjoint" simulate $m.json --out reference_$m >/dev/null || fail "reference run $m failed"
done
diff -rq reference_a reference_b >/dev/null && fail "the two references are equal"
start=$(date +%s%N)
"$clearjoint" simulate a.json --out out >/dev/null || fail "first run failed"
run_ms=$((($(date +%s%N) - start) / 1000000))
echo "simulate_kill_test: one run takes ${run_ms} ms; killing $kills runs at random moments"

holds() { diff -r "$1" out >/dev/null 2>&1; }
current=a
published=0
for ((k = 0; k < kills; ++k)); do
  next=b; [[ $current == b ]] && next=a
  "$clearjoint" simulate $next.json --out out --force >/dev/null 2>&1 &
  pid=$!
  # A random moment from the start to 20 % past the run's usual end.
  delay_ms=$((RANDOM % (run_ms * 12 / 10 + 1)))
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -KILL "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  if holds "reference_$current"; then
    :
  elif holds "reference_$next"; then
    current=$next
    published=$((published + 1))
  else
    fail "after kill $k (at $delay_ms ms) the folder is neither result: $(ls -A out 2>&1 | head -20)"
  fi
done
echo "simulate_kill_test: $kills kills, the folder held a complete result after each ($published times the killed run's, published before the kill)"
# The staging folders of the killed runs are removed by the next run, which publishes as usual.
"$clearjoint" simulate a.json --out out --force >/dev/null || fail "the run after the kills failed"
holds reference_a || fail "the run after the kills did not publish its result"
leftovers=$(ls -A | grep -c '^\.out\.staging-' || true)
((leftovers == 0)) || fail "$leftovers staging folders of killed runs stayed"
echo "simulate_kill_test: passed"
