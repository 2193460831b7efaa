# SPDX-License-Identifier: BSD-3-Clause
"""The summary tables of a study, derived from the store (never edited by hand):

    summary/runs.csv     one row per (point, member): engine, parameters, run id, reductions, wall time
    summary/points.csv   one row per point and reduction: engine, members stored, median, quartiles, range
    summary/trends.csv   per design with an x parameter, neighbouring points along x and first
                         against last: P(upper > lower) and the one-sided Mann-Whitney p-value
    summary/summary.json all of it, as strict JSON (no NaN or Infinity)

A value that is absent is left out: a run not stored yet has no reductions in its row (an empty
cell in runs.csv), a point without stored members no statistics. A stored reduction that is not a
finite number (only runs stored before reductions had to be finite can hold one) counts as
absent: null in summary.json, an empty cell in runs.csv, not in the statistics. A run file that
does not match its checksum is not read; it is listed under "unreadable_runs".
"""
import csv
import io
import math

from .expand import member_offsets
from .stats import p_value_greater, point_statistics, probability_greater
from .store import CorruptRun


def _csv(rows, columns):
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=columns, extrasaction="ignore", lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in row.items()})
    return out.getvalue()


def _finite_or_none(value):
    return value if math.isfinite(value) else None


def collect(study, store, points, membership):
    """Per point: its members' reductions as stored ({member: {reduction: value}}), complete or
    not; the rows of runs.csv; and the stored runs that could not be read ({run id: why})."""
    stored = store.stored_ids()
    members = {}
    rows = []
    unreadable = {}
    for point in points:
        members[point.point_id] = {}
        for k in member_offsets(point.members):
            run_id = membership[(point.point_id, k)]
            row = {"point_id": point.point_id, "designs": " ".join(point.designs), "member": k, "run_id": run_id,
                   "engine": point.engine}
            row.update(dict(point.values))
            if run_id in stored and run_id not in unreadable:
                try:
                    run = store.read(run_id, series=False)
                except CorruptRun as error:
                    unreadable[run_id] = str(error)
                    rows.append(row)
                    continue
                reductions = {name: _finite_or_none(value) for name, value in run["reductions"].items()}
                members[point.point_id][k] = reductions
                row.update(reductions)
                row.update({"wall_seconds": run["attrs"]["wall_seconds"], "host": run["attrs"]["host"],
                            "library_version": run["attrs"]["library_version"]})
            rows.append(row)
    return members, rows, unreadable


def trends(study, points, statistics):
    """Rank tests between neighbouring points along each design's x, and first against last."""
    by_id = {p.point_id: p for p in points}
    out = []
    for design in study.spec["designs"]:
        if "x" not in design:
            continue
        line = sorted((p for p in points if design["name"] in p.designs), key=lambda p: p.value(design["x"]))
        pairs = list(zip(line, line[1:]))
        if len(line) > 2:
            pairs.append((line[0], line[-1]))
        for lower, upper in pairs:
            for name in statistics.get(lower.point_id, {}):
                a = statistics[lower.point_id][name].get("values")
                b = statistics.get(upper.point_id, {}).get(name, {}).get("values")
                if not a or not b or len(a) < by_id[lower.point_id].members or len(b) < by_id[upper.point_id].members:
                    continue
                out.append({"design": design["name"], "statistic": name, "x": design["x"],
                            "lower": lower.value(design["x"]), "upper": upper.value(design["x"]),
                            "lower_point": lower.point_id, "upper_point": upper.point_id,
                            "probability_greater": probability_greater(a, b),
                            "p_value_greater": p_value_greater(a, b)})
    return out


def summarise(study, store, points, membership):
    """Writes the summary tables; returns the summary as a dict."""
    members, rows, unreadable = collect(study, store, points, membership)
    names = [r["name"] for r in study.reductions]
    statistics = {}
    point_rows = []
    for point in points:
        stored = members[point.point_id]
        statistics[point.point_id] = {}
        for name in names:
            values = [stored[k][name] for k in sorted(stored) if stored[k].get(name) is not None]
            if not values:
                continue
            entry = point_statistics(values)
            entry["values"] = values
            entry["complete"] = len(values) == point.members
            statistics[point.point_id][name] = entry
            row = {"point_id": point.point_id, "designs": " ".join(point.designs), "statistic": name,
                   "members": point.members, "engine": point.engine}
            row.update(dict(point.values))
            row.update({k: v for k, v in entry.items() if k != "values"})
            point_rows.append(row)
    trend_rows = trends(study, points, statistics)
    parameters = list(study.parameters)
    store.write_summary_file("runs.csv", _csv(rows, ["point_id", "designs", "member", "run_id", "engine"] + parameters
                                              + names + ["wall_seconds", "host", "library_version"]))
    store.write_summary_file("points.csv", _csv(point_rows, ["point_id", "designs", "engine"] + parameters + [
        "statistic", "members", "n", "complete", "median", "q1", "q3", "min", "max"]))
    store.write_summary_file("trends.csv", _csv(trend_rows, [
        "design", "statistic", "x", "lower", "upper", "probability_greater", "p_value_greater"]))
    summary = {"study": study.name, "runs": rows, "points": statistics, "trends": trend_rows,
               "designs": {d["name"]: d for d in study.spec["designs"]},
               "stored_runs": len({r["run_id"] for r in rows if "wall_seconds" in r}),
               "runs_in_study": len({r["run_id"] for r in rows}),
               "unreadable_runs": unreadable}
    store.write_summary_file("summary.json", summary)
    return summary
