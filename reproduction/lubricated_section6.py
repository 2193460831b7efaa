#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The lubricated Section 6.1 beside the dry one (issue 36; docs/lubrication.md, "A lubricated
Section 6.1"): the planar slider-crank of Marques et al. (2017) with its rod-slider clearance
joint dry (models/slider_crank_planar_clearance_aligned.json) and lubricated
(models/slider_crank_planar_clearance_lubricated.json), and the ideal mechanism as reference.

One command runs the three models in process (clearjoint.simulate, in the engine --engine) up to
--end-time and draws, with clearjoint.plot's panels, over the window --window:
  comparison.png           dry, lubricated and ideal overlaid by clearjoint.plot.compare (what
                           `clearjoint plot DRY LUBRICATED --ideal IDEAL --out comparison.png` draws);
  orbit.png                the journal's centre in units of the radial clearance, dry and lubricated;
  joint_force.png          the magnitude of the joint's force (contact, or film plus contact),
                           from the start and over the window;
  slider_acceleration.png  the slider's acceleration, dry and lubricated, the ideal one dashed;
  film.png                 the lubricated film's minimum thickness and eccentricity ratio;
into --out (default: a folder "figures" beside the runs, in a new temporary folder; the page's
figures are regenerated with --out docs/figures/lubrication), and prints the numbers the page
quotes.

    PYTHONPATH=build/bindings/python /usr/bin/python3 reproduction/lubricated_section6.py --engine simbody
"""
import argparse
import json
import os
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import clearjoint  # noqa: E402
from clearjoint import plot as runplot  # noqa: E402
from clearjoint.plot.panels import IDEAL_CURVE  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = {"dry": "slider_crank_planar_clearance_aligned.json",
          "lubricated": "slider_crank_planar_clearance_lubricated.json",
          "ideal": "slider_crank_planar_ideal.json"}
# The window of the paper's Sec. 6.1 figures as reproduction/section6_figures.py draws them: past the
# first impacts, a steady portion.
WINDOW = (0.1, 0.2)
CURVES = {"dry": dict(color="tab:red", linewidth=0.7), "lubricated": dict(color="tab:blue", linewidth=0.9)}


def run(name, end_time, folder, engine):
    start = time.perf_counter()
    clearjoint.simulate(os.path.join(ROOT, "models", MODELS[name]), out=folder, force=True, engine=engine,
                        overrides={"solver.end_time": end_time})
    return runplot.read_run(folder), time.perf_counter() - start


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path + ".partial.png", dpi=110)
    plt.close(fig)
    os.replace(path + ".partial.png", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--end-time", type=float, default=WINDOW[1], help="simulated time [s]")
    parser.add_argument("--window", type=float, nargs=2, default=WINDOW, help="drawn window [s]")
    parser.add_argument("--engine", default="clearjoint", choices=clearjoint._core.engines(),
                        help="the integrating engine (clearjoint simulate --engine)")
    parser.add_argument("--out", default=None,
                        help="where the figures go (default: RUNS/figures; the page's: docs/figures/lubrication)")
    parser.add_argument("--runs", default=None,
                        help="where the run folders go (default: a new temporary folder)")
    a = parser.parse_args()
    a.runs = a.runs or tempfile.mkdtemp(prefix="lubricated-section6-")
    a.out = a.out or os.path.join(a.runs, "figures")
    os.makedirs(a.out, exist_ok=True)
    window = tuple(a.window)
    runs, seconds = {}, {}
    for name in MODELS:
        runs[name], seconds[name] = run(name, a.end_time, os.path.join(a.runs, name), a.engine)
    comparison = runplot.compare([runs["dry"], runs["lubricated"]], labels=[f"dry ({a.engine})", f"lubricated ({a.engine})"],
                                 window=tuple(a.window), ideal=runs["ideal"])
    save(comparison.figure, a.out, "comparison.png")
    table = runs["dry"].clearance_tables()[0]
    series = {k: runplot.joint_series(runs[k], table, window) for k in ("dry", "lubricated")}

    fig, axes = plt.subplots(1, 2, figsize=(9, 4.6))
    for ax, k in zip(axes, ("dry", "lubricated")):
        runplot.plot_orbit(ax, series[k], title=f"{k}: journal centre, {window[0]:g}-{window[1]:g} s")
    fig.tight_layout()
    save(fig, a.out, "orbit.png")

    # The joint's force from the start (the dry journal's first impacts) and over the window.
    fig, axes = plt.subplots(2, 1, figsize=(8, 6))
    peak = {}
    for ax, (t0, t1) in zip(axes, ((0.0, window[0]), window)):
        for k in ("dry", "lubricated"):
            columns = runs[k].table(table)
            keep = (columns["time"] >= t0) & (columns["time"] <= t1)
            force = np.hypot(columns["fx"], columns["fy"])[keep]
            peak[f"{k} {t0:g}-{t1:g} s"] = float(force.max())
            ax.plot(columns["time"][keep], force, label=f"{k} (peak {force.max():.0f} N)", **CURVES[k])
        ax.set_ylabel("joint force |F| [N]")
        ax.legend(loc="upper right", fontsize=8)
        ax.grid(True, linewidth=0.3, alpha=0.5)
    axes[1].set_xlabel("time [s]")
    fig.tight_layout()
    save(fig, a.out, "joint_force.png")

    fig, ax = plt.subplots(figsize=(8, 3.6))
    t, ideal, component = runplot.slider_acceleration(runs["ideal"], "slider", window)
    ax.plot(t, ideal, label="ideal joint", **IDEAL_CURVE)
    spread = {}
    for k in ("dry", "lubricated"):
        t, acceleration, component = runplot.slider_acceleration(runs[k], "slider", window)
        spread[k] = float(np.max(np.abs(acceleration - np.interp(t, *runplot.slider_acceleration(runs["ideal"], "slider", window)[:2]))))
        ax.plot(t, acceleration, label=k, **CURVES[k])
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"slider acceleration {component} [m/s$^2$]")
    ax.legend(loc="upper right", fontsize=8)
    ax.grid(True, linewidth=0.3, alpha=0.5)
    fig.tight_layout()
    save(fig, a.out, "slider_acceleration.png")

    columns = runs["lubricated"].table(table)
    keep = (columns["time"] >= window[0]) & (columns["time"] <= window[1])
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 4.6), sharex=True)
    top.plot(columns["time"][keep], 1e6 * columns["film.min_thickness"][keep], **CURVES["lubricated"])
    top.set_ylabel("h_min [µm]")
    bottom.plot(columns["time"][keep], columns["film.eccentricity_ratio"][keep], **CURVES["lubricated"])
    bottom.set_ylabel("eps [-]")
    bottom.set_xlabel("time [s]")
    for ax in (top, bottom):
        ax.grid(True, linewidth=0.3, alpha=0.5)
    fig.tight_layout()
    save(fig, a.out, "film.png")

    regimes = {int(r): int(n) for r, n in zip(*np.unique(columns["film.regime"], return_counts=True))}
    print(json.dumps({
        "engine": a.engine, "out": a.out, "end_time": a.end_time, "window": window, "wall_seconds": seconds,
        "peak_joint_force": peak, "largest_slider_acceleration_departure_from_ideal": spread,
        "lubricated": {"min_film_thickness": float(np.min(columns["film.min_thickness"])),
                       "max_eccentricity_ratio": float(np.max(columns["film.eccentricity_ratio"])),
                       "max_pressure": float(np.nanmax(columns["film.max_pressure"])),
                       "regime_rows": regimes,
                       "impacts": int(len(series["lubricated"].impact_rows))},
        "dry_impacts_in_window": int(len(series["dry"].impact_rows)),
    }, indent=1, default=str))


if __name__ == "__main__":
    main()
