#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A fuzzing campaign: builds the libFuzzer targets of fuzz/ with ASan+UBSan (Clang 14, in
# build-fuzz/) and runs each for SECONDS on a scratch corpus seeded with the committed one,
# one after the other, one process each (one core). Prints each target's executions and
# exec/s, fails on the first finding (reproducer in build-fuzz/fuzz/campaign/artifacts-<target>/)
# and ends with a Markdown table of the runs (the table of docs/robustness.md).
#
#   scripts/fuzz.sh SECONDS [TARGET...]     (default: every target)
#
# New inputs that add coverage stay in build-fuzz/fuzz/campaign/<target>/; to keep some, minimise
# them into fuzz/corpus/<target>/ (TARGET -merge=1 fuzz/corpus/<target> build-fuzz/...).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:?usage: scripts/fuzz.sh SECONDS [TARGET...]}
shift
targets=("$@")
((${#targets[@]})) || targets=(fuzz_intersect_lines fuzz_detect_lines fuzz_model_file fuzz_detect_raw)
command -v clang++-14 >/dev/null || { echo "fuzz: clang++-14 is needed (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 2; }
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
      -DCMAKE_C_COMPILER=clang-14 -DCLEARJOINT_BUILD_FUZZERS=ON -DCLEARJOINT_BUILD_TESTS=OFF \
      -DCLEARJOINT_BUILD_BENCHMARKS=OFF -DCLEARJOINT_BUILD_PYTHON=OFF "${launcher[@]}" \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
      -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-fuzz -j2 --target "${targets[@]}"
total=0
table=("| target | seconds | executions | exec/s | findings |" "| --- | ---: | ---: | ---: | ---: |")
for target in "${targets[@]}"; do
  dictionary=fuzz/json.dict
  [[ $target == fuzz_detect_raw ]] && dictionary=
  # Printed once the target ends (fuzz-one.sh prints only then); not through `tee /dev/stderr`,
  # which truncates a log file that stderr is redirected to.
  status=0
  log=$(bash scripts/fuzz-one.sh "build-fuzz/fuzz/$target" "$seconds" \
        "build-fuzz/fuzz/campaign/$target" "fuzz/corpus/$target" "$dictionary" 2>&1) || status=$?
  printf '%s\n' "$log"
  ((status == 0)) || exit "$status"
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' <<<"$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' <<<"$log")
  total=$((total + ${runs:-0}))
  echo "fuzz: $target: ${runs:-?} executions in $seconds s (${rate:-?} exec/s)"
  table+=("| \`$target\` | $seconds | ${runs:-?} | ${rate:-?} | 0 |")
done
echo "fuzz: ${#targets[@]} targets, $total executions in total, no finding"
printf '%s\n' "${table[@]}"
