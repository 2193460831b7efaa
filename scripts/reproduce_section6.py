#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Figures 7-11 and 13-19 of Marques et al. (2017), Section 6, and the numbers of
docs/reports/reproduction.md, from the stores of the two Section 6 studies:

    clearjoint study run studies/section6_mechanisms.json    # 37 runs: Figs. 7-19
    clearjoint study run studies/section6_clearance.json     # 153 runs: the ensembles (and their figures)
    clearjoint study run studies/section6_settling.json      # 11 runs: the explanations' variants
    python3 scripts/reproduce_section6.py [--update-docs]

(bash scripts/reproduce-section6.sh does all four.) Figures go to docs/figures/section6/, the
measured numbers to results/section6/summary.json; --update-docs rewrites the generated tables of
docs/reports/reproduction.md (between its "generated" markers) from the stores.

Needs the clearjoint package (PYTHONPATH=build/bindings/python in a build tree) and matplotlib.
"""
import argparse
import json
import os
import sys

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STUDIES = os.path.join(REPOSITORY, "studies")
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--figures", default=os.path.join(REPOSITORY, "docs", "figures", "section6"))
    parser.add_argument("--summary", default=os.path.join(REPOSITORY, "results", "section6", "summary.json"))
    parser.add_argument("--update-docs", action="store_true",
                        help="rewrite the generated tables of docs/reports/reproduction.md from the "
                             "stores")
    args = parser.parse_args()
    import section6_figures  # noqa: E402 (matplotlib only when drawing)
    import section6_settling  # noqa: E402
    import section6_tables  # noqa: E402
    from clearjoint.study.plot import draw_all

    mechanisms = StoreRuns(os.path.join(STUDIES, "section6_mechanisms.json"))
    clearance = StoreRuns(os.path.join(STUDIES, "section6_clearance.json"))
    settling = StoreRuns(os.path.join(STUDIES, "section6_settling.json"))
    load = mechanism_loader(mechanisms)
    summary = section6_figures.draw_all(load, args.figures, STUDY_MM)
    from clearjoint.study.summary import summarise
    ensembles = summarise(clearance.study, clearance.store, clearance.points, clearance.membership)
    draw_all(clearance.study, ensembles, args.figures)  # the study alone draws into its store
    summary["ensembles"] = {"points": {pid: {s: {k: v for k, v in e.items()} for s, e in stats.items()}
                                       for pid, stats in ensembles["points"].items()},
                            "trends": ensembles["trends"]}
    summary["settling"] = section6_settling.summarise(settling)
    attrs = [study.store.read(r, series=False)["attrs"] for study in (mechanisms, clearance, settling)
             for r in sorted(set(study.membership.values()))]
    summary["wall_seconds_per_run"] = sorted(float(a["wall_seconds"]) for a in attrs)
    summary["library_versions"] = sorted({str(a["library_version"]) for a in attrs})
    os.makedirs(os.path.dirname(args.summary), exist_ok=True)
    with open(args.summary + ".partial", "w") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    os.replace(args.summary + ".partial", args.summary)
    print("figures in %s, numbers in %s" % (args.figures, args.summary), file=sys.stderr)
    if args.update_docs:
        page = os.path.join(REPOSITORY, "docs", "reports", "reproduction.md")
        section6_tables.update_page(page, load, ensembles, clearance.study, STUDY_MM, summary, len(attrs))
        print("tables of %s regenerated" % page, file=sys.stderr)


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
