# SPDX-License-Identifier: BSD-3-Clause
"""A run's reduced outputs, computed on the worker from the simulation's tables so that only
scalars and the kept time series travel back.

Tables are named as the files of ``clearjoint simulate``: body_<name>, energy, reactions,
force_<name>; each is a mapping column -> 1-d array sharing the column "time".

NaN in a column means "no value at this sample" (a contact slot's columns where the slot has no
contact), so peak_abs, percentile_abs and rms skip NaN samples; a reduction left with no sample is
an error naming the column, and so is any reduction whose value is not a finite number: a stored
NaN would make every run succeed, the plot blank and the summary invalid JSON.
"""
import fnmatch

import numpy as np


class ReductionError(ValueError):
    """A reduction or time series asks for a table or column the run does not have."""


def table(tables, name, purpose):
    if name not in tables:
        raise ReductionError("%s: the run has no table %r (tables: %s); name it in the model's output" % (
            purpose, name, ", ".join(sorted(tables))))
    return tables[name]


def column(tables, table_name, column_name, purpose):
    t = table(tables, table_name, purpose)
    if column_name not in t:
        raise ReductionError("%s: table %r has no column %r (columns: %s)" % (
            purpose, table_name, column_name, ", ".join(t)))
    return np.asarray(t[column_name], dtype=float)


def parse_share(after):
    """A reduction's `after` given as a share of the run ("50%"): the share as a fraction in
    [0, 1), else None (`after` in seconds). The form is checked by the study schema and by
    study_file."""
    if isinstance(after, str) and after.endswith("%"):
        return float(after[:-1]) / 100.0
    return None


def after_seconds(after, time):
    """The time [s] a reduction's window starts at: `after` itself when given in seconds, else
    the share of the simulated time from the run's first report (solver.start_time) to its last
    (solver.end_time), so that a shorter or longer run keeps the same part of its motion."""
    share = parse_share(after)
    if share is None:
        return float(after)
    return float(time[0] + share * (time[-1] - time[0]))


def _after_text(after, seconds):
    return "t = %g s" % seconds if parse_share(after) is None else "t = %g s (%s of the run)" % (seconds, after)


def _after(tables, spec, values):
    """The samples with time > spec['after'] (all samples when it is absent)."""
    if "after" not in spec:
        return values
    time = column(tables, spec["table"], "time", "reduction %r" % spec["name"])
    after = after_seconds(spec["after"], time)
    kept = values[time > after]
    if kept.size == 0:
        raise ReductionError("reduction %r: no sample after %s (the run ends at %g s)" % (
            spec["name"], _after_text(spec["after"], after), time[-1]))
    return kept


def _contact_depths(tables, spec):
    """The depth columns (one per contact slot) of a clearance joint's table; NaN where the slot
    has no contact."""
    t = table(tables, spec["table"], "reduction %r" % spec["name"])
    names = [c for c in t if c.endswith(".depth")]
    if not names:
        raise ReductionError("reduction %r: table %r has no <slot>.depth columns (a clearance joint's "
                             "table has them)" % (spec["name"], spec["table"]))
    depths = np.column_stack([np.asarray(t[c], dtype=float) for c in names])
    if "after" in spec:
        time = np.asarray(t["time"], dtype=float)
        depths = depths[time > after_seconds(spec["after"], time)]
    return depths


def reduce_one(tables, spec):
    """One reduction of one run (units those of the column; impacts are a count)."""
    quantity, purpose = spec["quantity"], "reduction %r" % spec["name"]
    if quantity == "energy_loss":  # mechanical energy at the first sample minus at the last [J]
        total = column(tables, "energy", "total", purpose)
        return float(total[0] - total[-1])
    if quantity in ("impacts", "max_depth"):
        depths = _contact_depths(tables, spec)
        in_contact = np.isfinite(depths)
        if quantity == "max_depth":
            return float(np.nanmax(depths)) if in_contact.any() else 0.0
        # Contact onsets seen at the report times, summed over the slots: a slot without contact
        # at one report and with contact at the next. Impacts shorter than the report step can
        # be missed; the joint's own count (every accepted step) is in the simulation's summary.
        onsets = in_contact[1:] & ~in_contact[:-1]
        return float(onsets.sum() + in_contact[0].sum())
    values = _after(tables, spec, column(tables, spec["table"], spec["column"], purpose))
    values = values[~np.isnan(values)]
    if values.size == 0:
        raise ReductionError("%s: column %r of table %r is NaN at every sample%s (no value there: a contact "
                             "slot without contact, say); max_depth and impacts count a joint's contacts" % (
                                 purpose, spec["column"], spec["table"],
                                 " after %s" % _after_text(spec["after"], after_seconds(
                                     spec["after"], column(tables, spec["table"], "time", purpose)))
                                 if "after" in spec else ""))
    if quantity == "peak_abs":
        return float(np.abs(values).max())
    if quantity == "percentile_abs":
        return float(np.percentile(np.abs(values), spec["percentile"]))
    if quantity == "rms":
        return float(np.sqrt(np.mean(values * values)))
    raise ReductionError("%s: unknown quantity %r" % (purpose, quantity))


def sample_indices(time, resolution):
    """The reported samples nearest to t0, t0 + resolution, ...: samples as computed, never
    interpolated."""
    if resolution is None:
        return np.arange(len(time))
    grid = np.arange(time[0], time[-1] + 0.5 * resolution, resolution)
    right = np.clip(np.searchsorted(time, grid), 1, len(time) - 1)
    nearer_left = (grid - time[right - 1]) <= (time[right] - grid)
    return np.unique(np.where(nearer_left, right - 1, right))


def time_series(tables, spec):
    """{table: {column: array}} for the tables and columns the study keeps, time included."""
    kept = {}
    for pattern, columns in spec["tables"].items():
        if any(ch in pattern for ch in "*?["):
            names = [n for n in sorted(tables) if fnmatch.fnmatchcase(n, pattern)]
        else:
            table(tables, pattern, "time_series")
            names = [pattern]
        for name in names:
            time = column(tables, name, "time", "time_series")
            index = sample_indices(time, spec.get("resolution"))
            wanted = ["time"] + [c for c in columns if c != "time"]
            kept[name] = {c: column(tables, name, c, "time_series")[index] for c in wanted}
    return kept


def reduce_run(tables, outputs):
    reductions = {}
    for spec in outputs.get("reductions", []):
        value = reduce_one(tables, spec)
        if not np.isfinite(value):
            raise ReductionError("reduction %r: the value is %r, not a finite number (a column of the run is "
                                 "not finite)" % (spec["name"], value))
        reductions[spec["name"]] = value
    series = time_series(tables, outputs["time_series"]) if "time_series" in outputs else {}
    return reductions, series
