#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Reproduce Section 6 of Marques et al. (2017): run the slider-crank models and draw Figs. 7-11
and 13-19 as PNG files.

    python3 scripts/reproduce_section6.py --clearjoint build/apps/clearjoint/clearjoint

Runs (all in models/): the planar slider-crank with ideal joints and with the clearance joint
aligned and misaligned (Sec. 6.1), the spatial one ideal and with the clearance joint (Sec. 6.2),
the 16 runs of the clearance study (models/clearance_study/), the same at tolerance 1e-8, and an
ensemble of 9 runs (initial crank speed x (1 + k 1e-9), k = -4..4) for each point of the radial,
axial and diagonal sweeps (ensemble_vs_clearance.png, section6_ensemble.py), and the radial and
axial ones again at tolerance 1e-8 (ensemble_vs_clearance_tolerance_1e-8.png). They run in parallel, one per
core (--jobs), with a progress line on standard error. Each run's result is reduced to the columns
the figures need and written atomically to RESULTS/<run>.npz (temporary name, then rename),
together with the SHA-256 of its model file; a later call skips every run whose result exists for
the same model file, so an interrupted sweep resumes where it stopped (--force redoes all).
Figures go to FIGURES/fig<N>.png, a summary of the measured numbers to RESULTS/summary.json.

Needs numpy and matplotlib (Debian: python3-matplotlib).
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = os.path.join(REPOSITORY, "models")
STUDY_MM = (0.05, 0.1, 0.3, 0.5)  # Sec. 6.2: radial and axial clearances [mm]
RESULT_FORMAT = 1  # bump when the reduced contents change: old results are then redone
SOURCE = "unknown"
# The simulations in progress, so that an interrupt can stop them (by their own process ids).
RUNNING = set()
RUNNING_LOCK = threading.Lock()
INTERRUPTED = threading.Event()

# Columns kept per run (file -> columns). Bodies: world-frame position, velocity, acceleration;
# the rod's Euler parameters; the joint's scenario, axis angle and rim centres in the bearing frame.
PLANAR_COLUMNS = {
    "body_slider.csv": ["time", "x", "vx", "ax"],
    "body_rod.csv": ["e0", "e1", "e2", "e3"],
    "energy.csv": ["total"],
}
SPATIAL_COLUMNS = {
    "body_slider.csv": ["time", "x", "vx", "ax"],
    "energy.csv": ["total"],
}
JOINT_COLUMNS = ["scenario", "axis_angle", "rim_a_u", "rim_a_v", "rim_a_axial", "rim_b_u", "rim_b_v",
                 "rim_b_axial"]


# The clearance study once more at a tenth of the paper's tolerance: the peak acceleration of one
# run is a single impact of a chaotic motion, and this shows how much of Fig. 19 survives a change
# of integration tolerance.
ROBUSTNESS_TOLERANCE = 1e-8


# Ensembles for the clearance trend of Figs. 15, 16 and 19. One run's peak acceleration is a single
# impact of a chaotic motion (it changes by a factor 0.69-1.88 with the tolerance), so each study
# point is also run with the held initial crank velocities scaled by 1 + k ENSEMBLE_STEP, k in
# ENSEMBLE_OFFSETS: a change far below anything the paper specifies (2 pi rad/s to 9 digits) and
# far above double rounding (2e-16), so the members share the physics and differ only in which
# impacts the chaotic motion happens to make. The member k = 0 is the study's model unchanged, run
# again here so that every member of an ensemble comes from the same build.
# Points: the radial sweep (axial 0.1 mm), the axial sweep (radial 0.1 mm) and the diagonal.
ENSEMBLE_STEP = 1e-9
ENSEMBLE_OFFSETS = (-4, -3, -2, -1, 0, 1, 2, 3, 4)


# The single-direction sweeps' ensembles once more at ROBUSTNESS_TOLERANCE: a second kind of
# perturbation (every step changes), to see whether the verdict on the trend depends on it.
ENSEMBLE_FINE_PREFIX = "tol1e-8_"


def ensemble_points(diagonal=True):
    """(radial, axial) clearances [mm] of the study points that get an ensemble."""
    points = [(cr, 0.1) for cr in STUDY_MM] + [(0.1, ca) for ca in STUDY_MM]
    if diagonal:
        points += [(c, c) for c in STUDY_MM]
    return list(dict.fromkeys(points))  # (0.1, 0.1) once, order kept


def ensemble_run_name(cr, ca, k, prefix=""):
    """The run of study point (cr, ca) [mm] with crank speed factor 1 + k ENSEMBLE_STEP."""
    return "ensemble_%scr%g_ca%g_k%+d" % (prefix, cr, ca, k)


def runs():
    """name -> (model file, columns per file, joint outputs wanted[, solver overrides[, crank
    speed factor]])."""
    table = {
        "planar_ideal": ("slider_crank_planar_ideal.json", PLANAR_COLUMNS, False),
        "planar_aligned": ("slider_crank_planar_clearance_aligned.json", PLANAR_COLUMNS, True),
        "planar_misaligned": ("slider_crank_planar_clearance_misaligned.json", PLANAR_COLUMNS, True),
        "spatial_ideal": ("slider_crank_spatial_ideal.json", SPATIAL_COLUMNS, False),
        "spatial_clearance": ("slider_crank_spatial_clearance.json", SPATIAL_COLUMNS, True),
    }
    for cr in STUDY_MM:
        for ca in STUDY_MM:
            model = os.path.join("clearance_study", "spatial_cr%g_ca%g.json" % (cr, ca))
            table["study_cr%g_ca%g" % (cr, ca)] = (model, SPATIAL_COLUMNS, False)
            table["study_tol1e-8_cr%g_ca%g" % (cr, ca)] = (
                model, SPATIAL_COLUMNS, False,
                {"relative_tolerance": ROBUSTNESS_TOLERANCE, "absolute_tolerance": ROBUSTNESS_TOLERANCE})
    for cr, ca in ensemble_points():
        model = os.path.join("clearance_study", "spatial_cr%g_ca%g.json" % (cr, ca))
        for k in ENSEMBLE_OFFSETS:
            table[ensemble_run_name(cr, ca, k)] = (model, SPATIAL_COLUMNS, False, {}, 1 + k * ENSEMBLE_STEP)
    fine = {"relative_tolerance": ROBUSTNESS_TOLERANCE, "absolute_tolerance": ROBUSTNESS_TOLERANCE}
    for cr, ca in ensemble_points(diagonal=False):
        model = os.path.join("clearance_study", "spatial_cr%g_ca%g.json" % (cr, ca))
        for k in ENSEMBLE_OFFSETS:
            table[ensemble_run_name(cr, ca, k, ENSEMBLE_FINE_PREFIX)] = (
                model, SPATIAL_COLUMNS, False, fine, 1 + k * ENSEMBLE_STEP)
    return table


def scale_crank_speed(model, factor):
    """Scales the crank's held initial velocities (and their guesses) by `factor`: the same rigid
    rotation about the journal's centre, a little faster or slower."""
    held = [h for h in model["initial_conditions"]["hold_velocities"] if h["body"] == "crank"]
    if not held:
        raise RuntimeError("crank speed factor: the model holds no crank velocity")
    for h in held:
        h["value"] *= factor
    crank = [b for b in model["bodies"] if b["name"] == "crank"][0]
    for key in ("velocity", "angular_velocity"):
        if key in crank:
            crank[key] = [v * factor for v in crank[key]]
    model["initial_conditions"]["comment"] = (
        "reproduce_section6.py ensemble member: held crank velocities scaled by %r" % factor)


def model_text(spec):
    """The model file's text, with the run's solver overrides applied (deterministic JSON)."""
    with open(os.path.join(MODELS, spec[0])) as f:
        text = f.read()
    solver = spec[3] if len(spec) > 3 else {}
    factor = spec[4] if len(spec) > 4 else None
    if not solver and factor is None:
        return text
    model = json.loads(text)
    if solver:
        model["solver"].update(solver)
        model["solver"]["comment"] = "reproduce_section6.py override: %s" % json.dumps(solver, sort_keys=True)
    if factor is not None:
        scale_crank_speed(model, factor)
    return json.dumps(model, indent=1, sort_keys=True) + "\n"


def source_version():
    """The commit the program was presumably built from, and whether the sources differed from it
    (results depend on rounding-level details: the contact sequence is chaotic)."""
    try:
        head = subprocess.run(["git", "-C", REPOSITORY, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True, check=True).stdout.strip()
        changed = subprocess.run(["git", "-C", REPOSITORY, "status", "--porcelain", "--", "geometry", "dynamics",
                                  "apps"], capture_output=True, text=True, check=True).stdout.strip()
        return head + (" with uncommitted changes in geometry/, dynamics/ or apps/" if changed else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown (not a git checkout)"


def sha256(text):
    return hashlib.sha256(text.encode()).hexdigest()


def read_columns(path, names):
    with open(path) as f:
        header = f.readline().strip().split(",")
    missing = [n for n in names if n not in header]
    if missing:
        raise RuntimeError("%s: no column %s" % (path, ", ".join(missing)))
    indices = [header.index(n) for n in names]
    data = np.loadtxt(path, delimiter=",", skiprows=1, usecols=indices, ndmin=2)
    return {n: data[:, k] for k, n in enumerate(names)}


def result_is_current(path, model_hash):
    if not os.path.exists(path):
        return False
    try:
        with np.load(path) as r:
            return str(r["model_sha256"]) == model_hash and int(r["format"]) == RESULT_FORMAT
    except Exception:  # unreadable (e.g. truncated by a crash before the rename existed): redo
        return False


def run_one(name, spec, clearjoint, results):
    """Simulate one model into a scratch directory, reduce it, write RESULTS/name.npz atomically."""
    columns, joint_outputs = spec[1], spec[2]
    text = model_text(spec)
    scratch = tempfile.mkdtemp(prefix=name + ".", dir=results)
    try:
        model_path = os.path.join(scratch, "model.json")  # the file as run, overrides included
        with open(model_path, "w") as f:
            f.write(text)
        start = time.monotonic()
        with RUNNING_LOCK:
            if INTERRUPTED.is_set():
                raise RuntimeError("%s: not started (interrupted)" % name)
            process = subprocess.Popen([clearjoint, "simulate", model_path, "--out", scratch],
                                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            RUNNING.add(process)
        try:
            stdout, stderr = process.communicate()
        finally:
            with RUNNING_LOCK:
                RUNNING.discard(process)
        wall = time.monotonic() - start
        if process.returncode != 0:
            raise RuntimeError("%s: clearjoint simulate failed (status %d): %s" % (
                name, process.returncode, (stderr or stdout).strip()))
        arrays = {}
        for file, names in columns.items():
            for column, values in read_columns(os.path.join(scratch, file), names).items():
                key = column if file in ("body_slider.csv", "energy.csv") else "rod_" + column
                arrays[key] = values
        if joint_outputs:
            joint_file = [f for f in os.listdir(scratch) if f.startswith("force_")]
            if len(joint_file) != 1:
                raise RuntimeError("%s: expected one force_*.csv, found %s" % (name, joint_file))
            for column, values in read_columns(os.path.join(scratch, joint_file[0]), JOINT_COLUMNS).items():
                arrays["joint_" + column] = values
        arrays["model_sha256"] = np.array(sha256(text))
        arrays["format"] = np.array(RESULT_FORMAT)
        arrays["wall_seconds"] = np.array(wall)
        arrays["source"] = np.array(SOURCE)
        arrays["simulate_output"] = np.array(stdout)
        final = os.path.join(results, name + ".npz")
        partial = final + ".partial-%d.npz" % os.getpid()
        np.savez_compressed(partial, **arrays)
        os.replace(partial, final)  # atomic on POSIX: readers see the old file or the whole new one
        return name, wall
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


class Progress:
    """One line on standard error: a bar over the runs, elapsed time and an estimate of the rest."""

    def __init__(self, total):
        self.total, self.done, self.start = total, 0, time.monotonic()
        self.tty = sys.stderr.isatty()
        self.lock = threading.Lock()
        self.draw("")

    def draw(self, last):
        elapsed = time.monotonic() - self.start
        rest = "~%.0f s" % (elapsed / self.done * (self.total - self.done)) if self.done else "?"
        width = 30
        filled = width * self.done // max(1, self.total)
        line = "[%s%s] %d/%d runs, %.0f s elapsed, %s to go %s" % (
            "#" * filled, " " * (width - filled), self.done, self.total, elapsed, rest, last)
        sys.stderr.write(("\r" + line + "\x1b[K") if self.tty else line + "\n")
        sys.stderr.flush()

    def advance(self, last):
        with self.lock:
            self.done += 1
            self.draw(last)

    def finish(self):
        if self.tty:
            sys.stderr.write("\n")


def run_all(clearjoint, results, jobs, force, only):
    os.makedirs(results, exist_ok=True)
    names = runs()
    for leftover in os.listdir(results):  # scratch directories and partial files of a killed run
        path = os.path.join(results, leftover)
        ours = any(leftover.startswith(name + ".") for name in names)  # names contain dots too
        if ours and os.path.isdir(path):
            shutil.rmtree(path, ignore_errors=True)
        elif ours and ".partial-" in leftover:
            os.remove(path)
    todo = {}
    for name, spec in names.items():
        if only and name not in only:
            continue
        model_hash = sha256(model_text(spec))
        if force or not result_is_current(os.path.join(results, name + ".npz"), model_hash):
            todo[name] = spec
    unknown = [name for name in (only or []) if name not in names]
    if unknown:
        raise SystemExit("--only: no run called %s (runs: %s)" % (", ".join(unknown), ", ".join(names)))
    skipped = (len(only) if only else len(names)) - len(todo)
    print("section 6: %d runs to do, %d up to date in %s, %d parallel jobs" % (
        len(todo), skipped, results, jobs), file=sys.stderr)
    if not todo:
        return
    progress = Progress(len(todo))
    failures = []
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=jobs)
    futures = {pool.submit(run_one, name, spec, clearjoint, results): name for name, spec in todo.items()}
    try:
        for future in concurrent.futures.as_completed(futures):
            try:
                name, wall = future.result()
                progress.advance("(%s: %.1f s)" % (name, wall))
            except Exception as error:  # keep the others going; report at the end
                failures.append(str(error))
                progress.advance("(%s failed)" % futures[future])
    except KeyboardInterrupt:
        # Runs not started are dropped and running simulations stopped; finished results are
        # complete files, and the next call removes the scratch directories and resumes. A second
        # interrupt (a terminal sends one to every process of the group) must not cut this short.
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        with RUNNING_LOCK:
            INTERRUPTED.set()
            for process in RUNNING:
                process.terminate()
        pool.shutdown(wait=True, cancel_futures=True)
        progress.finish()
        raise SystemExit("section 6: interrupted after %d of %d runs; run again to resume" % (
            progress.done, progress.total))
    pool.shutdown()
    progress.finish()
    if failures:
        raise SystemExit("section 6: %d runs failed:\n%s" % (len(failures), "\n".join(failures)))


def load(results, name):
    with np.load(os.path.join(results, name + ".npz")) as r:
        return {k: r[k] for k in r.files}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--clearjoint", required=True, help="the clearjoint program")
    parser.add_argument("--results", default=os.path.join(REPOSITORY, "results", "section6"))
    parser.add_argument("--figures", default=os.path.join(REPOSITORY, "docs", "figures", "section6"))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="parallel runs (all cores)")
    parser.add_argument("--force", action="store_true", help="redo runs whose results are up to date")
    parser.add_argument("--only", nargs="*", help="run only these (names as in the results)")
    parser.add_argument("--no-figures", action="store_true")
    parser.add_argument("--source", help="what the program was built from (default: this checkout's commit)")
    args = parser.parse_args()
    if not os.access(args.clearjoint, os.X_OK):
        raise SystemExit("--clearjoint %s: not an executable program" % args.clearjoint)
    if args.jobs < 1:
        raise SystemExit("--jobs %d: must be at least 1" % args.jobs)
    global SOURCE
    SOURCE = args.source or source_version()
    run_all(os.path.abspath(args.clearjoint), args.results, args.jobs, args.force, args.only)
    if not args.no_figures and not args.only:
        import section6_figures  # noqa: E402 (matplotlib only when drawing)
        import section6_ensemble  # noqa: E402
        summary = section6_figures.draw_all(lambda name: load(args.results, name), args.figures, STUDY_MM)
        summary["ensemble"] = section6_ensemble.draw(
            lambda name: load(args.results, name), args.figures, STUDY_MM, ensemble_points(), ENSEMBLE_OFFSETS,
            ensemble_run_name, "ensemble_vs_clearance.png", "tolerance 1e-7")
        summary["ensemble_tolerance_1e-8"] = section6_ensemble.draw(
            lambda name: load(args.results, name), args.figures, STUDY_MM, ensemble_points(diagonal=False),
            ENSEMBLE_OFFSETS, lambda cr, ca, k: ensemble_run_name(cr, ca, k, ENSEMBLE_FINE_PREFIX),
            "ensemble_vs_clearance_tolerance_1e-8.png", "tolerance 1e-8")
        summary["wall_seconds_per_run"] = {
            name: float(load(args.results, name)["wall_seconds"]) for name in runs()}
        summary["sources"] = sorted({str(load(args.results, name).get("source", "unknown")) for name in runs()})
        path = os.path.join(args.results, "summary.json")
        with open(path + ".partial", "w") as f:
            json.dump(summary, f, indent=1, sort_keys=True)
        os.replace(path + ".partial", path)
        print("figures in %s, numbers in %s" % (args.figures, path), file=sys.stderr)


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
