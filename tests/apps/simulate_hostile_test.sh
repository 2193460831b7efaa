#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `clearjoint simulate` against hostile models and faults: each case is one ctest test
# (tests/apps/CMakeLists.txt). Every model check must fail before the run starts and leave no
# output folder; file names from model names stay inside --out; the output folder is published
# as one unit (docs/command-line.md, "Output folder").
#   simulate_hostile_test.sh CLEARJOINT WORK_DIR CASE
set -euo pipefail
clearjoint=$1 work=$2 case=$3
rm -rf "$work" && mkdir -p "$work/a/b" && cd "$work/a/b"

fail() { echo "simulate_hostile_test [$case]: $*" >&2; exit 1; }
run() { set +e; "$@" >out.txt 2>err.txt; rc=$?; set -e; }
expect_rc() { [[ $rc == "$1" ]] || fail "exit status $rc, expected $1; stderr: $(head -c 600 err.txt)"; }
expect_in() { grep -qF -- "$2" "$1" || fail "'$2' not in $1: $(head -c 600 "$1")"; }
expect_no_output() { [[ ! -e out ]] || fail "an output folder was created: $(ls -A out)"; }
expect_no_output_named() { [[ ! -e $1 ]] || fail "an output folder $1 was created"; }

# model BODIES FORCES INITIAL OUTPUT SOLVER [GRAVITY]: a model file on standard output. The
# default is one free body falling for 0.1 s, which runs in milliseconds.
model() {
  local default_body='{"name": "ball", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]}'
  local default_solver='"end_time": 0.1, "report_step": 0.01'
  local default_gravity='[0, 0, -9.81]'
  cat <<JSON
{"name": "hostile", "gravity": ${6:-$default_gravity},
 "bodies": [${1:-$default_body}],
 "forces": [${2:-}],
 "initial_conditions": {${3:-}},
 "output": {${4:-}},
 "solver": {${5:-$default_solver}}}
JSON
}
ball='{"name": "ball", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]}'
spring() {  # spring NAME: a spring from the ground to the ball
  echo "{\"type\": \"spring_damper\", \"name\": \"$1\", \"body_i\": \"ground\", \"body_j\": \"ball\", \"stiffness\": 10, \"free_length\": 0}"
}

case $case in
deep_model)
  { printf '{"name": "deep", "comment": '; printf '%*s' 100000 '' | tr ' ' '['
    printf '%*s' 100000 '' | tr ' ' ']'; echo '}'; } >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'nesting deeper than 64 levels'
  expect_no_output
  ;;
underflow_model)
  model "$ball" "" "" "" '"end_time": 0.1, "report_step": 1e-400' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'solver.report_step = 1e-400: underflows'
  ;;
overflow_model)
  # A number that overflows escaped as a bare JSON library exception (found by fuzz_model_file).
  model "$ball" "" "" "" '"end_time": 1e400, "report_step": 0.01' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt "clearjoint simulate: m.json: malformed JSON: number overflow parsing '1e400'"
  expect_no_output
  ;;
huge_value_message)
  { printf '{"name": "x", "bodies": [{"name": "b", "mass": "'; printf '%*s' 1000000 '' | tr ' ' 9
    echo '", "inertia": [1,1,1], "position": [0,0,0]}]}'; } >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'bodies[0].mass = "999'
  (($(wc -c <err.txt) < 400)) || fail "message of $(wc -c <err.txt) bytes"
  ;;
body_name_escape)
  # A body named ../../escaped wrote body_../../escaped.csv outside --out.
  model '{"name": "../../escaped_by_body_name", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]}' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 0
  [[ -f out/body_______escaped_by_body_name.csv ]] || fail "sanitised file missing: $(ls -A out)"
  [[ -z $(find "$work" -name '*escaped_by_body_name*' ! -path "$work/a/b/out/*") ]] ||
    fail "a file escaped --out: $(find "$work" -name '*escaped*')"
  ;;
force_name_collision)
  # Two names that sanitise to one file wrote one file together (force elements and bodies go
  # through the same function; test_dynamics_simulation has the clearance-joint case).
  model '{"name": "crank arm", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]},
         {"name": "crank/arm", "mass": 1, "inertia": [1, 1, 1], "position": [1, 0, 0]}' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'output.bodies[1] "crank/arm": its output file body_crank_arm.csv has the name of output.bodies[0]'
  expect_no_output
  model '{"name": "Arm", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]},
         {"name": "arm", "mass": 1, "inertia": [1, 1, 1], "position": [1, 0, 0]}' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'without case'
  expect_no_output
  ;;
identical_force_names)
  model "$ball" "$(spring twin), $(spring twin)" >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'forces[1].name = "twin": used by forces[0] already'
  expect_no_output
  ;;
duplicate_output_body)
  model "$ball" "" "" '"bodies": ["ball", "ball"]' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'output.bodies[1] = "ball": listed already as output.bodies[0]'
  expect_no_output
  ;;
duplicate_held_velocity)
  model "$ball" "" '"hold_velocities": [{"body": "ball", "component": "vx", "value": 1},
                                         {"body": "ball", "component": "vx", "value": 2}]' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'hold_velocities[1] = ("ball", "vx", 2): the same component is held by hold_velocities[0] = 1'
  expect_no_output
  ;;
inertia_triangle)
  model '{"name": "ball", "mass": 1, "inertia": [1, 1, 3], "position": [0, 0, 0]}' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'bodies[0].inertia = [1, 1, 3]: inertia[2] is larger than the sum of the other two'
  ;;
absurd_scales)
  model '{"name": "ball", "mass": 1e-300, "inertia": [1, 1, 1], "position": [0, 0, 0]}' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'bodies[0].mass = 1e-300: outside [1e-12, 1e+12] kg'
  model "$ball" "" "" "" "" '[0, 0, 1e300]' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'gravity = [0, 0, 1e+300]: magnitude above 1e+06 m/s^2'
  ;;
tiny_report_step)
  # 1e-21 gave only the rows at start and end; 1.1e-21 never ended (std::lround overflow).
  for step in 1e-21 1.1e-21; do
    model "$ball" "" "" "" "\"end_time\": 1, \"report_step\": $step" >m.json
    run timeout 20 "$clearjoint" simulate m.json --out out --allow-large
    expect_rc 1
    expect_in err.txt "solver.report_step = "
    expect_in err.txt "report times, more than 1000000000000000, the most the integrator counts"
    expect_no_output
  done
  ;;
size_guard)
  model "$ball" "" "" "" '"end_time": 1e9, "report_step": 0.01' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'longer than 1000 s'
  expect_in err.txt '--allow-large'
  expect_no_output
  model "$ball" "" "" "" '"end_time": 1, "report_step": 1e-8' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'report times, more than 10000000'
  expect_no_output
  # Past the guard on request: a free fall of 2000 s reported every 100 s runs in milliseconds.
  model "$ball" "" "" "" '"end_time": 2000, "report_step": 100' >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  run "$clearjoint" simulate m.json --out out --allow-large
  expect_rc 0
  [[ $(wc -l <out/energy.csv) == 22 ]] || fail "energy.csv has $(wc -l <out/energy.csv) lines"
  ;;
existing_folder)
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out out --format hdf5  # an earlier run with other outputs
  expect_rc 0
  cp -r out before
  run "$clearjoint" simulate m.json --out out
  expect_rc 1
  expect_in err.txt 'use --force to replace it'
  diff -r before out >/dev/null || fail "the refused run changed the folder"
  run "$clearjoint" simulate m.json --out out --force
  expect_rc 0
  [[ ! -e out/run.h5 ]] || fail "a file of the earlier run stayed beside the new result"
  [[ -f out/body_ball.csv ]] || fail "new result missing"
  mkdir empty && run "$clearjoint" simulate m.json --out empty
  expect_rc 0  # an empty folder is no result to protect
  echo text >a_file && run "$clearjoint" simulate m.json --out a_file --force
  expect_rc 1
  expect_in err.txt 'exists and is not a folder'
  ;;
failed_run_keeps_previous)
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out out
  expect_rc 0
  cp -r out before
  # Fails during integration: more than solver.max_steps steps.
  model "$ball" "" "" "" '"end_time": 0.1, "report_step": 0.01, "max_steps": 3' >m.json
  run "$clearjoint" simulate m.json --out out --force
  expect_rc 1
  diff -r before out >/dev/null || fail "a failed run changed the published folder"
  [[ -z $(ls -A . | grep staging) ]] || fail "staging folder left: $(ls -A)"
  ;;
lock)
  # Two runs into one --out both exited 0, the last overwriting the other. A run holding the
  # lock is played by `flock` (util-linux) holding the lock file for 3 s.
  model "$ball" >m.json
  command -v flock >/dev/null || fail "flock (util-linux) is missing"
  touch .out.lock
  (flock .out.lock sleep 3) &
  holder=$!
  sleep 0.5
  run "$clearjoint" simulate m.json --out out --force
  wait "$holder"
  expect_rc 1
  expect_in err.txt 'another run is writing this output folder'
  expect_no_output
  run "$clearjoint" simulate m.json --out out  # the lock is free again
  expect_rc 0
  ;;
stale_staging)
  model "$ball" >m.json
  mkdir -p .out.staging-999999-dead/ && echo partial >.out.staging-999999-dead/body_ball.csv
  run "$clearjoint" simulate m.json --out out
  expect_rc 0
  [[ ! -e .out.staging-999999-dead ]] || fail "the dead run's staging folder stayed"
  ;;
full_disk)
  model "$ball" >m.json
  set +e; "$clearjoint" simulate m.json --out out >/dev/full 2>err.txt; rc=$?; set -e
  expect_rc 2
  expect_in err.txt 'cannot write to standard output'
  ;;
force_keeps_user_files)
  # --force deleted whatever --out held: the current folder, its parents, any folder of a user's.
  # It must replace only an earlier result (its marker file) and refuse the rest, touching nothing.
  model "$ball" >m.json
  echo precious >thesis.tex && mkdir data && echo raw >data/run1.txt
  echo notes >../notes.txt
  for target in . .. "$PWD" "$PWD/.." ../b; do
    run "$clearjoint" simulate m.json --out "$target" --force
    expect_rc 1
    expect_in err.txt 'is the current folder or one of its parents'
  done
  mkdir -p ../home && echo mine >../home/.bashrc && mkdir ../home/src && echo code >../home/src/main.c
  run "$clearjoint" simulate m.json --out ../home --force
  expect_rc 1
  expect_in err.txt 'holds files that are not a clearjoint result'
  expect_in err.txt '.clearjoint-result'
  [[ $(cat thesis.tex) == precious && $(cat data/run1.txt) == raw && $(cat ../notes.txt) == notes ]] ||
    fail "a user file changed"
  [[ $(cat ../home/.bashrc) == mine && $(cat ../home/src/main.c) == code && -f m.json ]] ||
    fail "a file in the refused folder changed"
  [[ -z $(ls -A .. | grep -e staging -e replaced) ]] || fail "left behind: $(ls -A ..)"
  # An earlier result (with its marker) is replaced.
  run "$clearjoint" simulate m.json --out out
  expect_rc 0
  [[ -f out/.clearjoint-result ]] || fail "the result has no marker"
  run "$clearjoint" simulate m.json --out out --force
  expect_rc 0
  [[ -f out/body_ball.csv && -f out/.clearjoint-result ]] || fail "the result was not replaced"
  # A marker that is a link does not make a user's folder a result.
  mkdir linked && echo keep >linked/keep.txt && ln -s ../out/.clearjoint-result linked/.clearjoint-result
  run "$clearjoint" simulate m.json --out linked --force
  expect_rc 1
  expect_in err.txt 'holds files that are not a clearjoint result'
  [[ $(cat linked/keep.txt) == keep ]] || fail "the linked folder changed"
  ;;
force_keeps_added_files)
  # --force deleted the files a user added inside an earlier result: it replaces only what runs
  # wrote (the manifest .clearjoint-result) and names the rest.
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out res
  expect_rc 0
  echo precious >res/mynotes.txt && mkdir res/mysub && echo '{}' >res/mysub/analysis.ipynb
  cp -r res before
  run "$clearjoint" simulate m.json --out res --force
  expect_rc 1
  expect_in err.txt 'holds files no clearjoint run wrote (mynotes.txt, mysub/analysis.ipynb)'
  expect_in err.txt 'move those files out of the folder, or choose another --out'
  diff -r before res >/dev/null || fail "the refused run changed the folder"
  rm -r res/mynotes.txt res/mysub
  run "$clearjoint" simulate m.json --out res --force
  expect_rc 0
  grep -qx body_ball.csv res/.clearjoint-result || fail "the manifest does not list body_ball.csv"
  ;;
refused_run_creates_nothing)
  # A refused run created .DIR.lock beside DIR (--out ~ created /.root.lock).
  model "$ball" >m.json
  mkdir -p home && echo mine >home/.bashrc
  run "$clearjoint" simulate m.json --out home
  expect_rc 1
  run "$clearjoint" simulate m.json --out home --force
  expect_rc 1
  run "$clearjoint" simulate m.json --out m.json --force
  expect_rc 1
  [[ -z $(ls -A | grep -e lock -e staging) ]] || fail "a refused run left: $(ls -A)"
  ;;
link_out)
  # A link to a folder got "exists and is not a folder": the run is published at its target and
  # the link stays.
  model "$ball" >m.json
  mkdir target && ln -s target link
  run "$clearjoint" simulate m.json --out link
  expect_rc 0
  [[ -L link && -f target/body_ball.csv ]] || fail "not published at the target: $(ls -lA . target)"
  run "$clearjoint" simulate m.json --out link/ --force
  expect_rc 0
  [[ -L link && -f link/.clearjoint-result ]] || fail "the link was replaced: $(ls -lA)"
  ln -s nowhere dangling
  run "$clearjoint" simulate m.json --out dangling
  expect_rc 1
  expect_in err.txt 'dangling: is a symbolic link to nowhere, which does not lead to a folder'
  [[ ! -e nowhere ]] || fail "the link's target was created"
  ;;
mount_point_out)
  # --out on a mount point ran the whole model, then failed to publish (EBUSY): refused up front.
  # A private mount namespace keeps the tmpfs from outliving the test.
  model "$ball" >m.json
  mkdir disk
  set +e
  unshare -m bash -c "mount -t tmpfs -o size=1m tmpfs disk && '$clearjoint' simulate m.json --out disk --force" \
    >out.txt 2>err.txt
  rc=$?; set -e
  expect_rc 1
  expect_in err.txt 'is a mount point'
  ;;
full_disk_at_commit)
  # A disk that fills when the result is committed (every row still in the stream's buffer, the
  # first flush fails at commit): the message gave no reason; it says ENOSPC.
  model "$ball" >m.json
  mkdir small
  set +e
  unshare -m bash -c "mount -t tmpfs -o size=8k tmpfs small && '$clearjoint' simulate m.json --out small/out" \
    >out.txt 2>err.txt
  rc=$?; set -e
  expect_rc 1
  expect_in err.txt 'No space left on device'
  ;;
formats_and_decimation)
  # The run folder: tables as CSV or one HDF5 file, model.json and strict summary.json; the report
  # interval and the decimation set from the command line.
  model "$ball" "" "" "" '"end_time": 0.1, "report_step": 0.01' >m.json
  run "$clearjoint" simulate m.json --out csv --report-step 0.001 --decimation 10
  expect_rc 0
  [[ $(wc -l <csv/energy.csv) == 12 ]] || fail "energy.csv has $(wc -l <csv/energy.csv) lines, expected 1 + 11"
  /usr/bin/python3 -c "import json, sys; json.load(open('csv/summary.json'), parse_constant=lambda c: sys.exit('bare ' + c))" ||
    fail "summary.json is not strict JSON"
  /usr/bin/python3 -c "import json; m = json.load(open('csv/model.json')); assert m['solver']['report_step'] == 0.001 and m['output']['decimation'] == 10" ||
    fail "model.json does not hold the overrides"
  run "$clearjoint" simulate m.json --out h5 --format hdf5
  expect_rc 0
  [[ -f h5/run.h5 && -f h5/summary.json && -f h5/model.json && ! -e h5/energy.csv ]] || fail "hdf5 folder: $(ls -A h5)"
  for bad in "--format xml" "--report-step soon" "--decimation 0" "--decimation 2.5"; do
    run "$clearjoint" simulate m.json --out bad $bad
    expect_rc 2
    expect_no_output_named bad
  done
  ;;
unknown_engine)
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out out --engine bogus
  expect_rc 2
  expect_in err.txt "--engine = 'bogus': unknown engine; the engines of this build are clearjoint"
  expect_no_output
  ;;
end_time_and_set_shape_the_run)
  # --end-time and --set give the run of a file edited by hand to the same values, bit for bit;
  # model.json is the model as run and summary.json lists the values set.
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out set --end-time 0.05 --set 'bodies[0].mass=2' --set 'gravity=[0, 0, -1]'
  expect_rc 0
  /usr/bin/python3 - <<'PY' || fail "the hand-edited model could not be written"
import json
m = json.load(open("m.json"))
m["solver"]["end_time"] = 0.05
m["bodies"][0]["mass"] = 2
m["gravity"] = [0, 0, -1]
json.dump(m, open("edited.json", "w"))
PY
  run "$clearjoint" simulate edited.json --out edited
  expect_rc 0
  for table in energy body_ball reactions; do
    cmp -s "set/$table.csv" "edited/$table.csv" || fail "$table.csv differs from the run of the edited file"
  done
  # Free fall under g = 1 m/s^2 from rest: z(0.05 s) = -g t^2 / 2 = -0.00125 m, the last row.
  /usr/bin/python3 - <<'PY' || fail "the run does not end at 0.05 s with the fall of g = 1 m/s^2"
import csv, json
rows = list(csv.DictReader(open("set/body_ball.csv")))
assert float(rows[-1]["time"]) == 0.05, rows[-1]["time"]
assert abs(float(rows[-1]["z"]) + 0.00125) < 1e-12, rows[-1]["z"]
m = json.load(open("set/model.json"))
assert m["solver"]["end_time"] == 0.05 and m["bodies"][0]["mass"] == 2 and m["gravity"] == [0, 0, -1], m
s = json.load(open("set/summary.json"))
assert s["overrides"] == {"solver.end_time": 0.05, "bodies[0].mass": 2, "gravity": [0, 0, -1]}, s["overrides"]
assert list(s["overrides"]) == ["solver.end_time", "bodies[0].mass", "gravity"]
assert json.load(open("edited/summary.json"))["overrides"] == {}
PY
  ;;
set_of_a_missing_field_is_refused)
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out out --set solver.end_tme=1
  expect_rc 1
  expect_in err.txt 'clearjoint simulate: m.json: solver.end_tme: unknown field (expected start_time, end_time,'
  expect_no_output
  run "$clearjoint" simulate m.json --out out --set 'bodies[3].mass=1'
  expect_rc 1
  expect_in err.txt "clearjoint simulate: --set bodies[3].mass=1: bodies has 1 element, [0]: there is no [3]"
  expect_no_output
  run "$clearjoint" simulate m.json --out out --set bodies.0.mass=1
  expect_rc 1
  expect_in err.txt "bodies is an array: write its elements as bodies[0]"
  expect_no_output
  run "$clearjoint" simulate m.json --out out --set 'bodies[0].mass'
  expect_rc 2
  expect_in err.txt "clearjoint simulate: --set bodies[0].mass: must be PATH=VALUE"
  expect_no_output
  ;;
set_of_a_wrong_type_is_refused)
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out out --set 'bodies[0].mass=heavy'
  expect_rc 1
  expect_in err.txt 'clearjoint simulate: m.json: bodies[0].mass = "heavy": must be a number'
  expect_no_output
  run "$clearjoint" simulate m.json --out out --set 'gravity=[0, 0]'
  expect_rc 1
  expect_in err.txt 'gravity = [0,0]: must be an array of 3 numbers'
  expect_no_output
  run "$clearjoint" simulate m.json --out out --set 'solver.end_time=.5'
  expect_rc 2
  expect_in err.txt '--set solver.end_time=.5: the VALUE is not JSON'
  expect_no_output
  run "$clearjoint" simulate m.json --out out --end-time soon
  expect_rc 2
  expect_in err.txt "--end-time = 'soon': must be a number"
  expect_no_output
  ;;
set_of_one_field_twice_is_refused)
  model "$ball" >m.json
  run "$clearjoint" simulate m.json --out out --end-time 1 --set /solver/end_time=2
  expect_rc 1
  expect_in err.txt 'clearjoint simulate: --set /solver/end_time=2: sets solver.end_time, which --end-time 1 sets too'
  expect_no_output
  run "$clearjoint" simulate m.json --out out --set 'bodies[0].mass=2' --set 'bodies[0]={}'
  expect_rc 1
  expect_in err.txt 'sets bodies[0], which overlaps bodies[0].mass set by --set bodies[0].mass=2'
  expect_no_output
  ;;
*) fail "unknown case" ;;
esac
echo "simulate_hostile_test [$case]: passed"
