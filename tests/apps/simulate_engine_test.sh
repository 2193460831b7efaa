#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `clearjoint simulate --engine simbody` writes the folder `--engine clearjoint` writes: the same
# tables, the same columns and report times, and values that agree (the planar aligned
# slider-crank over 0.1 s: the slider within 1e-6 m, the figure of docs/engines.md); and so it does
# with --decimation 3 and with --format hdf5 (over 20 ms: every column within a part in 1e-4 of
# its largest magnitude, the agreement of tests/engines/test_simbody_simulate_in_simbody.cpp).
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
/usr/bin/python3 - "$models/slider_crank_planar_clearance_aligned.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["solver"].update(end_time=0.02, report_step=1e-4, relative_tolerance=1e-10, absolute_tolerance=1e-10)
json.dump(m, open("short.json", "w"))
PY
for engine in clearjoint simbody; do
  "$clearjoint" simulate short.json --out "decimated-$engine" --decimation 3 --engine "$engine" >/dev/null
  "$clearjoint" simulate short.json --out "hdf5-$engine" --format hdf5 --engine "$engine" >/dev/null
done
[[ $(ls decimated-clearjoint | sort) == "$(ls decimated-simbody | sort)" ]] || fail "decimated: different files"
[[ $(ls hdf5-clearjoint | sort) == "$(ls hdf5-simbody | sort)" ]] || fail "hdf5: different files"
/usr/bin/python3 - <<'PY' || fail "the decimated or HDF5 tables differ"
import glob, os, h5py, numpy as np
# Every column within a part in AGREEMENT of its largest magnitude, or within ROUNDING where
# clearjoint's is zero; the constraint bookkeeping differs by design between the engines.
AGREEMENT, ROUNDING = 1e-4, 1e-9
def compare(name, columns, own, other):
    assert own.shape == other.shape, (name, own.shape, other.shape)
    assert np.array_equal(own[:, 0], other[:, 0]), (name, "report times")
    for c, column in enumerate(columns[1:], start=1):
        if "violation" in column or column == "euler_norm_drift":
            continue
        a, b = own[:, c], other[:, c]
        assert np.array_equal(np.isnan(a), np.isnan(b)), (name, column, "NaN rows")
        scale = np.nanmax(np.abs(a), initial=0.0)
        gap = np.nanmax(np.abs(a - b), initial=0.0)
        assert gap <= AGREEMENT * scale + ROUNDING, (name, column, gap, scale)
def names(attribute):
    return [c.decode() if isinstance(c, bytes) else str(c) for c in attribute]
def csv(path):
    return open(path).readline().strip().split(","), np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
for own in sorted(glob.glob("decimated-clearjoint/*.csv")):
    name = os.path.basename(own)
    (columns, x), (other_columns, y) = csv(own), csv(os.path.join("decimated-simbody", name))
    assert columns == other_columns, (name, columns, other_columns)
    assert len(x) == 68, (name, len(x))  # 201 report times: 0, 3, ..., 198 and the last
    compare(name, columns, x, y)
with h5py.File("hdf5-clearjoint/run.h5") as f, h5py.File("hdf5-simbody/run.h5") as g:
    assert sorted(f["tables"]) == sorted(g["tables"]), (list(f["tables"]), list(g["tables"]))
    for name in f["tables"]:
        columns = names(f["tables"][name].attrs["columns"])
        assert columns == names(g["tables"][name].attrs["columns"]), name
        x, y = f["tables"][name][:], g["tables"][name][:]
        assert len(x) == 201, (name, len(x))
        compare(name, columns, x, y)
print("decimated and HDF5 tables of both engines agree")
PY
echo "simulate_engine_test: passed"
