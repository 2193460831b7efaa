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
run_folder)
  # The folder held the force table only: no bodies, no energy, no model, no summary.
  run "$program" "$example" --out res "${short[@]}"
  expect_rc 0
  for file in body_crank.csv body_rod.csv body_slider.csv energy.csv force_rod_slider.csv summary.json model.xml; do
    [[ -f res/$file ]] || fail "no $file in the run folder: $(ls -A res)"
  done
  cmp -s "$example" res/model.xml || fail "model.xml is not the model run"
  # clearjoint simulate's columns (dynamics/src/simulation.cpp).
  [[ $(head -1 res/body_rod.csv) == time,x,y,z,e0,e1,e2,e3,vx,vy,vz,wx,wy,wz,ax,ay,az,alphax,alphay,alphaz ]] ||
    fail "body columns: $(head -1 res/body_rod.csv)"
  [[ $(head -1 res/energy.csv) == time,kinetic,potential,total ]] || fail "energy columns: $(head -1 res/energy.csv)"
  [[ $(wc -l <res/energy.csv) == 12 ]] || fail "$(wc -l <res/energy.csv) energy lines, expected 1 + 11"
  expect_in res/summary.json '"engine": "mujoco"'
  expect_in res/summary.json '"steps": 2000'
  expect_in res/summary.json '"element_statistics": ['
  # The first row against the keyframe worked out by hand (crank 150 rad/s about its hinge at
  # x = 0, its mass centre at 0.0762 m; the rod's from its joint at the crank's tip, 0.1524 m,
  # turning at 150 - 225 = -75 rad/s; slider at rest; all at y = 0, so no potential energy):
  #   rod:    vy = (150 - 75) 0.1524 = 11.43 m/s, wz = -75 rad/s, and its x acceleration the
  #           centripetal parts alone, -(150^2 + 75^2) 0.1524 = -4286.25 m/s^2 (the tangential
  #           parts of the angular accelerations lie along y at this pose)
  #   slider: ay = 0 (the slide joint), where MuJoCo's own body acceleration holds +9.81 (its
  #           recursion starts from the world accelerating at -g)
  #   kinetic energy = (0.002 + 0.15 0.0762^2) 150^2 / 2 + 0.3 11.43^2 / 2 + 0.002 75^2 / 2
  #                  = 57.5201025 J
  # Within 1e-9 relative: the rounding of a few products of doubles, far under it.
  value() {  # FILE COLUMN ROW(1 = first data row)
    awk -F, -v c="$2" -v r="$3" 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == c) n = k } NR == r + 1 { print $n }' "$1"
  }
  near() {  # WHAT ACTUAL EXPECTED
    awk -v a="$2" -v e="$3" 'BEGIN { d = a - e; if (d < 0) d = -d; s = e < 0 ? -e : e; exit !(d <= 1e-9 * (s > 1 ? s : 1)) }' ||
      fail "$1 = $2, expected $3"
  }
  near "body_rod vy" "$(value res/body_rod.csv vy 1)" 11.43
  near "body_rod wz" "$(value res/body_rod.csv wz 1)" -75
  near "body_rod ax" "$(value res/body_rod.csv ax 1)" -4286.25
  near "body_slider ay" "$(value res/body_slider.csv ay 1)" 0
  near "body_slider x" "$(value res/body_slider.csv x 1)" 0.4572
  near "energy kinetic" "$(value res/energy.csv kinetic 1)" 57.5201025
  near "energy potential" "$(value res/energy.csv potential 1)" 0
  near "energy total" "$(value res/energy.csv total 1)" 57.5201025
  # A later row: total = kinetic + potential (the contacts' elastic energy included).
  k=$(value res/energy.csv kinetic 11) p=$(value res/energy.csv potential 11)
  near "energy total at 1 ms" "$(value res/energy.csv total 11)" "$(awk -v k="$k" -v p="$p" 'BEGIN { printf "%.17g", k + p }')"
  ;;
progress)
  # Nothing was printed while a run went on. CLEARJOINT_STALL_WALL_TIME shortens the interval of
  # the progress lines (a sixth of it) as it shortens the stall rule's window.
  CLEARJOINT_STALL_WALL_TIME=0.03 run "$program" "$example" --out res --duration 0.005 --report-step 1e-3
  expect_rc 0
  expect_in err.txt '% of the simulated time after '
  grep -qE '^clearjoint-mujoco: [0-9]+\.[0-9]% of the simulated time after [0-9]+ s$' err.txt ||
    fail "progress line: $(head -c 300 err.txt)"
  CLEARJOINT_STALL_WALL_TIME=0 run "$program" "$example" --out res2 --duration 0.001
  expect_rc 1
  expect_in err.txt "CLEARJOINT_STALL_WALL_TIME = '0': must be a finite number of seconds above 0"
  [[ ! -e res2 ]] || fail "a refused run wrote res2"
  ;;
stall)
  # A run of any length went on, however slow. With the stall wall time shortened to 0.01 s
  # (windows of 5 ms, a limit of 60 stall wall times, 0.6 s), 0.1 s of the example (2e5 RK4
  # steps, about 2 s of wall time on the development machine) is projected beyond the limit
  # at its first window and stopped; --allow-large runs it to the end.
  CLEARJOINT_STALL_WALL_TIME=0.01 run "$program" "$example" --out res --duration 0.1 --report-step 1e-3
  expect_rc 1
  expect_in err.txt 'clearjoint-mujoco: MuJoCo run stopped at t = '
  expect_in err.txt 's of wall time, more than 0.6 s (the stall rule for a fixed-step engine'
  expect_in err.txt 'pass --allow-large to run it anyway'
  # Stopped after claiming the folder: no result, no staging folder (the lock file stays, as
  # every run's does: dynamics/output_folder.hpp).
  [[ ! -e res && -z $(ls -A | grep -e staging) ]] || fail "a stopped run left: $(ls -A)"
  CLEARJOINT_STALL_WALL_TIME=0.01 run "$program" "$example" --out res --duration 0.1 --report-step 1e-3 --allow-large
  expect_rc 0
  [[ $(wc -l <res/energy.csv) == 102 ]] || fail "$(wc -l <res/energy.csv) energy lines, expected 1 + 101"
  ;;
plot)
  # `clearjoint plot` read the folder as force tables only: no slider acceleration, no energy.
  # CLEARJOINT_TEST_PYTHON: the interpreter with the package on PYTHONPATH (tests/engines/CMakeLists.txt).
  run "$program" "$example" --out res --duration 0.004 --report-step 1e-4
  expect_rc 0
  run "$CLEARJOINT_TEST_PYTHON" -m clearjoint.plot res --out figures
  expect_rc 0
  [[ -s figures/joint_rod_slider.png ]] || fail "no figure: $(ls -A figures 2>&1)"
  run "$CLEARJOINT_TEST_PYTHON" - <<'PY'
import matplotlib
matplotlib.use("Agg")
from clearjoint import plot
result = plot.compare(["res", "res"], labels=["one", "two"])
labels = [axes.get_ylabel() for axes in result.figure.axes]
assert "total energy [J]" in labels, labels
assert any(label.startswith("slider acceleration") for label in labels), labels
assert not [note for note in result.notes if "energy" in note or "slider" in note], result.notes
PY
  expect_rc 0
  ;;
*) fail "unknown case" ;;
esac
echo "clearjoint_mujoco_test [$case]: passed"
