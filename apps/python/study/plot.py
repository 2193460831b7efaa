# SPDX-License-Identifier: BSD-3-Clause
"""The standard figure of a study: each statistic against the design's x parameter, one line per
design, the median of the members with bars from their minimum to their maximum and every member
as a dot (docs/figures/section6/ensemble_vs_clearance.png is one, drawn there by
reproduction/reproduce_section6.py; `study plot` draws into STORE/figures).

Titles and labels come from the study: a plot's title, x_label and the reductions' labels may name
{study}, {points}, {members} and {end_time}, filled in from the study's expansion, so that a title
does not state a member count or a simulated time that the file no longer has."""
import math
import os

import numpy as np

COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown")
# Neighbouring designs' bars are shifted apart by this share of the x range.
SHIFT_SHARE = 0.0178


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


DEFAULT_TITLE = "{study}: median and range of {members} members per point, {end_time} s simulated"


def _range_text(values):
    values = sorted(set(v for v in values if v is not None))
    if not values:
        return "?"
    return "%g" % values[0] if len(values) == 1 else "%g to %g" % (values[0], values[-1])


def study_fields(study, plot):
    """What a plot's title and labels may name: {study}, {points} (the plot's points), {members}
    (members per point) and {end_time} (the runs' simulated end time, s)."""
    from .expand import expand_study
    points, runs, _ = expand_study(study)
    mine = [p for p in points if set(plot["designs"]) & set(p.designs)]
    ids = {p.point_id for p in mine}
    end_times = [(r.model.get("solver") or {}).get("end_time") for r in runs if r.point_id in ids]
    return {"study": study.name, "points": str(len(mine)), "members": _range_text(p.members for p in mine),
            "end_time": _range_text(end_times)}


def fill(text, fields):
    """text with each {name} of fields replaced (other braces are left as written)."""
    for name, value in fields.items():
        text = text.replace("{%s}" % name, value)
    return text


def plot_title(plot, fields):
    return fill(plot.get("title", DEFAULT_TITLE), fields)


def plots_of(study):
    """The study file's plots, or the default one; [] when there is nothing to plot."""
    return study.spec.get("plots") or default_plots(study)


def default_plots(study):
    designs = [d["name"] for d in study.spec["designs"] if "x" in d]
    statistics = [r["name"] for r in study.reductions]
    if not designs or not statistics:
        return []
    return [{"file": "statistics.png", "designs": designs, "statistics": statistics}]


def _series(study, summary, design, statistic):
    """(x, medians, minima, maxima, members) along one design, complete points only."""
    rows = []
    for point_id, stats in summary["points"].items():
        entry = stats.get(statistic)
        if entry is None or not entry["complete"] or design["name"] not in _designs_of(summary, point_id):
            continue
        rows.append((_value(summary, point_id, design["x"]), entry))
    rows.sort(key=lambda r: r[0])
    return ([r[0] for r in rows], [r[1]["median"] for r in rows], [r[1]["min"] for r in rows],
            [r[1]["max"] for r in rows], [r[1]["values"] for r in rows])


def _designs_of(summary, point_id):
    for row in summary["runs"]:
        if row["point_id"] == point_id:
            return row["designs"].split(" ")
    return []


def _value(summary, point_id, parameter):
    for row in summary["runs"]:
        if row["point_id"] == point_id:
            return row[parameter]
    raise KeyError(point_id)


def draw(study, summary, plot, directory):
    """Draws one plot of the study into directory/plot['file']; returns the path."""
    plt = _pyplot()
    statistics = plot["statistics"]
    columns = 1 if len(statistics) == 1 else 2
    rows = math.ceil(len(statistics) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(6 * columns, 4.25 * rows), squeeze=False)
    designs = [study.design(name) for name in plot["designs"]]
    xs = [x for d in designs for x in _series(study, summary, d, statistics[0])[0]]
    span = (max(xs) - min(xs)) if xs else 1.0
    reductions = {r["name"]: r for r in study.reductions}
    fields = study_fields(study, plot)
    for ax, statistic in zip(axes.flat, statistics):
        for k, design in enumerate(designs):
            x, med, low, high, values = _series(study, summary, design, statistic)
            if not x:
                continue
            colour = COLOURS[k % len(COLOURS)]
            shifted = np.asarray(x) + (k - (len(designs) - 1) / 2) * SHIFT_SHARE * span
            med = np.asarray(med)
            ax.errorbar(shifted, med, yerr=[med - np.asarray(low), np.asarray(high) - med], color=colour,
                        marker="o", capsize=3, linewidth=1.2,
                        label=design.get("label", design["name"]) + " (median, min-max)")
            for xi, v in zip(shifted, values):
                ax.plot(np.full(len(v), xi), v, ".", color=colour, markersize=3, alpha=0.5)
        r = reductions[statistic]
        unit = " [%s]" % r["unit"] if "unit" in r else ""
        ax.set_ylabel(fill(r.get("label", statistic), fields) + unit)
        ax.set_xlabel(fill(plot.get("x_label", designs[0]["x"]), fields))
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[len(statistics):]:
        ax.set_visible(False)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle(plot_title(plot, fields), fontsize=10)
    fig.tight_layout()
    os.makedirs(directory, exist_ok=True)
    path = os.path.join(directory, plot["file"])
    partial = path + ".partial.png"
    fig.savefig(partial, dpi=110)
    plt.close(fig)
    os.replace(partial, path)
    return path


def figure_directory(study, plot, directory=None):
    """Where a plot is drawn: `directory` when given (`study plot --out`), else the plot's own
    `directory` (relative to the study file), else STORE/figures: beside the store, which the
    study owns, never into a folder of the repository or of the user unless the study says so."""
    if directory:
        return directory
    if "directory" in plot:
        return study.resolve(plot["directory"])
    return os.path.join(study.store_path, "figures")


def draw_all(study, summary, directory=None):
    """Every plot the study file lists (or the default one), each into figure_directory; returns
    the paths written."""
    return [draw(study, summary, plot, figure_directory(study, plot, directory)) for plot in plots_of(study)]
