# SPDX-License-Identifier: BSD-3-Clause
"""Runs overlaid in one figure (``clearjoint plot RUN RUN ... --out FIG``, docs/viewing-runs.md,
"Comparing runs"): any engine, any format, one colour and one legend entry per run.

Panels, top to bottom, each drawn when at least one run has what it needs (otherwise left out,
and the figure's notes say why):

- the journal orbit in clearance units (the clearance circle is the unit circle, Fig. 14);
- the joint's whole force |(fx, fy, fz)| [N]: contact and, for a lubricated joint, film;
- for lubricated runs: the film force, h_min [µm], the eccentricity ratio and the peak pressure;
- the slider's acceleration, beside an ideal run's (dashed) when one is given;
- the total mechanical energy [J].

The runs must share a clearance joint (a table ``force_<name>`` in each); the time window is
the span they share, past its first ``TRANSIENT_SHARE`` unless given.
"""
from __future__ import annotations

import os
import textwrap
from dataclasses import dataclass, field
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

from .figures import default_slider, slider_acceleration
from .joint_series import ClearanceJointSeries, joint_series
from .panels import IDEAL_CURVE, MICROMETRES_PER_METRE
from .run_folder import Run, RunError, read_run

Window = Optional[Tuple[Optional[float], Optional[float]]]

#: The automatic window leaves out this share of the runs' common time span. A journal that starts
#: centred in its bearing meets the wall within the first milliseconds, and that first impact is
#: the largest force of the run by an order of magnitude (the planar slider-crank of Sec. 6.1:
#: 9.7 kN in the first 10 ms, at most 0.8 kN after): drawn with the rest, it flattens every other
#: curve. For the shipped 1 s models the share is 0.1 s, where the Sec. 6 figures'
#: windows begin (reproduction/section6_figures.py, reproduction/lubricated_section6.py).
TRANSIENT_SHARE = 0.1
#: Pressures are drawn in MPa (a film's peak pressure is 1e5 to 1e8 Pa).
PASCALS_PER_MEGAPASCAL = 1e6
#: The notes under the figure are wrapped at this many characters: the width of the 9-inch
#: figure in its 7-point note font, less the left margin.
NOTE_WIDTH = 150
#: Colours of the runs, in order (matplotlib's default cycle, without the grey kept for ideal runs).
RUN_COLOURS = ("tab:blue", "tab:red", "tab:green", "tab:orange", "tab:purple", "tab:brown",
               "tab:pink", "tab:olive", "tab:cyan")
#: Line styles of the runs, in order: two engines' runs of one model lie on top of each other,
#: and a dashed curve over a solid one shows both.
RUN_STYLES = ("-", (0, (5, 2)), (0, (1, 1.5)), "-.")


@dataclass
class Comparison:
    """What ``compare`` drew: the figure, the window [s], the joint's table, and the notes on
    panels or curves left out (also printed by ``clearjoint plot``)."""

    figure: Any
    window: Tuple[float, float]
    table: str
    notes: List[str] = field(default_factory=list)


def _label(run: Run, index: int) -> str:
    if os.path.isdir(run.source):
        return os.path.basename(os.path.normpath(run.source))
    return f"run {index + 1}"


def _time_span(run: Run) -> Tuple[float, float]:
    starts, ends = [], []
    for columns in run.tables.values():
        time = columns.get("time")
        if time is not None and len(time):
            starts.append(float(time[0]))
            ends.append(float(time[-1]))
    if not starts:
        raise RunError(f"{run.source}: no table with a time column")
    return min(starts), max(ends)


def common_joint(runs: Sequence[Run], labels: Sequence[str], joint: Optional[str] = None) -> str:
    """The clearance joint's table every run has ("force_<name>"); RunError naming the runs and
    what each has when there is none (or, with several, when ``joint`` does not pick one)."""
    have = [set(run.clearance_tables()) for run in runs]
    shared = sorted(set.intersection(*have))
    if joint is not None:
        wanted = joint if joint.startswith("force_") else "force_" + joint
        missing = [label for label, tables in zip(labels, have) if wanted not in tables]
        if missing:
            raise RunError(f"joint {joint!r}: not a clearance joint of {', '.join(missing)} (shared: "
                           f"{', '.join(t[len('force_'):] for t in shared) or 'none'})")
        return wanted
    if not shared:
        each = "; ".join(f"{label}: {', '.join(t[len('force_'):] for t in sorted(tables)) or 'none'}"
                         for label, tables in zip(labels, have))
        raise RunError(f"runs {', '.join(labels)} have no clearance joint of the same name to compare "
                       f"(clearance joints: {each})")
    if len(shared) > 1:
        raise RunError(f"runs {', '.join(labels)} share {len(shared)} clearance joints "
                       f"({', '.join(t[len('force_'):] for t in shared)}): name one (--joint)")
    return shared[0]


def comparison_window(runs: Sequence[Run], labels: Sequence[str], window: Window = None) -> Tuple[float, float]:
    """(start, end) [s]: ``window``'s ends where given, else the span all runs cover, without its
    first TRANSIENT_SHARE (start) or to its end (end)."""
    spans = [_time_span(run) for run in runs]
    start, end = max(s for s, _ in spans), min(e for _, e in spans)
    if start > end:
        raise RunError(f"runs {', '.join(labels)} share no time span ("
                       + "; ".join(f"{label}: {s:g} s to {e:g} s" for label, (s, e) in zip(labels, spans)) + ")")
    given_start, given_end = window if window is not None else (None, None)
    chosen = (start + TRANSIENT_SHARE * (end - start) if given_start is None else float(given_start),
              end if given_end is None else float(given_end))
    if not chosen[0] < chosen[1] and not (chosen[0] == chosen[1] == start):
        raise RunError(f"the time window [{chosen[0]:g}, {chosen[1]:g}] s is empty")
    return chosen


def _film_panels(series: Sequence[ClearanceJointSeries]):
    """(key, y label, values of a series or None) for the film panels."""
    def film(name, scale=1.0):
        return lambda s: None if s.film is None or name not in s.film else s.film[name] * scale
    return [
        ("film force", "film force [N]", lambda s: s.film_force),
        ("h_min", "h_min [µm]", film("min_thickness", MICROMETRES_PER_METRE)),
        ("eccentricity", "eccentricity ratio ε [-]", film("eccentricity_ratio")),
        ("peak pressure", "peak pressure [MPa]", film("max_pressure", 1.0 / PASCALS_PER_MEGAPASCAL)),
    ]


def compare(runs: Sequence[Any], labels: Optional[Sequence[str]] = None, out: Any = None, *,
            window: Window = None, ideal: Any = None, joint: Optional[str] = None,
            models: Optional[Sequence[Any]] = None, slider: Optional[str] = None,
            dpi: int = 150) -> Comparison:
    """Overlay ``runs`` (run folders of any engine and format, SimulationResults, or Runs) in one
    figure, one colour per run, named by ``labels`` (default: the folders' names).

    ``window``: (start, end) [s], either None for the automatic end (module docstring);
    ``ideal``: a run of the same mechanism with ideal joints, its slider acceleration dashed;
    ``joint``: the clearance joint's name when the runs share several; ``models``: one model
    (file or dict) per run, for runs whose folder has no model.json; ``out``: a file to save
    the figure to (its extension chooses the format). Returns a :class:`Comparison`.
    """
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    if isinstance(runs, (str, os.PathLike)) or len(runs) == 0:
        raise ValueError("runs: a list of at least one run (folders, SimulationResults or Runs)")
    if models is not None and len(models) != len(runs):
        raise ValueError(f"models: {len(models)} given for {len(runs)} runs (one per run, None for its own)")
    loaded = [read_run(run, models[k] if models is not None else None) for k, run in enumerate(runs)]
    if labels is None:
        labels = [_label(run, k) for k, run in enumerate(loaded)]
    labels = list(labels)
    if len(labels) != len(loaded):
        raise ValueError(f"labels: {len(labels)} given for {len(loaded)} runs (one per run)")
    table = common_joint(loaded, labels, joint)
    start, end = comparison_window(loaded, labels, window)
    series = [joint_series(run, table, (start, end)) for run in loaded]
    colours = [dict(color=RUN_COLOURS[k % len(RUN_COLOURS)], linestyle=RUN_STYLES[k % len(RUN_STYLES)])
               for k in range(len(loaded))]
    notes: List[str] = []

    # Each time panel: (y label, [(x, y, colour) per run that has it]).
    time_panels = []
    time_panels.append(("joint force |F| [N]",
                        [(s.time, s.total_force, c) for s, c in zip(series, colours) if s.total_force is not None]))
    if any(s.lubricated for s in series):
        dry = [label for label, s in zip(labels, series) if not s.lubricated]
        if dry:
            notes.append(f"film panels: no film in {', '.join(dry)} (a dry joint)")
        for _, y_label, values in _film_panels(series):
            time_panels.append((y_label, [(s.time, values(s), c) for s, c in zip(series, colours)
                                          if values(s) is not None]))
    slider = slider or next((b for b in map(default_slider, loaded) if b), None)
    ideal_run = None
    component = "x"
    if slider is not None:
        curves = []
        for label, run, colour in zip(labels, loaded, colours):
            if "body_" + slider in run.tables:
                t, a, component = slider_acceleration(run, slider, (start, end))
                curves.append((t, a, colour))
            else:
                notes.append(f"slider acceleration: {label} has no table body_{slider}")
        if ideal is not None:
            ideal_run = read_run(ideal, None)
            t, a, component = slider_acceleration(ideal_run, slider, (start, end))
            curves.insert(0, (t, a, None))
        time_panels.append((f"slider acceleration {component} [m/s²]", curves))
    else:
        notes.append("slider acceleration: no run has a body table body_slider")
    energy = [(run.column("energy", "time"), run.column("energy", "total"), c)
              for run, c in zip(loaded, colours) if "energy" in run.tables]
    without_energy = [label for label, run in zip(labels, loaded) if "energy" not in run.tables]
    if without_energy:
        notes.append(f"energy: no energy table in {', '.join(without_energy)}")
    if energy:
        keep = [(t[(t >= start) & (t <= end)], e[(t >= start) & (t <= end)], c) for t, e, c in energy]
        time_panels.append(("total energy [J]", keep))
    time_panels = [(y_label, curves) for y_label, curves in time_panels if curves]

    clearance_units = all(s.radial_clearance for s in series)
    if not clearance_units:
        notes.append("orbit in metres: " + ", ".join(label for label, s in zip(labels, series)
                                                      if not s.radial_clearance)
                     + " without a model (its clearance unknown)")
    figure = plt.figure(figsize=(9.0, 5.0 + 1.9 * len(time_panels)), constrained_layout=True)
    grid = figure.add_gridspec(1 + len(time_panels), 1, height_ratios=[3.2] + [1.0] * len(time_panels))
    orbit = figure.add_subplot(grid[0, 0])
    if clearance_units:
        angle = np.linspace(0.0, 2.0 * np.pi, 361)
        orbit.plot(np.cos(angle), np.sin(angle), color="0.4", linewidth=0.8, zorder=0)
    for s, colour in zip(series, colours):
        scale = 1.0 / s.radial_clearance if clearance_units else 1.0
        orbit.plot(s.rim_a[:, 0] * scale, s.rim_a[:, 1] * scale, linewidth=0.7, alpha=0.85, **colour)
    unit = "/ c_r [-]" if clearance_units else "[m]"
    orbit.set_xlabel(f"u {unit}")
    orbit.set_ylabel(f"v {unit}")
    orbit.set_aspect("equal", adjustable="datalim")
    orbit.set_title("journal centre (base A) in the bearing frame", fontsize=10)
    orbit.grid(True, linewidth=0.3, alpha=0.5)

    shared = None
    for row, (y_label, curves) in enumerate(time_panels, start=1):
        ax = figure.add_subplot(grid[row, 0], sharex=shared)
        shared = shared or ax
        for x, y, colour in curves:
            if colour is None:
                ax.plot(x, y, **IDEAL_CURVE)
            else:
                ax.plot(x, y, linewidth=0.8, **colour)
        ax.set_ylabel(y_label, fontsize=8)
        ax.grid(True, linewidth=0.3, alpha=0.5)
        ax.set_xlabel("time [s]" if row == len(time_panels) else "")
        if row < len(time_panels):
            ax.tick_params(labelbottom=False)
    if shared is not None:
        shared.set_xlim(start, end)

    handles = [Line2D([], [], linewidth=1.5, label=label, **c) for label, c in zip(labels, colours)]
    if ideal_run is not None:
        handles.append(Line2D([], [], label="ideal joint", **IDEAL_CURVE))
    orbit.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.04, 1.0), borderaxespad=0.0,
                 fontsize=9, title="runs", title_fontsize=9)
    name = table[len("force_"):]
    figure.suptitle(f"clearance joint '{name}', {start:g} s to {end:g} s", fontsize=11)
    if notes:
        # A figure-level x label, not free text: constrained layout keeps room for it below the
        # last axis, so the notes never cover the time axis's label.
        figure.supxlabel("\n".join(textwrap.wrap("; ".join(notes), NOTE_WIDTH)), x=0.01, ha="left",
                         fontsize=7, color="0.3")
    if out is not None:
        _save(figure, out, dpi)
    return Comparison(figure=figure, window=(start, end), table=table, notes=notes)


def _save(figure: Any, out: Any, dpi: int) -> None:
    path = os.fspath(out)
    extension = os.path.splitext(path)[1][1:].lower()
    supported = figure.canvas.get_supported_filetypes()
    if extension not in supported:
        raise ValueError(f"out = {path!r}: the file's extension chooses the format; one of "
                         f"{', '.join('.' + e for e in sorted(supported))}")
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise ValueError(f"out = {path!r}: no such folder {directory}")
    figure.savefig(path, dpi=dpi)
