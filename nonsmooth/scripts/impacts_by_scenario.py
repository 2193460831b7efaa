#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Energy lost and contact onsets per scenario of a run folder's clearance joint, compliant or
Moreau-Jean alike (docs/nonsmooth.md, "The spatial slider-crank, non-smooth").

usage: impacts_by_scenario.py [--min-speed V] RUN_DIR [RUN_DIR ...]

An onset is a row where a contact slot's normal_force is > 0 and was not in the row before
(the compliant force, or Moreau-Jean's percussion / h) with an approach speed
(`<slot>.approach_speed`) of at least V m/s (default 0: every onset), counted under the row's scenario
and under its slot (geometry::ContactScenario: 1-9 Fig. 2 (a)-(i), 10 (j) line, 11 (k) face, 12 (l) line and face,
13 beyond the model). Rows are report times: contacts shorter than the report step between two
rows are not seen, so run the compliant model at its own report step (1e-5 s)."""
import csv
import glob
import math
import os
import sys

SLOTS = ("radial_a", "radial_b", "line", "axial_a", "axial_b")
NAMES = {0: "none", **{k: "(" + "abcdefghi"[k - 1] + ")" for k in range(1, 10)},
         10: "(j) line", 11: "(k) face", 12: "(l) line+face", 13: "beyond"}


def pressed(row, slot):
    value = float(row[f"{slot}.normal_force"])
    return not math.isnan(value) and value > 0.0


def summarise(run, min_speed):
    with open(os.path.join(run, "energy.csv"), newline="") as f:
        energy = [float(r["total"]) for r in csv.DictReader(f)]
    (force,) = glob.glob(os.path.join(run, "force_*.csv"))
    onsets, by_slot, previous = {}, {s: 0 for s in SLOTS}, {s: False for s in SLOTS}
    with open(force, newline="") as f:
        for row in csv.DictReader(f):
            for slot in SLOTS:
                now = pressed(row, slot)
                if now and not previous[slot] and float(row[f"{slot}.approach_speed"]) >= min_speed:
                    key = NAMES.get(int(float(row["scenario"])), row["scenario"])
                    onsets[key] = onsets.get(key, 0) + 1
                    by_slot[slot] += 1
                previous[slot] = now
    return energy[0], energy[0] - energy[-1], onsets, by_slot


def main(args):
    min_speed = 0.0
    if args[0] == "--min-speed":
        min_speed, args = float(args[1]), args[2:]
    for run in args:
        e0, lost, onsets, by_slot = summarise(run, min_speed)
        per = ", ".join(f"{k} {v}" for k, v in sorted(onsets.items(), key=lambda kv: -kv[1]))
        print(f"{run}: E0 = {e0:.6g} J, lost {lost:.6g} J ({100 * lost / e0:.1f} %), "
              f"{sum(onsets.values())} onsets; by scenario: {per}; by slot: "
              + ", ".join(f"{k} {v}" for k, v in by_slot.items()))


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if len(sys.argv) >= 2 else 2)
    main(sys.argv[1:])
