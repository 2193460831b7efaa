# SPDX-License-Identifier: BSD-3-Clause
"""The tables of docs/reproduction.md, generated from the Section 6 study stores: each sits
between `<!-- generated: NAME -->` and `<!-- end generated: NAME -->` and is replaced whole."""
import os
import re

import numpy as np

TOLERANCES = (1e-7, 1e-8)
STATISTIC_NAMES = {"peak": "peak", "p999": "99.9th percentile", "p99": "99th percentile", "rms": "RMS"}


def _number(value):
    """Three significant figures at most, as the page writes accelerations: 575, 15.7."""
    return "%.0f" % value if abs(value) >= 100 else "%.1f" % value


def _tolerance(value):
    return ("%g" % value).replace("e-0", "e-")


def _p_value(p):
    if p < 1e-4:
        return "< 1e-4"
    if p < 1e-3:
        return ("%.1e" % p).replace("e-0", "e-")
    return "%.2g" % p if p < 0.1 else "%.2f" % p


def single_run_peaks(load, clearances_mm):
    """Figs. 15, 16 and the diagonal of Fig. 19: the peak |a| of single runs at both tolerances."""
    sweeps = (("c_r varied, c_a = 0.1 mm", lambda c: (c, 0.1)), ("c_a varied, c_r = 0.1 mm", lambda c: (0.1, c)),
              ("c_r = c_a varied", lambda c: (c, c)))
    lines = ["| | %s |" % " | ".join("%g mm" % c for c in clearances_mm),
             "| --- |%s" % (" ---: |" * len(clearances_mm))]
    for label, point in sweeps:
        for tolerance in TOLERANCES:
            prefix = "study_" if tolerance == TOLERANCES[0] else "study_tol1e-8_"
            peaks = [np.abs(load("%scr%g_ca%g" % ((prefix,) + point(c)))["ax"]).max() for c in clearances_mm]
            name = ("%s, tolerance %s" % (label, _tolerance(tolerance)) if tolerance == TOLERANCES[0]
                    else "same at tolerance %s" % _tolerance(tolerance))
            lines.append("| %s | %s |" % (name, " | ".join("%.0f" % p for p in peaks)))
    return "\n".join(lines)


def ensemble_table(summary, study, designs, statistics, clearances_mm):
    """Median (min-max) per point along each design, P (p) between neighbours and first-last."""
    steps = ", ".join("%g->%g" % pair for pair in zip(clearances_mm, clearances_mm[1:]))
    lines = ["| statistic | sweep | %s | P (p) %s | P (p) %g->%g |" % (
                 " | ".join("%g mm" % c for c in clearances_mm), steps, clearances_mm[0], clearances_mm[-1]),
             "| --- | --- |%s --- | --- |" % (" ---: |" * len(clearances_mm))]
    rows = {(r["point_id"]): r for r in summary["runs"]}
    for statistic in statistics:
        for name in designs:
            design = study.design(name)
            line = sorted((pid for pid, row in rows.items() if name in row["designs"].split(" ")),
                          key=lambda pid: rows[pid][design["x"]])
            cells = []
            for pid in line:
                e = summary["points"][pid][statistic]
                cells.append("%s (%s-%s)" % (_number(e["median"]), _number(e["min"]), _number(e["max"])))
            trends = [t for t in summary["trends"] if t["design"] == name and t["statistic"] == statistic]
            cell = lambda t: "%.2f (%s)" % (t["probability_greater"], _p_value(t["p_value_greater"]))  # noqa: E731
            neighbours = ", ".join(cell(t) for t in trends[:-1])
            label = design.get("label", name).replace("$", "")
            lines.append("| %s | %s | %s | %s | %s |" % (STATISTIC_NAMES.get(statistic, statistic), label,
                                                        " | ".join(cells), neighbours, cell(trends[-1])))
    return "\n".join(lines)


def replace_block(text, name, body):
    pattern = re.compile(r"(<!-- generated: %s -->\n).*?(\n<!-- end generated: %s -->)" % (
        re.escape(name), re.escape(name)), re.S)
    if not pattern.search(text):
        raise SystemExit("docs/reproduction.md: no generated block %r" % name)
    return pattern.sub(lambda m: m.group(1) + body + m.group(2), text)


def update_page(page, load, ensembles, study, clearances_mm):
    with open(page) as f:
        text = f.read()
    text = replace_block(text, "single_run_peaks", single_run_peaks(load, clearances_mm))
    text = replace_block(text, "ensembles_tolerance_1e-7", ensemble_table(
        ensembles, study, ["radial", "axial", "diagonal"], ["peak", "p999", "rms"], clearances_mm))
    text = replace_block(text, "ensembles_tolerance_1e-8", ensemble_table(
        ensembles, study, ["radial_tolerance_1e-8", "axial_tolerance_1e-8"], ["peak", "p999", "rms"], clearances_mm))
    with open(page + ".partial", "w") as f:
        f.write(text)
    os.replace(page + ".partial", page)
