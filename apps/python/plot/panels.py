# SPDX-License-Identifier: BSD-3-Clause
"""The panels of a clearance joint's figure, each drawn on a matplotlib Axes it is given: the
journal orbit in the clearance circle, the normal force, the axial position, the tilt and the
slider's acceleration. Every curve of a joint is coloured by the contact scenario of its report
time (scenario_colours.py) and impacts are marked where they began.
"""
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from .joint_series import ClearanceJointSeries
from .scenario_colours import scenario_colour, scenario_name

#: Look of the marks where an impact began and of the ideal joint's curve.
IMPACT_MARK = dict(marker="o", facecolors="none", edgecolors="black", linewidths=0.5, s=9, alpha=0.7,
                   zorder=4)
RASTERIZE_ABOVE_STEPS = 20_000
#: A film's thickness is drawn in micrometres: the paper's clearance is 100 µm.
MICROMETRES_PER_METRE = 1e6
# On time axes an impact is a tick along the bottom edge: a mark at the force of its first report
# time (nearly zero) would hide the curve's foot.
IMPACT_TICK = dict(marker="|", color="black", markersize=5, markeredgewidth=0.6, linestyle="none",
                   alpha=0.7)
# The ideal joint's curve is drawn over the clearance joint's, which oscillates about it; the
# styles are reproduction/section6_figures.py's.
IDEAL_CURVE = dict(color="0.3", linestyle="--", linewidth=1.0, zorder=3)
CLEARANCE_CURVE = dict(color="tab:blue", linewidth=0.8)
# A lubricated joint's whole force, drawn under the scenario-coloured contact force.
TOTAL_FORCE_CURVE = dict(color="tab:blue", linewidth=1.0, alpha=0.8, zorder=1)


def _scenario_stretches(points: np.ndarray, scenario: np.ndarray, geometry: Optional[str] = None):
    """(paths, colours): one polyline per stretch of steps that arrive in the same scenario, the
    step from point k to k + 1 taking the colour of scenario[k + 1] (codes of a joint of
    ``geometry``: scenario_colours.py)."""
    arrived = np.asarray(scenario[1:], dtype=int)
    starts = np.concatenate([[0], np.flatnonzero(np.diff(arrived)) + 1])  # first step of a stretch
    ends = np.concatenate([starts[1:], [len(arrived)]])
    paths = [points[start:end + 1] for start, end in zip(starts, ends)]
    return paths, [scenario_colour(arrived[start], geometry) for start in starts]


def _scenario_segments(ax, x: np.ndarray, y: np.ndarray, scenario: np.ndarray, linewidth: float = 1.0,
                       geometry: Optional[str] = None):
    """A polyline whose step from point k to k + 1 has the colour of scenario[k + 1], the state
    the step arrived in, so that a contact shows from its first report time. Steps are grouped
    into one path per stretch of equal scenario: a run of 1e5 report times changes scenario a few
    thousand times, and one matplotlib Path per step would take seconds to build and draw."""
    from matplotlib.collections import LineCollection
    if len(x) < 2:
        ax.scatter(x, y, c=[scenario_colour(s, geometry) for s in scenario], s=4)
        return
    points = np.column_stack([x, y])
    paths, colours = _scenario_stretches(points, scenario, geometry)
    # A long run is drawn as an image inside the SVG (axes and text stay vector): 1e5 points per
    # panel as vector paths make a file that viewers render slowly.
    ax.add_collection(LineCollection(paths, colors=colours, linewidths=linewidth,
                                     rasterized=len(points) - 1 > RASTERIZE_ABOVE_STEPS))
    ax.update_datalim(points)
    ax.autoscale_view()


def scenario_legend_handles(scenarios: Sequence[int], with_impacts: bool = True,
                            geometry: Optional[str] = None) -> list:
    """Legend entries for the scenarios that occur (in code order; codes of a joint of
    ``geometry``, default the paper's), then the impact mark."""
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color=scenario_colour(code, geometry), linewidth=2.5,
                      label=scenario_name(code, geometry))
               for code in sorted(set(int(s) for s in scenarios))]
    if with_impacts:
        handles.append(Line2D([], [], linestyle="none", marker="o", markerfacecolor="none",
                              markeredgecolor="black", markersize=4,
                              label="impact began (| on time axes)"))
    return handles


def plot_orbit(ax, series: ClearanceJointSeries, rim: str = "a", title: Optional[str] = None) -> None:
    """The centre of the journal's rim facing bearing base ``rim`` ("a" or "b") in the bearing
    frame, in units of the radial clearance (the clearance circle is the unit circle, Fig. 14), or
    in metres when the model (hence cr) is not known."""
    centre = series.rim_a if rim == "a" else series.rim_b
    cr = series.radial_clearance
    scale = 1.0 / cr if cr else 1.0
    u, v = centre[:, 0] * scale, centre[:, 1] * scale
    if cr:
        angle = np.linspace(0.0, 2.0 * np.pi, 361)
        ax.plot(np.cos(angle), np.sin(angle), color="0.4", linewidth=0.8, zorder=0)
        ax.set_xlabel("u / c_r [-]")
        ax.set_ylabel("v / c_r [-]")
        ax.set_xlim(-1.15, 1.15)
        ax.set_ylim(-1.15, 1.15)
    else:
        ax.set_xlabel("u [m]")
        ax.set_ylabel("v [m]")
    _scenario_segments(ax, u, v, series.scenario, geometry=series.geometry, linewidth=0.7)
    if len(series.impact_rows):
        ax.scatter(u[series.impact_rows], v[series.impact_rows], **IMPACT_MARK)
    if cr:  # a tilted journal's rim may pass the circle by up to (Rj sin(tilt)); keep it framed
        reach = max(1.15, 1.05 * float(np.nanmax(np.hypot(u, v), initial=0.0)))
        ax.set_xlim(-reach, reach)
        ax.set_ylim(-reach, reach)
    ax.set_aspect("equal")
    ax.set_title(title if title is not None else f"journal centre at base {rim.upper()}", fontsize=10)
    ax.grid(True, linewidth=0.3, alpha=0.5)


def plot_normal_force(ax, series: ClearanceJointSeries, x: np.ndarray, x_label: str) -> None:
    """Total normal contact force F_N (eqs. 27-29, summed over the contacts) against x; for a
    lubricated joint also the joint's whole force |F| (film and contact, the table's fx, fy, fz),
    which carries the load while the film holds and F_N is 0."""
    if series.lubricated and series.total_force is not None:
        ax.plot(x, series.total_force, label="|F|, film + contact", **TOTAL_FORCE_CURVE)
    _scenario_segments(ax, x, series.normal_force, series.scenario, linewidth=0.8,
                       geometry=series.geometry)
    if len(series.impact_rows):
        ax.plot(x[series.impact_rows], np.zeros(len(series.impact_rows)),
                transform=ax.get_xaxis_transform(), clip_on=False, **IMPACT_TICK)
    if series.lubricated:
        from matplotlib.lines import Line2D
        ax.legend(handles=[Line2D([], [], label="|F|, film + contact", **TOTAL_FORCE_CURVE),
                           Line2D([], [], color="0.5", linewidth=0.8, label="contact F_N (by scenario)")],
                  loc="upper right", fontsize=7)
        ax.set_ylabel("joint force [N]")
    else:
        ax.set_ylabel("normal force [N]")
    ax.set_xlabel(x_label)
    ax.grid(True, linewidth=0.3, alpha=0.5)


def plot_film_thickness(ax, series: ClearanceJointSeries, x: np.ndarray, x_label: str) -> None:
    """A lubricated joint's minimum film thickness h_min [µm] (docs/dynamics.md,
    film.min_thickness), coloured by contact scenario; 0 is where the surfaces would touch."""
    _scenario_segments(ax, x, series.film["min_thickness"] * MICROMETRES_PER_METRE, series.scenario,
                       linewidth=0.8, geometry=series.geometry)
    ax.axhline(0.0, color="0.4", linestyle="--", linewidth=0.8)
    ax.set_ylabel("h_min [µm]")
    ax.set_xlabel(x_label)
    ax.grid(True, linewidth=0.3, alpha=0.5)


def plot_axial_position(ax, series: ClearanceJointSeries, x: np.ndarray, x_label: str) -> None:
    """The journal centre along the bearing axis in units of the axial clearance c_a (eq. 2),
    whose bounds +-1 are dashed; in metres when the model (hence c_a) is not known."""
    ca = series.axial_clearance
    ax.set_ylabel("axial position / c_a [-]" if ca else "axial position [m]")
    _scenario_segments(ax, x, series.axial_position / (ca if ca else 1.0), series.scenario, linewidth=0.8,
                       geometry=series.geometry)
    if ca:
        for side in (-1.0, 1.0):
            ax.axhline(side, color="0.4", linestyle="--", linewidth=0.8)
    ax.set_xlabel(x_label)
    ax.grid(True, linewidth=0.3, alpha=0.5)


def plot_tilt(ax, series: ClearanceJointSeries, x: np.ndarray, x_label: str, log: bool = False) -> None:
    """The angle between journal and bearing axes (Fig. 11(b)); ``log``: on a logarithmic axis,
    for a tilt that decays by orders of magnitude (an exactly parallel report time is drawn at
    the smallest positive tilt of the window)."""
    tilt = np.degrees(series.axis_angle)
    if log:
        positive = tilt[tilt > 0.0]
        tilt = np.maximum(tilt, positive.min() if positive.size else 1e-12)
        ax.set_yscale("log")
    _scenario_segments(ax, x, tilt, series.scenario, geometry=series.geometry, linewidth=0.8)
    ax.set_ylabel("tilt [deg]")
    ax.set_xlabel(x_label)
    ax.grid(True, linewidth=0.3, alpha=0.5)


def plot_compared(ax, x: np.ndarray, y: np.ndarray, x_label: str, y_label: str,
                  reference_x: Optional[np.ndarray] = None, reference_y: Optional[np.ndarray] = None, *,
                  scenario: Optional[np.ndarray] = None, label: str = "clearance joint",
                  reference_label: str = "ideal joint", linewidth: float = 0.8,
                  colour: Optional[str] = None, legend: bool = True,
                  geometry: Optional[str] = None) -> None:
    """A quantity of a run with a clearance joint against ``x`` (time, or another quantity for a
    phase portrait), beside the same quantity of a reference run, dashed (the ideal joint's:
    paper Figs. 7-10, 13, 15-18). With ``scenario`` (the joint's scenario code at each of the
    run's report times) the curve is coloured by contact scenario as the joint's panels are,
    otherwise drawn in one colour (``colour``, default the clearance curve's) and labelled
    ``label``; ``legend`` names the curves drawn in one colour (a scenario-coloured curve takes its
    legend from ``scenario_legend_handles``); ``geometry`` is the joint's, which says the table
    of its scenario codes (scenario_colours.py)."""
    if reference_x is not None and reference_y is not None:
        ax.plot(reference_x, reference_y, label=reference_label, **IDEAL_CURVE)
    if scenario is not None:
        _scenario_segments(ax, np.asarray(x), np.asarray(y), np.asarray(scenario), linewidth=linewidth,
                           geometry=geometry)
    else:
        style = dict(CLEARANCE_CURVE, linewidth=linewidth)
        if colour is not None:
            style["color"] = colour
        ax.plot(x, y, label=label, **style)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper right", fontsize=8)
    ax.grid(True, linewidth=0.3, alpha=0.5)


def plot_slider_acceleration(ax, x: np.ndarray, acceleration: np.ndarray, x_label: str,
                             ideal_x: Optional[np.ndarray] = None,
                             ideal_acceleration: Optional[np.ndarray] = None,
                             component: str = "x") -> None:
    """The slider's acceleration with the clearance joint, and the ideal joint's when given
    (paper Figs. 8, 13)."""
    plot_compared(ax, x, acceleration, x_label, f"slider acceleration {component} [m/s$^2$]",
                  ideal_x, ideal_acceleration)


def plot_orbit_3d(ax, series: ClearanceJointSeries) -> None:
    """Both journal base centres in the bearing frame on a 3-D Axes (``projection="3d"``), the
    isometric view of Fig. 14: u and v in units of the radial clearance (metres when the
    model is not known), each base centre's axial position in metres, so that the two
    orbits lie at the two ends of the bearing, each with its clearance circle; coloured by
    scenario."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection
    cr = series.radial_clearance
    scale = 1.0 / cr if cr else 1.0
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    for centre in (series.rim_a, series.rim_b):
        points = np.column_stack([centre[:, 0] * scale, centre[:, 1] * scale, centre[:, 2]])
        if cr:
            ax.plot(np.cos(angle), np.sin(angle), np.full(angle.size, np.median(points[:, 2])), color="0.4",
                    linewidth=0.8)
        paths, colours = _scenario_stretches(points, series.scenario, series.geometry)
        ax.add_collection3d(Line3DCollection(paths, colors=colours, linewidths=0.6))
        ax.auto_scale_xyz(points[:, 0], points[:, 1], points[:, 2], had_data=True)
    ax.set_xlabel("u / c_r [-]" if cr else "u [m]")
    ax.set_ylabel("v / c_r [-]" if cr else "v [m]")
    ax.set_zlabel("axial position [m]")
