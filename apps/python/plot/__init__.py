# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.plot: the standard figures of a run with clearance joints (docs/viewing-runs.md).

- ``joint_figure(run, joint=None, model=None, ideal=None, panels=None, window=None, x="time")``:
  one joint's figure (a matplotlib Figure): the journal orbit in clearance units inside the unit
  circle (both base centres for a spatial joint), the normal force, the axial position and tilt,
  the slider's acceleration beside an ideal run's; coloured by contact scenario, impacts marked;
- ``compare(runs, labels=None, out=None, window=None, ideal=None, ...)``: several runs (any
  engine, CSV or HDF5) overlaid in one figure with a legend (``clearjoint plot RUN RUN --out FIG``);
- ``save_joint_figures(run, out_dir=None, ...)``: every joint's figure as PNG and SVG files
  (``clearjoint plot RUN_DIR`` and ``clearjoint simulate --plot``);
- ``plot_orbit``, ``plot_normal_force``, ``plot_axial_position``, ``plot_tilt``,
  ``plot_slider_acceleration``: the panels, on an Axes of your own, from ``joint_series``;
  ``plot_orbit_3d``, both base centres on a 3-D Axes; ``plot_compared``, any quantity of the run
  (or a phase portrait) beside an ideal run's, optionally coloured by scenario (the paper's
  Figs. 7-18 in reproduction/section6_figures.py);
- ``SCENARIO_COLOURS``, ``scenario_colour``: the one table of scenario colours.

``run`` is a run folder of ``clearjoint simulate --out`` (CSV or HDF5, either engine) or of
``clearjoint-mujoco``, or the :class:`clearjoint.SimulationResult` that ``clearjoint.simulate``
returns (then pass ``model=``, the same model file or dict).
"""
from .compare import Comparison, compare
from .figures import PANELS, joint_figure, joint_figures, save_joint_figures, slider_acceleration
from .joint_series import ClearanceJointSeries, joint_series, rotation_angle
from .panels import (plot_axial_position, plot_compared, plot_film_thickness, plot_normal_force, plot_orbit,
                     plot_orbit_3d, plot_slider_acceleration, plot_tilt, scenario_legend_handles)
from .run_folder import ClearanceJointModel, Run, RunError, read_run
from .scenario_colours import SCENARIO_COLOURS, scenario_colour, scenario_name, scenario_table

__all__ = [
    "PANELS", "SCENARIO_COLOURS", "ClearanceJointModel", "ClearanceJointSeries", "Comparison", "Run",
    "RunError", "compare", "joint_figure", "joint_figures", "joint_series", "plot_axial_position",
    "plot_compared", "plot_film_thickness", "plot_normal_force", "plot_orbit", "plot_orbit_3d", "plot_slider_acceleration", "plot_tilt",
    "read_run", "rotation_angle", "save_joint_figures", "scenario_colour", "scenario_legend_handles", "scenario_name",
    "scenario_table", "slider_acceleration",
]
