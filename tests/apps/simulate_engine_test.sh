#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `clearjoint simulate --engine simbody` writes the folder `--engine clearjoint` writes: the same
# tables, the same columns and report times, and values that agree (the planar aligned
# slider-crank over 0.1 s: the slider within 1e-6 m, the figure of docs/engines.md).
#   simulate_engine_test.sh CLEARJOINT MODELS_DIR WORK_DIR
set -euo pipefail
clearjoint=$1 models=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "simulate_engine_test: $*" >&2; exit 1; }
/usr/bin/python3 - "$models/slider_crank_planar_clearance_aligned.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["solver"].update(end_time=0.1, report_step=1e-3, relative_tolerance=1e-10, absolute_tolerance=1e-10)
json.dump(m, open("m.json", "w"))
PY
"$clearjoint" simulate m.json --out own >/dev/null
"$clearjoint" simulate m.json --out simbody --engine simbody >/dev/null
[[ $(ls own | sort) == "$(ls simbody | sort)" ]] || fail "different files: $(ls own) / $(ls simbody)"
/usr/bin/python3 - <<'PY' || fail "the tables differ"
import numpy as np, glob, os, sys
for own in sorted(glob.glob("own/*.csv")):
    other = os.path.join("simbody", os.path.basename(own))
    a, b = open(own).readline(), open(other).readline()
    assert a == b, (own, a, b)
    x, y = np.loadtxt(own, delimiter=",", skiprows=1), np.loadtxt(other, delimiter=",", skiprows=1)
    assert x.shape == y.shape, (own, x.shape, y.shape)
    assert np.array_equal(x[:, 0], y[:, 0]), own
slider = lambda d: np.loadtxt(f"{d}/body_slider.csv", delimiter=",", skiprows=1)[:, 1]
gap = np.max(np.abs(slider("own") - slider("simbody")))
print(f"slider x, largest difference over 0.1 s: {gap:.3g} m")
sys.exit(0 if gap < 1e-6 else 1)
PY
echo "simulate_engine_test: passed"
