# SPDX-License-Identifier: BSD-3-Clause
"""One figure per clearance joint, assembled from panels.py, and the files ``clearjoint plot``
writes. Orbits on top (both journal base centres for a spatial joint, Fig. 14), then the time
panels sharing their x axis (time, or the crank angle)."""
from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import panels as draw
from .joint_series import ClearanceJointSeries, joint_series, rotation_angle, window_rows
from .result_manifest import register_written
from .run_folder import Run, RunError, read_run
from .scenario_colours import JOURNAL_BEARING, PIN_IN_HOLE

#: Panels in the order they are drawn; ``panels=`` picks among them.
#: The legend's title by joint geometry: the paper's Fig. 2 cases, or the pin-in-hole table
#: (docs/contact-detection.md, "The pin-in-hole joint").
SCENARIO_LEGEND_TITLES = {JOURNAL_BEARING: "contact scenario (Fig. 2)",
                          PIN_IN_HOLE: "contact scenario (pin in hole)"}

PANELS = ("orbit", "force", "film", "axial", "tilt", "slider")
Window = Optional[Tuple[Optional[float], Optional[float]]]


def _pyplot():
    # Imported late so that `import clearjoint.plot` stays cheap and the caller's backend choice
    # (Jupyter, or Agg set by the command line) stands.
    import matplotlib.pyplot as plt
    return plt


def is_spatial(series: ClearanceJointSeries) -> bool:
    """The journal tilts or moves along the axis at some report time (a planar joint keeps its
    axes parallel, and then both base centres draw the same orbit)."""
    return bool(np.nanmax(series.axis_angle, initial=0.0) > 0.0 or np.ptp(series.axial_position) > 0.0)


def _moving_body(run: Run, table: str) -> Optional[Tuple[str, np.ndarray]]:
    """The joint's body that is not the ground, with the joint axis in its frame (the crank)."""
    joint = run.joint_model(table)
    if joint is None:
        return None
    for body, axis in ((joint.bearing_body, joint.bearing_axis), (joint.journal_body, joint.journal_axis)):
        if body != "ground" and "body_" + body in run.tables:
            return body, axis
    return None


def _abscissa(run: Run, table: str, x: str, window: Window) -> Tuple[np.ndarray, str]:
    if x == "time":
        time = run.column(table, "time")
        return time[window_rows(time, window)], "time [s]"
    if x == "angle":
        moving = _moving_body(run, table)
        if moving is None:
            raise RunError(f"{run.source}: the crank angle needs the model and the table of the "
                           "joint's moving body (pass the model; output.bodies must list it)")
        return np.degrees(rotation_angle(run, moving[0], moving[1], window)), f"{moving[0]} angle [deg]"
    raise ValueError(f"x = {x!r}: must be 'time' or 'angle'")


def _slider_axis(run: Run, body: str) -> Tuple[np.ndarray, str]:
    """The direction the slider runs in: the axis of its translational joint to the ground
    (world frame), else x."""
    for joint in (run.model or {}).get("joints", []):
        if joint.get("type") != "translational":
            continue
        if joint.get("body_i") == "ground" and joint.get("body_j") == body and "axis_i" in joint:
            axis = np.asarray(joint["axis_i"], dtype=float)
            axis = axis / np.linalg.norm(axis)
            names = {(1.0, 0.0, 0.0): "x", (0.0, 1.0, 0.0): "y", (0.0, 0.0, 1.0): "z"}
            return axis, names.get(tuple(np.abs(axis)), "along its guide")
    return np.array([1.0, 0.0, 0.0]), "x"


def slider_acceleration(run: Run, body: str, window: Window = None) -> Tuple[np.ndarray, np.ndarray, str]:
    """(time, acceleration along the guide [m/s^2], component name) of an output body."""
    time, ax, ay, az = (run.column("body_" + body, c) for c in ("time", "ax", "ay", "az"))
    keep = window_rows(time, window)
    axis, component = _slider_axis(run, body)
    acceleration = axis[0] * ax + axis[1] * ay + axis[2] * az
    return time[keep], acceleration[keep], component


def default_slider(run: Run) -> Optional[str]:
    """The body called "slider" when the run has its table (the paper's slider-cranks)."""
    return "slider" if "body_slider" in run.tables else None


def joint_figure(run: Any, joint: Optional[str] = None, *, model: Any = None, ideal: Any = None,
                 panels: Optional[Sequence[str]] = None, window: Window = None, x: str = "time",
                 slider: Optional[str] = None):
    """The figure of one clearance joint of a run, as a matplotlib Figure.

    Parameters
    ----------
    run:
        A run folder, a :class:`clearjoint.SimulationResult` (what ``clearjoint.simulate``
        returns) or a :class:`clearjoint.plot.Run`.
    joint:
        The joint's name (or its table, "force_<name>"); default: the run's only clearance joint.
    model:
        The run's model file or dict: gives the clearances (orbits in units of c_r, the +-c_a
        lines), the crank and the slider's guide. Default: ``model.json`` in the run folder.
    ideal:
        A run of the same mechanism with an ideal joint (folder or result): its slider
        acceleration is drawn beside this one's.
    panels:
        Some of ``PANELS`` ("orbit", "force", "film", "axial", "tilt", "slider"); default: all
        that apply (film for a lubricated joint, axial and tilt for a spatial joint, slider when
        the run has a body called slider).
    window:
        (start, end) in seconds, either None for an open end.
    x:
        "time" (seconds) or "angle" (the crank's rotation about the joint axis, degrees).
    slider:
        The body whose acceleration is drawn (default "slider").
    """
    plt = _pyplot()
    run = read_run(run, model)
    table = _joint_table(run, joint)
    series = joint_series(run, table, window)
    spatial = is_spatial(series)
    slider = slider or default_slider(run)
    wanted = list(panels) if panels is not None else [
        p for p in PANELS if (p not in ("axial", "tilt") or spatial) and (p != "film" or series.lubricated)]
    unknown = [p for p in wanted if p not in PANELS]
    if unknown:
        raise ValueError(f"panels: {', '.join(unknown)} unknown (choose among {', '.join(PANELS)})")
    if "film" in wanted and not series.lubricated:
        raise RunError(f"{run.source}: {table} has no film columns (a dry joint): no film panel")
    if "slider" in wanted and slider is None:
        if panels is not None:
            raise RunError(f"{run.source}: no body table body_slider.csv; name the body (slider=)")
        wanted.remove("slider")
    time_panels = [p for p in wanted if p != "orbit"]
    x_values, x_label = _abscissa(run, table, x, window)

    rows = len(time_panels) + (1 if "orbit" in wanted else 0)
    figure = plt.figure(figsize=(9.0, 0.5 + (4.2 if "orbit" in wanted else 0.0) + 2.1 * len(time_panels)),
                        constrained_layout=True)
    grid = figure.add_gridspec(max(rows, 1), 2, height_ratios=([2.0] if "orbit" in wanted else []) +
                               [1.0] * len(time_panels))
    row = 0
    if "orbit" in wanted:
        if spatial:
            draw.plot_orbit(figure.add_subplot(grid[0, 0]), series, "a")
            orbit_b = figure.add_subplot(grid[0, 1])
            draw.plot_orbit(orbit_b, series, "b")
            legend_axes = orbit_b
        else:
            legend_axes = figure.add_subplot(grid[0, 0])
            draw.plot_orbit(legend_axes, series, "a", title="journal centre")
        legend_axes.legend(handles=draw.scenario_legend_handles(series.scenario, geometry=series.geometry),
                           fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                           title=SCENARIO_LEGEND_TITLES.get(series.geometry,
                                                            SCENARIO_LEGEND_TITLES[JOURNAL_BEARING]),
                           title_fontsize=8)
        row = 1
    shared = None
    for panel in time_panels:
        ax = figure.add_subplot(grid[row, :], sharex=shared)
        shared = shared or ax
        row += 1
        if panel == "force":
            draw.plot_normal_force(ax, series, x_values, x_label)
        elif panel == "film":
            draw.plot_film_thickness(ax, series, x_values, x_label)
        elif panel == "axial":
            draw.plot_axial_position(ax, series, x_values, x_label)
        elif panel == "tilt":
            draw.plot_tilt(ax, series, x_values, x_label)
        elif panel == "slider":
            _draw_slider(ax, run, table, slider, ideal, x, window, x_values, x_label)
    if "orbit" not in wanted and time_panels:
        figure.axes[0].legend(handles=draw.scenario_legend_handles(series.scenario, geometry=series.geometry),
                              fontsize=7,
                              loc="upper right", ncol=2)
    # Tick labels and the x label on the bottom time panel only: the panels share their axis.
    time_axes = figure.axes[-len(time_panels):] if time_panels else []
    for ax in time_axes[:-1]:
        ax.set_xlabel("")
        ax.tick_params(labelbottom=False)
    name = series.joint.name if series.joint is not None else series.name
    where = "" if series.radial_clearance else " (model unknown: lengths in m)"
    figure.suptitle(f"clearance joint '{name}'{where}", fontsize=11)
    return figure


def _draw_slider(ax, run: Run, table: str, slider: str, ideal: Any, x: str, window: Window,
                 x_values: np.ndarray, x_label: str) -> None:
    _, acceleration, component = slider_acceleration(run, slider, window)
    ideal_x = ideal_acceleration = None
    if ideal is not None:
        ideal_run = read_run(ideal, run.model if not isinstance(ideal, Run) else None)
        ideal_time, ideal_acceleration, _ = slider_acceleration(ideal_run, slider, window)
        ideal_x = ideal_time
        if x == "angle":
            moving = _moving_body(run, table)
            ideal_x = np.degrees(rotation_angle(ideal_run, moving[0], moving[1], window))
    draw.plot_slider_acceleration(ax, x_values, acceleration, x_label, ideal_x, ideal_acceleration,
                                  component)


def _joint_table(run: Run, joint: Optional[str]) -> str:
    tables = run.clearance_tables()
    if not tables:
        raise RunError(f"{run.source}: no clearance joint in this run (no force_<joint>.csv with a "
                       "scenario column): nothing to draw")
    if joint is None:
        if len(tables) > 1:
            raise RunError(f"{run.source}: {len(tables)} clearance joints ({', '.join(tables)}): "
                           "name one")
        return tables[0]
    for candidate in (joint, "force_" + joint):
        if candidate in tables:
            return candidate
    named = [j.table for j in run.clearance_joints if j.name == joint]
    if named and named[0] in tables:
        return named[0]
    raise RunError(f"{run.source}: no clearance joint {joint!r} (joints: "
                   f"{', '.join(t[len('force_'):] for t in tables)})")


def joint_figures(run: Any, *, model: Any = None, **options) -> Dict[str, Any]:
    """Every clearance joint's figure, by table name ("force_<name>"); options as joint_figure."""
    run = read_run(run, model)
    return {table: joint_figure(run, table, **options) for table in _clearance_tables_or_fail(run)}


def _clearance_tables_or_fail(run: Run) -> List[str]:
    tables = run.clearance_tables()
    if not tables:
        _joint_table(run, None)  # raises the one message for a run without clearance joints
    return tables


def save_joint_figures(run: Any, out_dir: Any = None, *, model: Any = None, joint: Optional[str] = None,
                       formats: Sequence[str] = ("png", "svg"), dpi: int = 150, **options) -> List[str]:
    """Write every clearance joint's figure (or only ``joint``'s) as ``joint_<name>.<format>``
    into ``out_dir`` (default: ``figures/`` in the run folder) and return the paths written.
    Options as joint_figure. This is what ``clearjoint plot`` and ``clearjoint simulate --plot``
    call."""
    plt = _pyplot()
    run = read_run(run, model)
    if out_dir is None:
        if not os.path.isdir(run.source):
            raise ValueError("out_dir: needed when the run is not a folder")
        out_dir = os.path.join(run.source, "figures")
    os.makedirs(out_dir, exist_ok=True)
    written = []
    tables = [_joint_table(run, joint)] if joint is not None else _clearance_tables_or_fail(run)
    for table in tables:
        figure = joint_figure(run, table, **options)
        for extension in formats:
            path = os.path.join(os.fspath(out_dir), f"joint_{table[len('force_'):]}.{extension}")
            figure.savefig(path, dpi=dpi)
            written.append(path)
        plt.close(figure)
    if os.path.isdir(run.source):
        register_written(run.source, written)  # so that `simulate --force` replaces them too
    return written
