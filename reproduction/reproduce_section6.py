#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Reproduce Section 6 of Marques et al. (2017), Figs. 7-11 and 13-19 and the numbers of
docs/reports/reproduction.md, in one command:

    python3 reproduction/reproduce_section6.py                 # resumes: stored runs are not redone
    python3 reproduction/reproduce_section6.py --force         # redo every run (after changing the code)
    python3 reproduction/reproduce_section6.py --scheduler tcp://host:8786
    python3 reproduction/reproduce_section6.py --update-docs   # also the page's figures and tables

1. Builds the clearjoint program and its Python package in --build-dir (default build).
2. Runs the three Section 6 studies with the study runner (docs/studies.md), on a local Dask
   cluster (one worker per core, or --workers) or an existing one (--scheduler):
   reproduction/studies/section6_mechanisms.json (37 runs: the planar and spatial slider-cranks
   and the 4 x 4 clearance study at two tolerances; Figs. 7-19), section6_clearance.json (153
   runs: ensembles of 9 runs per point of the radial, axial and diagonal sweeps) and
   section6_settling.json (11 runs: the variants behind the page's explanations). Stores:
   results/section6_mechanisms/, results/section6_clearance/, results/section6_settling/.
3. With the interpreter the package was built for, draws every figure into --out (default
   results/section6: figures/ and summary.json, the numbers the page quotes); the figures of one
   run with clearjoint.plot's panels, the ensembles with the study's plots. --update-docs then
   copies the figures the docs show into docs/figures/section6/ and rewrites the generated tables
   of docs/reports/reproduction.md (between its "generated" markers) from the stores.

--draw-only skips steps 1 and 2 (it needs the clearjoint package, PYTHONPATH=build/bindings/python
in a build tree, and matplotlib).
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(HERE)
STUDIES = os.path.join(HERE, "studies")
STUDY_FILES = ("section6_mechanisms.json", "section6_clearance.json", "section6_settling.json")
# The committed copies of the figures the docs show (docs/figures/section6/NAME.png in a page).
DOCS_FIGURES = os.path.join(REPOSITORY, "docs", "figures", "section6")
SHOWN_FIGURE = re.compile(r"figures/section6/([A-Za-z0-9_.-]+\.png)")
STUDY_MM = (0.05, 0.1, 0.3, 0.5)  # Sec. 6.2: radial and axial clearances [mm]
PAPER_TOLERANCE, FINE_TOLERANCE = 1e-7, 1e-8


class StoreRuns:
    """A study's stored runs by the point's parameters, as the figure code reads them: the old
    reduced-run layout (time, x, vx, ax, total, rod_e0..e3, joint_<column>), and the stored
    tables with the model they ran ("tables", "model": what clearjoint.plot.read_run takes)."""

    def __init__(self, study_file):
        from clearjoint.study import Store, expand_study, load_study
        self.study = load_study(study_file)
        self.points, _, self.membership = expand_study(self.study)
        self.store = Store(self.study.store_path)
        missing = {run_id for run_id in self.membership.values()} - self.store.stored_ids()
        if missing:
            raise SystemExit("%s: %d runs are not in the store %s; run `clearjoint study run %s` first" % (
                study_file, len(missing), self.store.path, study_file))

    def run_id(self, design=None, member=0, **values):
        for point in self.points:
            if design is not None and point.base != design:
                continue
            if design is None and (point.base or any(point.value(k) != v for k, v in values.items())):
                continue
            return self.membership[(point.point_id, member)]
        raise KeyError("no point %s %s" % (design, values))

    def load(self, run_id):
        stored = self.store.read(run_id)
        run = {"wall_seconds": stored["attrs"]["wall_seconds"], "source": stored["attrs"]["library_version"],
               "tables": stored["time_series"], "model": json.loads(stored["attrs"]["model"])}
        for table, columns in stored["time_series"].items():
            for column, values in columns.items():
                if table == "body_slider" or (table == "energy" and column != "time"):
                    run[column] = values
                elif table.startswith("body_rod") and column != "time":
                    run["rod_" + column] = values
                elif table.startswith("force_") and column != "time":
                    run["joint_" + column] = values
        return run


def mechanism_loader(mechanisms):
    """The old run names (planar_ideal, study_cr0.1_ca0.3, study_tol1e-8_cr0.1_ca0.3, ...) to runs."""
    def load(name):
        if name.startswith("study_"):
            fine = name.startswith("study_tol1e-8_")
            cr, ca = name.split("_cr")[1].split("_ca")
            run_id = mechanisms.run_id(radial_clearance_mm=float(cr), axial_clearance_mm=float(ca),
                                       tolerance=FINE_TOLERANCE if fine else PAPER_TOLERANCE)
        else:
            run_id = mechanisms.run_id(design=name)
        return mechanisms.load(run_id)
    return load


def figures_the_docs_show():
    """The names of the Section 6 figures a page of the docs (or the README) shows."""
    pages = [os.path.join(REPOSITORY, "README.md")] + glob.glob(os.path.join(REPOSITORY, "docs", "**", "*.md"),
                                                                 recursive=True)
    names = set()
    for page in pages:
        with open(page, encoding="utf-8") as f:
            names.update(SHOWN_FIGURE.findall(f.read()))
    return sorted(names)


def build_and_run_studies(args):
    """Steps 1 and 2; returns the interpreter the package was built for."""
    build = os.path.abspath(args.build_dir)
    subprocess.run(["cmake", "-S", REPOSITORY, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                    "-DCLEARJOINT_BUILD_PYTHON=ON"], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", build, "-j2", "--target", "clearjoint", "clearjoint_python_core"],
                   check=True)
    run_options = ["--no-plot"] + (["--force"] if args.force else [])
    if args.scheduler:
        run_options += ["--scheduler", args.scheduler]
    elif args.workers:
        run_options += ["--workers", str(args.workers)]
    program = os.path.join(build, "apps", "clearjoint", "clearjoint")
    for study in STUDY_FILES:
        subprocess.run([program, "study", "run", os.path.join(STUDIES, study)] + run_options, check=True)
    with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8") as f:
        cached = re.search(r"^Python3_EXECUTABLE:FILEPATH=(.*)$", f.read(), re.MULTILINE)
    return cached.group(1) if cached else "/usr/bin/python3"


def draw(args):
    """Step 3, in the interpreter the package was built for."""
    import section6_figures  # noqa: E402 (matplotlib only when drawing)
    import section6_settling  # noqa: E402
    import section6_tables  # noqa: E402
    from clearjoint.study.plot import draw_all

    figures = os.path.join(args.out, "figures")
    summary_path = os.path.join(args.out, "summary.json")
    os.makedirs(figures, exist_ok=True)
    mechanisms = StoreRuns(os.path.join(STUDIES, "section6_mechanisms.json"))
    clearance = StoreRuns(os.path.join(STUDIES, "section6_clearance.json"))
    settling = StoreRuns(os.path.join(STUDIES, "section6_settling.json"))
    load = mechanism_loader(mechanisms)
    summary = section6_figures.draw_all(load, figures, STUDY_MM)
    from clearjoint.study.summary import summarise
    ensembles = summarise(clearance.study, clearance.store, clearance.points, clearance.membership)
    draw_all(clearance.study, ensembles, figures)  # the study alone draws into its store
    summary["ensembles"] = {"points": {pid: {s: {k: v for k, v in e.items()} for s, e in stats.items()}
                                       for pid, stats in ensembles["points"].items()},
                            "trends": ensembles["trends"]}
    summary["settling"] = section6_settling.summarise(settling)
    attrs = [study.store.read(r, series=False)["attrs"] for study in (mechanisms, clearance, settling)
             for r in sorted(set(study.membership.values()))]
    summary["wall_seconds_per_run"] = sorted(float(a["wall_seconds"]) for a in attrs)
    summary["library_versions"] = sorted({str(a["library_version"]) for a in attrs})
    with open(summary_path + ".partial", "w") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    os.replace(summary_path + ".partial", summary_path)
    print("figures in %s, numbers in %s" % (figures, summary_path), file=sys.stderr)
    if args.update_docs:
        shown = figures_the_docs_show()
        missing = [name for name in shown if not os.path.isfile(os.path.join(figures, name))]
        if missing:
            raise SystemExit("the docs show figures this command did not draw: %s" % ", ".join(missing))
        os.makedirs(DOCS_FIGURES, exist_ok=True)
        for name in shown:
            shutil.copyfile(os.path.join(figures, name), os.path.join(DOCS_FIGURES, name))
        page = os.path.join(REPOSITORY, "docs", "reports", "reproduction.md")
        section6_tables.update_page(page, load, ensembles, clearance.study, STUDY_MM, summary, len(attrs))
        print("%d figures copied to %s, tables of %s regenerated" % (len(shown), DOCS_FIGURES, page),
              file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", default=os.environ.get("BUILD_DIR", "build"),
                        help="the CMake build folder (default: build, or $BUILD_DIR)")
    parser.add_argument("--force", action="store_true", help="run again runs the stores already hold")
    parser.add_argument("--scheduler", help="an existing Dask scheduler (tcp://host:8786)")
    parser.add_argument("--workers", type=int, default=int(os.environ["JOBS"]) if os.environ.get("JOBS") else None,
                        help="local cluster: worker processes (default: one per core, or $JOBS)")
    parser.add_argument("--out", default=os.path.join(REPOSITORY, "results", "section6"),
                        help="where the figures (OUT/figures) and the numbers (OUT/summary.json) go")
    parser.add_argument("--update-docs", action="store_true",
                        help="copy the figures the docs show into docs/figures/section6 and rewrite the "
                             "generated tables of docs/reports/reproduction.md")
    parser.add_argument("--draw-only", action="store_true",
                        help="only draw (and --update-docs) from the stores: no build, no runs")
    args = parser.parse_args()
    if args.draw_only:
        draw(args)
        return
    python = build_and_run_studies(args)
    package = os.path.join(os.path.abspath(args.build_dir), "bindings", "python")
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [package] + ([os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else [])))
    command = [python, os.path.abspath(__file__), "--draw-only", "--out", os.path.abspath(args.out)]
    sys.exit(subprocess.run(command + (["--update-docs"] if args.update_docs else []), env=environment).returncode)


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
