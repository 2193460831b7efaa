#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Hostile input and faults for the clearjoint program: each case below is one ctest test
# (tests/apps/CMakeLists.txt) and reproduces a way a careless or hostile user broke it (deep
# nesting, huge lines and values, numbers that underflow, a full disk, a directory as input).
# Every case asserts an exit status and a message; none may crash.
#   hostile_input_test.sh CLEARJOINT SOURCE_DIR WORK_DIR CASE
set -euo pipefail
clearjoint=$1 source_dir=$2 work=$3 case=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"

fail() { echo "hostile_input_test [$case]: $*" >&2; exit 1; }
# run CMD...: runs, sets rc, out (stdout file) and err (stderr file); never aborts the script.
run() { set +e; "$@" >out.txt 2>err.txt; rc=$?; set -e; }
expect_rc() { [[ $rc == "$1" ]] || fail "exit status $rc, expected $1; stderr: $(head -c 600 err.txt)"; }
expect_in() {  # expect_in FILE TEXT
  grep -qF -- "$2" "$1" || fail "'$2' not in $1: $(head -c 600 "$1")"
}
# The first line of examples/rims.jsonl and of examples/joints.jsonl: answers that must survive.
good_rim=$(head -n 1 "$source_dir/examples/rims.jsonl")
good_joint=$(head -n 1 "$source_dir/examples/joints.jsonl")
nested() { printf '%*s' "$1" '' | tr ' ' "$2"; }  # nested N CHAR: CHAR N times

case $case in
deep_nesting_intersect | deep_nesting_detect)
  # 100,000 '[': the JSON library's recursive copy and dump overflowed the stack (SIGSEGV) and
  # the answer to the good line before it was lost.
  sub=${case#deep_nesting_}
  good=$good_rim; [[ $sub == detect ]] && good=$good_joint
  { echo "$good"; nested 100000 '['; nested 100000 ']'; echo; echo "$good"; } >deep.jsonl
  run "$clearjoint" "$sub" deep.jsonl
  expect_rc 1
  [[ $(wc -l <out.txt) == 3 ]] || fail "expected 3 answer lines, got $(wc -l <out.txt)"
  sed -n 2p out.txt | grep -qF 'nesting deeper than 64 levels' || fail "line 2: $(sed -n 2p out.txt | head -c 300)"
  sed -n 1p out.txt | grep -qvF '"error"' || fail "the good line before was not answered"
  sed -n 3p out.txt | grep -qvF '"error"' || fail "the good line after was not answered"
  ;;
deep_id)
  # A deep "id" is copied into the answer: the depth limit applies to it before any copy.
  { printf '{"id": '; nested 50000 '['; nested 50000 ']'; echo ', "x": 1}'; } >deep_id.jsonl
  run "$clearjoint" detect deep_id.jsonl
  expect_rc 1
  expect_in out.txt 'nesting deeper than 64 levels'
  ;;
long_line)
  # A line past the line limit gets an error line; the lines after it are still answered.
  { printf '{"id": "long", "pad": "'; nested 2000000 x; echo '"}'; echo "$good_rim"; } >long.jsonl
  run "$clearjoint" intersect long.jsonl
  expect_rc 1
  expect_in out.txt 'line 1: longer than 1048576 bytes'
  sed -n 2p out.txt | grep -qvF '"error"' || fail "the line after the long one was not answered"
  ;;
huge_value_in_message)
  # A value of 500 kB quoted in an error message is cut to a short excerpt.
  { printf '{"id": 1, "circle": {"center": [0,0,0], "normal": [0,0,1], "radius": "'; nested 500000 9
    echo '"}, "plane": {"point": [0,0,0], "normal": [0,0,1]}}'; } >huge.jsonl
  run "$clearjoint" intersect huge.jsonl
  expect_rc 1
  expect_in out.txt 'circle.radius = \"999'
  (($(wc -c <out.txt) < 300)) || fail "error line of $(wc -c <out.txt) bytes"
  ;;
underflow)
  # 1e-400 was read as 0 without a word.
  echo '{"id": 1, "circle": {"center": [0,0,0], "normal": [0,0,1], "radius": 1e-400}, "plane": {"point": [0,0,0], "normal": [0,0,1]}}' >under.jsonl
  run "$clearjoint" intersect under.jsonl
  expect_rc 1
  expect_in out.txt 'circle.radius = 1e-400: underflows'
  ;;
full_disk)
  # Answers written to /dev/full were lost with status 0 and no message.
  [[ -w /dev/full ]] || fail "/dev/full is missing"
  for sub in detect intersect; do
    example=$source_dir/examples/joints.jsonl; [[ $sub == intersect ]] && example=$source_dir/examples/rims.jsonl
    set +e; "$clearjoint" $sub "$example" >/dev/full 2>err.txt; rc=$?; set -e
    expect_rc 2
    expect_in err.txt 'cannot write'
    set +e; "$clearjoint" $sub <"$example" >/dev/full 2>err.txt; rc=$?; set -e
    expect_rc 2
    expect_in err.txt 'No space left on device'
  done
  set +e; "$clearjoint" --help >/dev/full 2>err.txt; rc=$?; set -e
  expect_rc 2
  expect_in err.txt 'cannot write'
  ;;
stdin_directory)
  # `clearjoint intersect < /tmp` answered nothing with status 0.
  set +e; "$clearjoint" intersect <"$work" >out.txt 2>err.txt; rc=$?; set -e
  expect_rc 2
  expect_in err.txt 'standard input: is a directory'
  ;;
*) fail "unknown case" ;;
esac
echo "hostile_input_test [$case]: passed"
