# SPDX-License-Identifier: BSD-3-Clause
"""What can be checked in a study's runs before the first one starts: each reduction's window
against the runs' end times, and the kept time series' resolution against their length. Without
these checks such a study runs every simulation and then fails them all."""
from .study_file import StudyError

# The most samples a kept time series may ask for per table: (end_time - start_time) /
# resolution. The grid of wanted times is built whole, and the command line refuses more than
# 1e7 report rows per run for the same reason (docs/dynamics.md).
MAX_SERIES_SAMPLES = 1e7


def _span(model):
    """(start_time, end_time) of a model's solver, or None when the model does not say (the model
    reader then reports it, naming the field)."""
    solver = model.get("solver") if isinstance(model, dict) else None
    if not isinstance(solver, dict):
        return None
    start, end = solver.get("start_time", 0.0), solver.get("end_time")
    numbers = all(isinstance(t, (int, float)) and not isinstance(t, bool) for t in (start, end))
    return (float(start), float(end)) if numbers else None


def check_engines(study):
    """Raises StudyError naming the field when the study or a design names an engine this build
    of clearjoint cannot run (the Simbody adapter is optional: clearjoint._core.engines())."""
    from .. import _core
    available = _core.engines()
    named = [("engine", study.spec["engine"])] if "engine" in study.spec else []
    named += [("designs[%d].engine" % i, d["engine"]) for i, d in enumerate(study.spec["designs"]) if "engine" in d]
    for where, engine in named:
        if engine not in available:
            raise StudyError("%s: %s = %r: this build of clearjoint has no such engine (engines: %s)" % (
                study.path, where, engine, ", ".join(available)))


def check_runs(study, runs):
    """Raises StudyError naming the field when an engine is not in this build, when a reduction's
    `after` is not before a run's end, or when the time series' resolution would ask for more
    than MAX_SERIES_SAMPLES samples."""
    check_engines(study)
    resolution = study.spec["outputs"].get("time_series", {}).get("resolution")
    seen = set()
    for run in runs:
        span = _span(run.model)
        if span is None or span in seen:
            continue
        seen.add(span)
        start, end = span
        for i, reduction in enumerate(study.reductions):
            # A share of the run ("50%") is below 100 % (study_file checks it): always before the end.
            if "after" in reduction and not isinstance(reduction["after"], str) and not reduction["after"] < end:
                raise StudyError("%s: outputs.reductions[%d] (%r): after = %g s is not before the end of the run "
                                 "at point %s (solver.end_time = %g s): no sample would be left" % (
                                     study.path, i, reduction["name"], reduction["after"], run.point_id, end))
        if resolution is not None and (end - start) / resolution > MAX_SERIES_SAMPLES:
            raise StudyError("%s: outputs.time_series.resolution = %g s: %.3g samples over the %g s of the run at "
                             "point %s, more than %g; give a coarser resolution, or null to keep every reported "
                             "sample" % (study.path, resolution, (end - start) / resolution, end - start,
                                         run.point_id, MAX_SERIES_SAMPLES))
