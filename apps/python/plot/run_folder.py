# SPDX-License-Identifier: BSD-3-Clause
"""A run as the figures and the viewer read it: the tables of ``clearjoint simulate`` (a run
folder of CSV files or run.h5, of either engine; a folder of ``clearjoint-mujoco``, which holds
force tables only; or the :class:`clearjoint.SimulationResult` of ``clearjoint.simulate`` or
``clearjoint.read_run``) and the model file that produced them, when it is known.

Folders are read by the reader of ``clearjoint.read_run`` (_run_files.read_folder_tables): the
same files are accepted and refused with the same messages. The difference: ``clearjoint.read_run``
returns DataFrames with typed code columns and the summary, this one float64 arrays (what the
figures compute with) and the model.

Bad input ends in :class:`RunError` with one sentence for people (a folder that is not a run, a
truncated table, a model that does not match the tables), never a NumPy traceback.
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from typing import Any, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np

from .._run_files import read_folder_tables, read_json_bounded
from .scenario_colours import JOURNAL_BEARING, PIN_IN_HOLE

Tables = Dict[str, Dict[str, np.ndarray]]

#: The file a run folder may carry its model in; ``--model`` (``model=``) overrides it.
MODEL_FILE_IN_RUN = "model.json"


class RunError(ValueError):
    """A run folder, table or model that cannot be read as a run of ``clearjoint simulate``."""


@dataclass(frozen=True)
class ClearanceJointModel:
    """What the figures need of one ``clearance_revolute`` force element of the model file.

    A pin-in-hole joint (``geometry`` "pin_in_hole", docs/dynamics.md) fills the same fields: the
    hole is the bearing (radius, the link's thickness as length), the pin the journal (radius;
    as length the span between its two stops, else the hole's length plus twice its radius, a
    length to draw), and ``stops`` are its stops as (position along the pin, outer radius)."""

    name: str
    table: str                 # its table: "force_" + the name, sanitised as the C++ side does
    bearing_body: str
    journal_body: str
    bearing_point: np.ndarray  # P_i in the bearing body's frame [m]
    bearing_axis: np.ndarray   # a_i in the bearing body's frame (unit)
    journal_point: np.ndarray
    journal_axis: np.ndarray
    bearing_radius: float      # Ri [m]
    bearing_length: float      # Li [m]
    journal_radius: float      # Rj [m]
    journal_length: float      # Lj [m]
    parallel_angle_tolerance: float = 0.0
    geometry: str = JOURNAL_BEARING
    stops: Tuple[Tuple[float, float], ...] = ()  # a pin's stops: (position, outer radius) [m]

    @property
    def radial_clearance(self) -> float:
        """cr = Ri - Rj [m] (paper eq. 1)."""
        return self.bearing_radius - self.journal_radius

    @property
    def axial_clearance(self) -> float:
        """ca = (Li - Lj) / 2 [m] (paper eq. 2); a pin with two stops: how far the stops' faces
        lie beyond the link's faces, (s_0 - s_1 - Li) / 2; a pin with fewer: 0 (no axial play
        to scale by)."""
        if self.geometry == PIN_IN_HOLE:
            if len(self.stops) != 2:
                return 0.0
            return 0.5 * (abs(self.stops[0][0] - self.stops[1][0]) - self.bearing_length)
        return 0.5 * (self.bearing_length - self.journal_length)


@dataclass(frozen=True)
class Run:
    """The tables of one run and, when known, its model (the parsed model-file dict)."""

    tables: Tables
    model: Optional[Dict[str, Any]] = None
    source: str = "<run>"      # the folder, for messages
    clearance_joints: List[ClearanceJointModel] = field(default_factory=list)

    def table(self, name: str) -> Dict[str, np.ndarray]:
        try:
            return self.tables[name]
        except KeyError:
            raise RunError(f"{self.source}: has no table {name}.csv (tables: "
                           f"{', '.join(sorted(self.tables)) or 'none'})") from None

    def column(self, table: str, name: str) -> np.ndarray:
        """One column of a table; RunError naming both when the table lacks it (a damaged
        table, or one not written by clearjoint simulate)."""
        columns = self.table(table)
        try:
            return columns[name]
        except KeyError:
            raise RunError(f"{self.source}: {table}.csv has no column {name} (a damaged table, or "
                           "one not written by clearjoint simulate)") from None

    def clearance_tables(self) -> List[str]:
        """Tables of clearance joints (force_*.csv with a scenario column), in name order."""
        return sorted(name for name, columns in self.tables.items()
                      if name.startswith("force_") and "scenario" in columns and "rim_a_u" in columns)

    def joint_model(self, table: str) -> Optional[ClearanceJointModel]:
        for joint in self.clearance_joints:
            if joint.table == table:
                return joint
        return None


def table_name(prefix: str, name: str) -> str:
    """A table's name as simulation.hpp forms it: characters other than letters, digits, - and _
    become _."""
    return prefix + re.sub(r"[^A-Za-z0-9_-]", "_", name)


def _vector(value: Any, default: List[float]) -> np.ndarray:
    return np.asarray(value if value is not None else default, dtype=float)


def clearance_joints_of(model: Mapping[str, Any]) -> List[ClearanceJointModel]:
    """The clearance joints of a model-file dict (docs/dynamics.md, model.schema.json)."""
    joints = []
    for element in model.get("forces", []):
        if element.get("type") != "clearance_revolute":
            continue
        geometry = element.get("geometry", JOURNAL_BEARING)
        if geometry == PIN_IN_HOLE:
            joints.append(_pin_in_hole_joint(element))
            continue
        bearing, journal = element["bearing"], element["journal"]
        axis_i = _vector(bearing.get("axis"), [0.0, 0.0, 1.0])
        axis_j = _vector(journal.get("axis"), [0.0, 0.0, 1.0])
        joints.append(ClearanceJointModel(
            name=element["name"], table=table_name("force_", element["name"]),
            bearing_body=bearing["body"], journal_body=journal["body"],
            bearing_point=_vector(bearing.get("point"), [0.0, 0.0, 0.0]),
            bearing_axis=axis_i / np.linalg.norm(axis_i),
            journal_point=_vector(journal.get("point"), [0.0, 0.0, 0.0]),
            journal_axis=axis_j / np.linalg.norm(axis_j),
            bearing_radius=float(bearing["radius"]), bearing_length=float(bearing["length"]),
            journal_radius=float(journal["radius"]), journal_length=float(journal["length"]),
            parallel_angle_tolerance=float(
                element.get("detection", {}).get("parallel_angle_tolerance", 0.0))))
    return joints


def _pin_in_hole_joint(element: Mapping[str, Any]) -> ClearanceJointModel:
    hole, pin = element["hole"], element["pin"]
    axis_i = _vector(hole.get("axis"), [0.0, 0.0, 1.0])
    axis_j = _vector(pin.get("axis"), [0.0, 0.0, 1.0])
    stops = tuple((float(stop["position"]), float(stop["outer_radius"])) for stop in pin.get("stops", []))
    hole_length, pin_radius = float(hole["length"]), float(pin["radius"])
    drawn_length = abs(stops[0][0] - stops[1][0]) if len(stops) == 2 else hole_length + 2.0 * pin_radius
    return ClearanceJointModel(
        name=element["name"], table=table_name("force_", element["name"]),
        bearing_body=hole["body"], journal_body=pin["body"],
        bearing_point=_vector(hole.get("point"), [0.0, 0.0, 0.0]),
        bearing_axis=axis_i / np.linalg.norm(axis_i),
        journal_point=_vector(pin.get("point"), [0.0, 0.0, 0.0]),
        journal_axis=axis_j / np.linalg.norm(axis_j),
        bearing_radius=float(hole["radius"]), bearing_length=hole_length,
        journal_radius=pin_radius, journal_length=drawn_length,
        parallel_angle_tolerance=float(element.get("detection", {}).get("parallel_angle_tolerance", 0.0)),
        geometry=PIN_IN_HOLE, stops=stops)


def _read_model(model: Union[str, "os.PathLike[str]", Mapping[str, Any], None]) -> Optional[Dict[str, Any]]:
    if model is None or isinstance(model, Mapping):
        return dict(model) if model is not None else None
    try:
        loaded = read_json_bounded(os.fspath(model), "model")
    except (FileNotFoundError, ValueError) as error:  # and the bounded reader's refusals
        raise RunError(str(error)) from None
    if not isinstance(loaded, dict):
        raise RunError(f"model {os.fspath(model)}: not a model file (a JSON object)")
    return loaded


def _check_times(tables: Tables, source: str) -> None:
    """Every table's time column holds numbers that never decrease (the report times, paper
    Sec. 5's integration reported at solver.report_step): a NaN or a step back means the table
    was damaged or edited, and figures drawn from it would be wrong without a word."""
    for name, columns in sorted(tables.items()):
        time = columns.get("time")
        if time is None or len(time) == 0:
            continue
        bad = np.flatnonzero(~np.isfinite(time))
        if len(bad):
            row = int(bad[0])
            raise RunError(f"{source}: {name}.csv row {row + 1}: time = {float(time[row])!r}: every report "
                           "time must be a finite number (a damaged table)")
        back = np.flatnonzero(np.diff(time) < 0)
        if len(back):
            row = int(back[0]) + 1
            raise RunError(f"{source}: {name}.csv row {row + 1}: time = {float(time[row])!r} is before the "
                           f"previous row's {float(time[row - 1])!r}: report times must not run backwards "
                           "(a damaged table)")


def _check_rows(tables: Tables, source: str) -> None:
    rows = {name: len(next(iter(columns.values()))) for name, columns in tables.items() if columns}
    if not rows:
        return
    longest = max(rows.values())
    for name, count in sorted(rows.items()):
        if count != longest:
            raise RunError(f"{source}: {name} has {count} rows where other tables have {longest} "
                           "(a truncated table)")
    if longest == 0:
        raise RunError(f"{source}: the tables have no rows")


def _with_model(tables: Tables, model: Optional[Dict[str, Any]], source: str) -> Run:
    _check_rows(tables, source)
    _check_times(tables, source)
    joints: List[ClearanceJointModel] = []
    if model is not None:
        try:
            joints = clearance_joints_of(model)
        except (KeyError, TypeError, ValueError) as error:
            raise RunError(f"{source}: the model's clearance joint cannot be read ({error!r})") from None
    return Run(tables=tables, model=model, source=source, clearance_joints=joints)


def _float_tables(tables: Mapping[str, Any]) -> Tables:
    """Tables as dicts of float64 arrays, also from the DataFrames of ``clearjoint.read_run``."""
    return {name: {column: np.asarray(columns[column], dtype=np.float64) for column in columns}
            for name, columns in tables.items()}


def read_run(run: Any, model: Union[str, "os.PathLike[str]", Mapping[str, Any], None] = None) -> Run:
    """A :class:`Run` from a run folder (str or os.PathLike), a :class:`clearjoint.SimulationResult`
    (or anything with ``tables``), its ``tables`` dict, or a :class:`Run` (returned as it is unless
    ``model`` is given).

    ``model``: the model file (path or dict) of the run. Default: ``model.json`` in the run folder
    when there is one; without a model (a ``clearjoint-mujoco`` run) the figures still draw, in
    metres instead of clearance units, and the viewer refuses (it needs the shapes).
    """
    if isinstance(run, Run):
        return run if model is None else _with_model(run.tables, _read_model(model), run.source)
    if hasattr(run, "tables"):
        source = getattr(run, "folder", None) or "<simulation result>"
        if model is None and getattr(run, "folder", None):
            candidate = os.path.join(run.folder, MODEL_FILE_IN_RUN)
            model = candidate if os.path.lexists(candidate) else None
        return _with_model(_float_tables(run.tables), _read_model(model), source)
    if isinstance(run, Mapping):  # result.tables itself: table name -> column name -> array
        return _with_model(_float_tables(run), _read_model(model), "<tables>")
    if not isinstance(run, (str, os.PathLike)):
        raise TypeError(f"run = {type(run).__name__}: must be a run folder, a SimulationResult or a Run")
    folder = os.fspath(run)
    if not os.path.isdir(folder):
        raise RunError(f"{folder}: no such folder (a run folder of clearjoint simulate --out)")
    try:
        tables = read_folder_tables(folder)
    except ValueError as error:  # RunFileError, and the bounded reader's refusals
        raise RunError(str(error)) from None
    if model is None and os.path.lexists(os.path.join(folder, MODEL_FILE_IN_RUN)):
        model = os.path.join(folder, MODEL_FILE_IN_RUN)
    return _with_model(tables, _read_model(model), folder)
