#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The paper's Section 6.2 spatial slider-crank for 1 s, compliant (the model file as shipped)
and Moreau-Jean at h = 1e-4 s and 1e-5 s: energy lost and contact onsets per slot and per
scenario beside each other, as the generated table of docs/nonsmooth.md ("The spatial
slider-crank, non-smooth") and the figure docs/figures/nonsmooth/spatial_slider_crank.png.

usage: PYTHONPATH=build/bindings/python nonsmooth/scripts/spatial_comparison.py [--runs DIR] [--reuse]
           [--page MD] [--figure PNG]

Runs the three models with clearjoint.simulate into DIR (default build/nonsmooth_spatial; --reuse
keeps folders already there), counts onsets with impacts_by_scenario.py (all of them, and those
approaching at MIN_SPEED or faster), draws the figure (default
docs/figures/nonsmooth/spatial_slider_crank.png) and rewrites the block between
`<!-- generated: spatial -->` and `<!-- end generated: spatial -->` of the page (default
docs/nonsmooth.md)."""
import argparse
import csv
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
from impacts_by_scenario import SLOTS, summarise  # noqa: E402

MODEL = os.path.join(ROOT, "models", "slider_crank_spatial_clearance.json")
PAGE = os.path.join(ROOT, "docs", "nonsmooth.md")
FIGURE = os.path.join(ROOT, "docs", "figures", "nonsmooth", "spatial_slider_crank.png")
BEGIN, END = "<!-- generated: spatial -->", "<!-- end generated: spatial -->"
# Onsets approaching at least this fast [m/s] are counted as impacts: it leaves out the
# chatter of a sustained Moreau-Jean contact (re-activations at a rebound speed of e times a
# step's gravity-scale approach, ~1e-3 m/s) and keeps every impact of the compliant run that
# moves the mechanism (the paper's impacts are at 0.05-0.5 m/s).
MIN_SPEED = 0.01
# (folder, label, overrides): the model file's compliant run at its own settings (Table 2), and
# the non-smooth runs reporting every step.
RUNS = [
    ("compliant", "compliant (Dormand-Prince, tol 1e-7)", {}),
    ("moreau_jean_1e-4", "Moreau-Jean, h = 1e-4 s",
     {"solver.method": "moreau_jean", "solver.step": 1e-4, "solver.report_step": 1e-4}),
    ("moreau_jean_1e-5", "Moreau-Jean, h = 1e-5 s",
     {"solver.method": "moreau_jean", "solver.step": 1e-5, "solver.report_step": 1e-5}),
]


def run_all(folder, reuse):
    import clearjoint
    for name, _, overrides in RUNS:
        out = os.path.join(folder, name)
        if reuse and os.path.exists(os.path.join(out, "summary.json")):
            continue
        clearjoint.simulate(MODEL, out=out, force=True, overrides=overrides)


def statistics(folder, name):
    """The summary's step count and, for Moreau-Jean, contact problems and unconverged steps."""
    import json
    summary = json.load(open(os.path.join(folder, name, "summary.json")))
    text = f"{summary['steps']} steps"
    for line in summary["element_statistics"]:
        match = re.match(r"moreau_jean: .*?, (\d+) contact problems, .*?, (\d+) unconverged steps", line)
        if match:
            text += f", {match.group(1)} contact problems, {match.group(2)} unconverged"
    return text


def energy_series(run):
    with open(os.path.join(run, "energy.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r["time"]) for r in rows], [float(r["total"]) for r in rows]


def table(folder, results):
    head = ("| run | energy lost in 1 s | onsets (all) | onsets at >= {s} m/s | by slot, >= {s} m/s ({slots}) "
            "| by scenario, >= {s} m/s | run |").format(s=MIN_SPEED, slots=", ".join(SLOTS))
    lines = [head, "| --- | --- | ---: | ---: | --- | --- | --- |"]
    for (name, label, _), (every, fast) in zip(RUNS, results):
        e0, lost, onsets_all, _ = every
        _, _, onsets, by_slot = fast
        scenarios = ", ".join(f"{k} {v}" for k, v in sorted(onsets.items(), key=lambda kv: (-kv[1], kv[0])))
        lines.append(f"| {label} | {lost:.3f} J ({100 * lost / e0:.1f} % of E0 = {e0:.3f} J) | "
                     f"{sum(onsets_all.values())} | {sum(onsets.values())} | "
                     f"{', '.join(str(by_slot[s]) for s in SLOTS)} | {scenarios} | {statistics(folder, name)} |")
    return "\n".join(lines)


def figure(folder, results, path):
    fig, (energy_axes, slot_axes, scenario_axes) = plt.subplots(1, 3, figsize=(15, 4.2),
                                                                gridspec_kw={"width_ratios": [1.1, 1, 1.4]})
    width = 0.8 / len(RUNS)
    scenarios = sorted({k for _, fast in results for k in fast[2]},
                       key=lambda k: (k in ("none", "beyond"), k))
    for index, ((name, label, _), (_, fast)) in enumerate(zip(RUNS, results)):
        times, total = energy_series(os.path.join(folder, name))
        energy_axes.plot(times, total, label=label, linewidth=1)
        offset = (index - (len(RUNS) - 1) / 2) * width
        slot_axes.bar([k + offset for k in range(len(SLOTS))], [fast[3][s] for s in SLOTS], width, label=label)
        scenario_axes.bar([k + offset for k in range(len(scenarios))], [fast[2].get(s, 0) for s in scenarios],
                          width, label=label)
    energy_axes.set(xlabel="time [s]", ylabel="total energy [J]", title="Mechanical energy")
    energy_axes.legend(fontsize=8)
    slot_axes.set_xticks(range(len(SLOTS)), SLOTS, rotation=30)
    slot_axes.set(ylabel="onsets", title=f"Impacts (>= {MIN_SPEED} m/s) per contact slot")
    scenario_axes.set_xticks(range(len(scenarios)), scenarios, rotation=30)
    scenario_axes.set(ylabel="onsets", title=f"Impacts (>= {MIN_SPEED} m/s) per scenario (Fig. 2)")
    fig.suptitle("Spatial slider-crank with its clearance joint (paper Section 6.2), 1 s: compliant and non-smooth")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=110)


def commit_text():
    """HEAD, marked when tracked files differ from it (the build may hold those changes)."""
    try:
        git = ["git", "-C", ROOT]
        commit = subprocess.run(git + ["rev-parse", "--short=10", "HEAD"], capture_output=True, text=True,
                                check=True).stdout.strip()
        dirty = subprocess.run(git + ["status", "--porcelain", "--untracked-files=no"], capture_output=True,
                               text=True, check=True).stdout.strip()
        return commit + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", default=os.path.join(ROOT, "build", "nonsmooth_spatial"))
    parser.add_argument("--reuse", action="store_true", help="keep run folders already written")
    parser.add_argument("--page", default=PAGE, help="the page whose generated block is rewritten")
    parser.add_argument("--figure", default=FIGURE, help="the figure's file")
    args = parser.parse_args()
    run_all(args.runs, args.reuse)
    results = [(summarise(os.path.join(args.runs, name), 0.0), summarise(os.path.join(args.runs, name), MIN_SPEED))
               for name, _, _ in RUNS]
    figure(args.runs, results, args.figure)
    page = open(args.page).read()
    pattern = re.compile(re.escape(BEGIN) + r"\n.*?" + re.escape(END), re.S)
    if not pattern.search(page):
        sys.exit(f"{args.page}: no {BEGIN} ... {END} block to rewrite")
    block = (f"{BEGIN}\nGenerated by `nonsmooth/scripts/spatial_comparison.py` from commit {commit_text()}.\n\n"
             f"{table(args.runs, results)}\n{END}")
    with open(args.page, "w") as f:
        f.write(pattern.sub(lambda _: block, page, count=1))
    print(f"wrote {args.figure} and the spatial table of {args.page}")


if __name__ == "__main__":
    main()
