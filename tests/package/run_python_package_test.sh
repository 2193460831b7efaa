#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Python package as docs/python.md tells a user to install it: `pip wheel .` and `pip install .`
# from a copy of the sources, offline, in virtual environments that see Debian's NumPy
# (--system-site-packages), then python_smoke.py run against each install.
#
# usage: run_python_package_test.sh STEP SCRATCH [ARGS...]
#   pip-wheel SOURCE_DIR PYTHON      copy the files a clone of SOURCE_DIR would hold (tracked ones
#                                    and new ones git does not ignore) to SCRATCH/source, then
#                                    `pip wheel .` there into SCRATCH/wheels
#   wheel-smoke PYTHON VERSION MODELS
#                                    install the wheel into a new virtual environment, run the
#                                    smoke script from outside the sources
#   source-smoke PYTHON VERSION MODELS
#                                    `pip install .` from SCRATCH/source into another one (the
#                                    setuptools build folder of pip-wheel is reused), likewise
#   module-pic SOURCE_DIR PYTHON     configure SOURCE_DIR as setup.py does but without
#                                    CMAKE_POSITION_INDEPENDENT_CODE, and check with CMake's file
#                                    API that every static and object library the module links
#                                    compiles with -fPIC (the link itself takes a full build)
#
# SCRATCH/source/build-pip (setup.py's build folder) is kept between runs: the copy keeps the
# sources' times, so a rerun recompiles only what changed. After a build, SCRATCH/source/build (the
# README's CMake build folder) must not exist: setup.py builds beside it, not inside. CMAKE_BUILD_PARALLEL_LEVEL (set by the test) is setup.py's job count.
set -euo pipefail
step=$1 scratch=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*" >&2; exit 1; }
# Only what Debian installed, as on a machine without PyPI: no index, no local wheel folders, no
# wheels cached by an earlier run.
pip_offline=(--no-index --no-cache-dir --disable-pip-version-check --no-input)
unset PIP_FIND_LINKS PIP_INDEX_URL PIP_EXTRA_INDEX_URL

new_venv() {  # new_venv DIR PYTHON
  rm -rf "$1"
  "$2" -m venv --system-site-packages "$1"
}

smoke() {  # smoke VENV VERSION MODELS
  local run=$scratch/smoke-run
  rm -rf "$run" && mkdir -p "$run"
  (cd "$run" && env -u PYTHONPATH "$1/bin/python" "$here/python_smoke.py" "$1" "$2" "$3")
}

build_beside() {  # build_beside SOURCE: setup.py built in SOURCE/build-pip, not in the README's build/
  [[ -d $1/build-pip ]] || fail "setup.py left no build folder $1/build-pip"
  [[ ! -e $1/build ]] || fail "setup.py built inside the README's build folder: $1/build exists"
}

case $step in
pip-wheel)
  source_dir=$1 python=$2
  mkdir -p "$scratch/source"
  find "$scratch/source" -mindepth 1 -maxdepth 1 ! -name build-pip -exec rm -rf {} +
  if git -C "$source_dir" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    (cd "$source_dir" && git ls-files -z --cached --others --exclude-standard |
       while IFS= read -r -d '' f; do [[ -e $f ]] && printf '%s\0' "$f"; done |
       tar --null -T - -cf -) | tar -C "$scratch/source" -xf -
  else
    (cd "$source_dir" && tar --exclude='./build*' -cf - .) | tar -C "$scratch/source" -xf -
  fi
  new_venv "$scratch/venv-build" "$python"
  rm -rf "$scratch/wheels"
  start=$SECONDS
  (cd "$scratch/source" &&
     "$scratch/venv-build/bin/pip" wheel "${pip_offline[@]}" --no-build-isolation --no-deps \
       -w "$scratch/wheels" .) > "$scratch/pip-wheel.log" 2>&1 ||
    { tail -60 "$scratch/pip-wheel.log"; fail "pip wheel . failed (log: $scratch/pip-wheel.log)"; }
  build_beside "$scratch/source"
  wheels=("$scratch"/wheels/clearjoint-*.whl)
  [[ -f ${wheels[0]} ]] || fail "pip wheel . wrote no clearjoint wheel"
  echo "pip wheel . (CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-all cores}): $((SECONDS - start)) s, ${wheels[0]##*/}"
  ;;
wheel-smoke)
  python=$1 version=$2 models=$3
  venv=$scratch/venv-wheel
  new_venv "$venv" "$python"
  "$venv/bin/pip" install "${pip_offline[@]}" "$scratch"/wheels/clearjoint-*.whl > "$scratch/wheel-install.log" 2>&1 ||
    { cat "$scratch/wheel-install.log"; fail "pip install of the wheel failed"; }
  smoke "$venv" "$version" "$models"
  ;;
source-smoke)
  python=$1 version=$2 models=$3
  venv=$scratch/venv-source
  new_venv "$venv" "$python"
  (cd "$scratch/source" && "$venv/bin/pip" install "${pip_offline[@]}" --no-build-isolation .) \
    > "$scratch/pip-install.log" 2>&1 ||
    { tail -60 "$scratch/pip-install.log"; fail "pip install . failed (log: $scratch/pip-install.log)"; }
  build_beside "$scratch/source"
  smoke "$venv" "$version" "$models"
  ;;
module-pic)
  source_dir=$1 python=$2
  build=$scratch/module-pic
  rm -rf "$build"
  mkdir -p "$build/.cmake/api/v1/query"
  touch "$build/.cmake/api/v1/query/codemodel-v2"
  cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE="$python" \
        -DCLEARJOINT_BUILD_PYTHON=ON -DCLEARJOINT_BUILD_TESTS=OFF -DCLEARJOINT_BUILD_BENCHMARKS=OFF \
        -DCLEARJOINT_BUILD_APPS=OFF -DCLEARJOINT_BUILD_MATLAB=OFF -DCLEARJOINT_BUILD_FORTRAN=OFF \
        -DCLEARJOINT_WITH_SIMBODY=OFF -DCLEARJOINT_WITH_MUJOCO=OFF -DBUILD_SHARED_LIBS=OFF \
        > "$scratch/module-pic.configure.log" 2>&1 ||
    { cat "$scratch/module-pic.configure.log"; exit 1; }
  "$python" - "$build/.cmake/api/v1/reply" <<'PY'
import glob, json, os, sys
reply = sys.argv[1]
index = json.load(open(glob.glob(os.path.join(reply, "codemodel-v2-*.json"))[0]))
targets = {t["id"]: json.load(open(os.path.join(reply, t["jsonFile"])))
           for t in index["configurations"][0]["targets"]}
module = next(i for i, t in targets.items() if t["name"] == "clearjoint_python_core")
pending, seen, bad = [module], set(), []
while pending:
    current = pending.pop()
    if current in seen:
        continue
    seen.add(current)
    target = targets[current]
    fragments = [f["fragment"] for group in target.get("compileGroups", [])
                 for f in group.get("compileCommandFragments", [])]
    if target["type"] in ("STATIC_LIBRARY", "OBJECT_LIBRARY"):
        pic = any("-fPIC" in f.split() for f in fragments)
        print(f"{target['name']} ({target['type']}): {'-fPIC' if pic else 'NOT position-independent'}")
        if not pic:
            bad.append(target["name"])
    pending += [d["id"] for d in target.get("dependencies", [])]
if bad:
    sys.exit(f"FAIL: the Python module links {', '.join(bad)}, compiled without -fPIC")
PY
  ;;
*)
  fail "unknown step $step"
  ;;
esac
