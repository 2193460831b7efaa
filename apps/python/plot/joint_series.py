# SPDX-License-Identifier: BSD-3-Clause
"""One clearance joint's time series as the figures draw them, from its ``force_<joint>`` table
(docs/dynamics.md, "Outputs"): the journal rims in the bearing frame, the scenario of each report
time, where impacts began, the normal force, the axial position and the tilt.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, Optional, Tuple

import numpy as np

from .._enums import ContactSlot
from .run_folder import ClearanceJointModel, Run, RunError
from .scenario_colours import JOURNAL_BEARING

#: The contact slots of a clearance joint's table, in the order of the library's table
#: (ContactSlot, clearance_revolute_joint.hpp).
CONTACT_SLOTS = tuple(slot.name for slot in ContactSlot)


@dataclass(frozen=True)
class ClearanceJointSeries:
    """Rows of one joint's table inside a time window; lengths in metres, angles in radians."""

    name: str                      # the table's name without "force_"
    time: np.ndarray               # [s]
    scenario: np.ndarray           # ContactScenario codes (int); PinInHoleScenario's for a pin in a hole
    rim_a: np.ndarray              # (N, 3): centre of the journal rim facing bearing base A, in
    rim_b: np.ndarray              #   the bearing frame (u, v, axial) relative to P_i [m] (Fig. 14)
    normal_force: np.ndarray       # sum of the slots' F_N [N]
    impact_rows: np.ndarray        # rows where some slot's contact began (its depth was NaN before)
    contact_free: np.ndarray       # rows where no slot is in dry contact (bool)
    axis_angle: np.ndarray         # angle between journal and bearing axes [rad] (Fig. 11(b))
    joint: Optional[ClearanceJointModel]  # the model's joint, when the model is known
    total_force: Optional[np.ndarray] = None  # |(fx, fy, fz)|: contact and film force on the journal [N]
    film: Optional[Dict[str, np.ndarray]] = None  # a lubricated joint's film.* columns, without "film."

    @property
    def lubricated(self) -> bool:
        return self.film is not None

    @property
    def film_force(self) -> Optional[np.ndarray]:
        """The film's force on the journal, lambda |F_film| [N], where the tables give it alone:
        at report times without a dry contact the joint's force (fx, fy, fz) is the film's
        (docs/dynamics.md: lambda F_film + F_dry); where a dry contact acts too the tables hold
        only the sum, and the value is NaN (a gap in the curve). None for a dry joint."""
        if self.film is None or self.total_force is None:
            return None
        return np.where(self.contact_free, self.total_force, np.nan)

    @property
    def geometry(self) -> str:
        """The joint's geometry, which says the table of its scenario codes; the paper's joint
        when the model is unknown."""
        return JOURNAL_BEARING if self.joint is None else self.joint.geometry

    @property
    def axial_position(self) -> np.ndarray:
        """The journal centre's position along the bearing axis, relative to P_i [m]."""
        return 0.5 * (self.rim_a[:, 2] + self.rim_b[:, 2])

    @property
    def radial_clearance(self) -> Optional[float]:
        return None if self.joint is None else self.joint.radial_clearance

    @property
    def axial_clearance(self) -> Optional[float]:
        return None if self.joint is None else self.joint.axial_clearance


def window_rows(time: np.ndarray, window: Optional[Tuple[Optional[float], Optional[float]]]) -> np.ndarray:
    """Which report times lie in ``window`` = (start, end) seconds, either end None for open;
    RunError when none does."""
    start, end = window if window is not None else (None, None)
    keep = np.ones(len(time), dtype=bool)
    if start is not None:
        keep &= time >= start
    if end is not None:
        keep &= time <= end
    if not keep.any():
        raise RunError(f"the time window [{start}, {end}] s holds no report time (the run covers "
                       f"{time[0]:g} s to {time[-1]:g} s)")
    return keep


def joint_series(run: Run, table: str,
                 window: Optional[Tuple[Optional[float], Optional[float]]] = None) -> ClearanceJointSeries:
    """The series of the clearance joint whose table is ``table`` ("force_<name>"), restricted to
    report times in ``window`` = (start, end) seconds (None: open end)."""
    columns = run.table(table)
    required = ["time", "scenario", "axis_angle", "rim_a_u", "rim_a_v", "rim_a_axial",
                "rim_b_u", "rim_b_v", "rim_b_axial"]
    missing = [c for c in required if c not in columns]
    if missing:
        raise RunError(f"{run.source}: {table} is not a clearance joint's table (no column "
                       f"{', '.join(missing)})")
    time = columns["time"]
    keep = window_rows(time, window)
    # A table without depth columns (a study store keeps only the columns it was asked for) marks
    # no impacts.
    depths = [columns[f"{s}.depth"] for s in CONTACT_SLOTS if f"{s}.depth" in columns]
    depth = np.stack(depths, axis=1) if depths else np.full((len(time), 0), np.nan)
    in_contact = np.isfinite(depth)
    # An impact begins where a slot is in contact and was not at the report time before (the
    # impact-velocity memory of eq. 28 starts there); the first row counts when already touching.
    began = in_contact & ~np.vstack([np.zeros((1, depth.shape[1]), dtype=bool), in_contact[:-1]])
    impact_rows_all = np.flatnonzero(began.any(axis=1))
    forces = [columns[f"{s}.normal_force"] for s in CONTACT_SLOTS if f"{s}.normal_force" in columns]
    normal_force = np.sum(forces, axis=0) if forces else np.zeros_like(time)
    rows = np.flatnonzero(keep)
    first = rows[0]
    impact_rows = impact_rows_all[keep[impact_rows_all]] - first
    total_force = None
    if all(c in columns for c in ("fx", "fy", "fz")):
        total_force = np.sqrt(columns["fx"] ** 2 + columns["fy"] ** 2 + columns["fz"] ** 2)[keep]
    film = {name[len("film."):]: values[keep] for name, values in columns.items()
            if name.startswith("film.")} or None
    return ClearanceJointSeries(
        name=table[len("force_"):],
        time=time[keep],
        scenario=np.nan_to_num(columns["scenario"][keep]).astype(int),
        rim_a=np.stack([columns["rim_a_u"], columns["rim_a_v"], columns["rim_a_axial"]], axis=1)[keep],
        rim_b=np.stack([columns["rim_b_u"], columns["rim_b_v"], columns["rim_b_axial"]], axis=1)[keep],
        normal_force=normal_force[keep],
        impact_rows=impact_rows,
        contact_free=~in_contact.any(axis=1)[keep],
        axis_angle=columns["axis_angle"][keep],
        joint=run.joint_model(table),
        total_force=total_force,
        film=film)


def rotation_angle(run: Run, body: str, axis_B: np.ndarray,
                   window: Optional[Tuple[Optional[float], Optional[float]]] = None) -> np.ndarray:
    """The body's rotation about its own axis ``axis_B`` (unit, body frame) from its Euler
    parameters, unwrapped [rad]: 2 atan2(e . n, e0), exact for a rotation about n and the crank
    angle of a crank that turns about n (the joint axis) with small wobble."""
    time, e0, e1, e2, e3 = (run.column("body_" + body, c) for c in ("time", "e0", "e1", "e2", "e3"))
    keep = window_rows(time, window)
    along = e1 * axis_B[0] + e2 * axis_B[1] + e3 * axis_B[2]
    return np.unwrap(2.0 * np.arctan2(along, e0))[keep]
