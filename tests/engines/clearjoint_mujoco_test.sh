#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The program clearjoint-mujoco against hostile command lines and models: each case is one ctest
# test (tests/engines/CMakeLists.txt). Its output folder has `clearjoint simulate`'s protection
# (docs/command-line.md, "Output folder"), MuJoCo writes no MUJOCO_LOG.TXT, and every bad option
# or declaration is refused naming it, before any folder is created.
#   clearjoint_mujoco_test.sh CLEARJOINT_MUJOCO EXAMPLE.xml WORK_DIR CASE
set -euo pipefail
program=$1 example=$2 work=$3 case=$4
rm -rf "$work" && mkdir -p "$work/a" && cd "$work/a"

fail() { echo "clearjoint_mujoco_test [$case]: $*" >&2; exit 1; }
run() { set +e; "$@" >out.txt 2>err.txt; rc=$?; set -e; }
expect_rc() { [[ $rc == "$1" ]] || fail "exit status $rc, expected $1; stderr: $(head -c 600 err.txt)"; }
expect_in() { grep -qF -- "$2" "$1" || fail "'$2' not in $1: $(head -c 600 "$1")"; }
expect_no_output() { [[ ! -e out && -z $(ls -A | grep -v -e '^out.txt$' -e '^err.txt$' -e '^m.xml$') ]] ||
  fail "something was created: $(ls -A)"; }
short=(--duration 0.001 --report-step 1e-4)  # 2000 steps of 0.5 us: milliseconds

case $case in
out_folder)
  # --out overwrote a user's file of the name of a force table and wrote into the current folder.
  mkdir u && echo precious >u/force_rod_slider.csv
  run "$program" "$example" --out u "${short[@]}"
  expect_rc 1
  expect_in err.txt 'the folder exists and is not empty'
  [[ $(cat u/force_rod_slider.csv) == precious ]] || fail "the user's file was overwritten"
  run "$program" "$example" --out u "${short[@]}" --force
  expect_rc 1
  expect_in err.txt 'holds files that are not a clearjoint result'
  [[ $(cat u/force_rod_slider.csv) == precious ]] || fail "the user's file was overwritten by --force"
  for target in . .. "$PWD"; do
    run "$program" "$example" --out "$target" "${short[@]}" --force
    expect_rc 1
    expect_in err.txt 'is the current folder or one of its parents'
  done
  [[ -z $(ls -A .. | grep -e lock -e staging) ]] || fail "a refused run left: $(ls -A ..)"
  run "$program" "$example" --out res "${short[@]}"
  expect_rc 0
  [[ -f res/force_rod_slider.csv && -f res/.clearjoint-result ]] || fail "result: $(ls -A res)"
  [[ $(wc -l <res/force_rod_slider.csv) == 12 ]] || fail "$(wc -l <res/force_rod_slider.csv) lines, expected 1 + 11"
  run "$program" "$example" --out res "${short[@]}"
  expect_rc 1
  expect_in err.txt 'use --force to replace it'
  run "$program" "$example" --out res "${short[@]}" --force
  expect_rc 0
  [[ ! -e MUJOCO_LOG.TXT ]] || fail "MuJoCo wrote MUJOCO_LOG.TXT"
  ;;
mujoco_warning)
  # A velocity beyond MuJoCo's 1e10 makes it warn (into MUJOCO_LOG.TXT by default), reset the
  # state and carry on from qpos0: the run stops instead, its warning on standard error.
  sed 's/qvel="150 0 0 -225 0"/qvel="1e11 0 0 -225 0"/' "$example" >m.xml
  grep -q 1e11 m.xml || fail "the example's keyframe changed: edit this test"
  run "$program" m.xml --out res "${short[@]}"
  expect_rc 1
  expect_in err.txt 'clearjoint-mujoco: MuJoCo warning: '
  expect_in err.txt 'in qvel by t = 0 s and reset the state'
  [[ ! -e MUJOCO_LOG.TXT ]] || fail "MuJoCo wrote MUJOCO_LOG.TXT: $(cat MUJOCO_LOG.TXT)"
  expect_no_output
  ;;
bad_options)
  # --duration inf ran one row at t = 0 and exited 0; --report-step 1e300 gave 202 rows.
  for bad in "--duration inf" "--duration nan" "--duration -1" "--duration 0" "--duration 1s" "--duration 1e400" \
             "--report-step inf" "--report-step 0" "--report-step abc"; do
    run "$program" "$example" --out res $bad
    expect_rc 2
    expect_in err.txt "clearjoint-mujoco: ${bad%% *} = '${bad#* }': must be a finite number of seconds above 0"
    expect_no_output
  done
  run "$program" "$example" --out res --duration 0.001 --report-step 1e300
  expect_rc 2
  expect_in err.txt '--report-step = 1e300 s: longer than --duration = 0.001 s'
  run "$program" "$example" --out res --duration 0.001 --duration 0.002
  expect_rc 2
  expect_in err.txt '--duration: given twice'
  run "$program" "$example" --out res --duration 1e-9
  expect_rc 1
  expect_in err.txt "--duration = 1e-9 s: shorter than the model's timestep 5e-07 s"
  expect_no_output
  ;;
size_guard)
  # simulate's guard (dynamics/run_size.hpp): 1000 s simulated, 1e7 report times.
  run "$program" "$example" --out res --duration 1e300
  expect_rc 1
  expect_in err.txt '--duration = 1e300 s: longer than 1000 s'
  expect_in err.txt '--allow-large'
  run "$program" "$example" --out res --duration 1e300 --allow-large
  expect_rc 1
  expect_in err.txt 'more than 1e+15, the most this program counts'
  run "$program" "$example" --out res --duration 10 --report-step 5e-7
  expect_rc 1
  expect_in err.txt '--report-step = 5e-7 s: 20000001 report times, more than 1e+07'
  expect_no_output
  ;;
unknown_key)
  # A misspelt field left its joint at the default values without a word.
  sed 's/clearance:rod_slider:friction/clearance:rod_slider:frictoin/' "$example" >m.xml
  run "$program" m.xml --out res "${short[@]}"
  expect_rc 1
  expect_in err.txt '<numeric name="clearance:rod_slider:frictoin">: unknown field "frictoin"'
  expect_in err.txt 'dimensions, normal_force, friction, parallel_angle_tolerance'
  expect_no_output
  ;;
*) fail "unknown case" ;;
esac
echo "clearjoint_mujoco_test [$case]: passed"
