# SPDX-License-Identifier: BSD-3-Clause
"""The numbers the viewer page animates, packed for the browser: one Float32 array of frames
(report times, decimated to at most ``max_frames``) and a JSON manifest saying where each
quantity sits in a frame and what shapes to draw.

Why this shape: a run of 1e5 report times is 10-40 MB of CSV text, seconds of parsing in a
browser. Packed as Float32, decimated to 20 000 frames, it is a few megabytes that the page maps
with one ``new Float32Array(buffer)`` and indexes directly (``data[frame * stride + offset]``).
Decimation keeps every ``step``-th report time for the 3-D scene, and for the force plot keeps
the largest normal force of the report times each frame stands for, so that no impact peak is
lost; ``step`` is in the manifest and the page shows it.

Frame layout (floats): time; per body x, y, z, e0, e1, e2, e3 (world; body frame to world, paper
eq. (5) notation for the Euler parameters); per clearance joint: scenario code, contact count,
rim A centre (u, v, axial), rim B centre (u, v, axial) in the bearing frame [m] (the table's
columns), total normal force at the frame [N], largest normal force since the previous frame
[N], the joint's whole force |(fx, fy, fz)| at the frame (contact and, for a lubricated joint,
film) [N], its largest since the previous frame [N], the film's minimum thickness h_min [m] (NaN
for a dry joint), then MAX_CONTACTS slots of contact point C_i (u, v, axial) [m] and unit normal (u, v, axial),
out of the bearing, NaN in unused slots.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from ..plot.joint_series import CONTACT_SLOTS
from ..plot.run_folder import ClearanceJointModel, Run, RunError
from ..plot.scenario_colours import PIN_IN_HOLE, scenario_table

#: Frames sent to the page at most: 20 000 frames of a three-body, one-joint model are 4.6 MB.
DEFAULT_MAX_FRAMES = 20_000
#: Contact slots per joint and frame (clearjoint.MAX_CONTACTS, C++ geometry::kMaxContacts).
MAX_CONTACTS = 6
BODY_FLOATS = 7
JOINT_HEAD_FLOATS = 13
CONTACT_FLOATS = 6
#: The displayed clearance is at most this share of the bearing's radius and half-length, so
#: that the magnified journal keeps a visible radius and length.
DISPLAYED_CLEARANCE_SHARE = 0.15


@dataclass
class ViewerData:
    manifest: Dict[str, Any]
    frames: np.ndarray  # float32, (frame_count, stride)


def rotation_matrices(e: np.ndarray) -> np.ndarray:
    """A(p) for Euler parameters e = (e0, e1, e2, e3) of shape (N, 4): (N, 3, 3), body to world
    (Nikravesh's A = (2 e0^2 - 1) I + 2 (e e^T + e0 e~), the paper's rotation of body frames)."""
    e = e / np.linalg.norm(e, axis=1, keepdims=True)
    e0, e1, e2, e3 = e.T
    return np.stack([
        np.stack([1 - 2 * (e2 * e2 + e3 * e3), 2 * (e1 * e2 - e0 * e3), 2 * (e1 * e3 + e0 * e2)], axis=1),
        np.stack([2 * (e1 * e2 + e0 * e3), 1 - 2 * (e1 * e1 + e3 * e3), 2 * (e2 * e3 - e0 * e1)], axis=1),
        np.stack([2 * (e1 * e3 - e0 * e2), 2 * (e2 * e3 + e0 * e1), 1 - 2 * (e1 * e1 + e2 * e2)], axis=1),
    ], axis=1)


def bearing_frame_B(axis_B: np.ndarray) -> np.ndarray:
    """Columns u, v, a of the bearing frame in the bearing body's frame, as the joint builds it
    (clearance_revolute_joint.cpp): u = the body axis least aligned with a, made perpendicular
    (first of equals), v = a x u."""
    a = axis_B / np.linalg.norm(axis_B)
    e = np.zeros(3)
    e[int(np.argmin(np.abs(a)))] = 1.0
    u = e - e.dot(a) * a
    u /= np.linalg.norm(u)
    return np.column_stack([u, np.cross(a, u), a])


def inertia_box(mass: float, inertia: List[float]) -> List[float]:
    """Edge lengths of the uniform box with the body's mass and principal inertia, a simple shape
    that a model file fully determines: I_xx = m (b^2 + c^2) / 12, ... gives
    a^2 = 6 (I_yy + I_zz - I_xx) / m. A thin body (a^2 <= 0) gets a tenth of its largest edge."""
    ixx, iyy, izz = inertia
    squares = [6.0 * (iyy + izz - ixx) / mass, 6.0 * (ixx + izz - iyy) / mass,
               6.0 * (ixx + iyy - izz) / mass]
    largest = math.sqrt(max(max(squares), 1e-12))
    return [math.sqrt(s) if s > (0.1 * largest) ** 2 else 0.1 * largest for s in squares]


def nice_magnification(limit: float) -> float:
    """The largest of 1, 2, 5 x 10^k not above ``limit`` (at least 1)."""
    if limit <= 1.0:
        return 1.0
    power = 10.0 ** math.floor(math.log10(limit))
    return max(m * power for m in (1.0, 2.0, 5.0) if m * power <= limit)


def _magnification_limit(joint: ClearanceJointModel, share: float) -> float:
    """The magnification that shows the radial and axial clearances as ``share`` of Ri and Li/2;
    a pin without two stops has no axial clearance, and only its radial one limits."""
    limits = [share * joint.bearing_radius / joint.radial_clearance]
    if joint.axial_clearance > 0.0:
        limits.append(share * 0.5 * joint.bearing_length / joint.axial_clearance)
    return min(limits)


def default_magnification(joint: ClearanceJointModel) -> float:
    """So that the displayed clearances are at most DISPLAYED_CLEARANCE_SHARE of Ri and Li/2."""
    return nice_magnification(_magnification_limit(joint, DISPLAYED_CLEARANCE_SHARE))


def _body_pose(run: Run, body: str, rows: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """(positions (N, 3), Euler parameters (N, 4)) of a body at the given rows; ground: origin."""
    if body == "ground":
        e = np.zeros((len(rows), 4))
        e[:, 0] = 1.0
        return np.zeros((len(rows), 3)), e
    if "body_" + body not in run.tables:
        raise RunError(f"{run.source}: no table body_{body}.csv; the viewer needs every body of a "
                       "clearance joint in the model's output.bodies")
    position = np.stack([run.column("body_" + body, c)[rows] for c in ("x", "y", "z")], axis=1)
    return position, np.stack([run.column("body_" + body, c)[rows] for c in ("e0", "e1", "e2", "e3")], axis=1)


def _contacts_in_bearing_frame(run: Run, joint: ClearanceJointModel, rows: np.ndarray) -> np.ndarray:
    """(N, MAX_CONTACTS, 6): C_i and the normal of every contact, bearing frame, from the
    certified detection (clearjoint.detect, paper Sec. 3; clearjoint.detect_pin_in_hole for a pin
    in a hole, the hole's frame) on the recorded poses, every pose in one packed batch; NaN where
    no contact. The run's table says which scenario each report time was in; the page shows where."""
    from .. import JointDimensions, PinInHoleDimensions, detect, detect_pin_in_hole
    r_i, e_i = _body_pose(run, joint.bearing_body, rows)
    r_j, e_j = _body_pose(run, joint.journal_body, rows)
    rot_i, rot_j = rotation_matrices(e_i), rotation_matrices(e_j)
    p_WPi = r_i + rot_i @ joint.bearing_point
    axis_i = rot_i @ joint.bearing_axis
    p_WPj = r_j + rot_j @ joint.journal_point
    axis_j = rot_j @ joint.journal_axis
    if joint.geometry == PIN_IN_HOLE:
        pin_dims = PinInHoleDimensions(hole_radius=joint.bearing_radius, hole_length=joint.bearing_length,
                                       pin_radius=joint.journal_radius, stops=list(joint.stops))
        batch = detect_pin_in_hole(pin_dims, p_WPi, axis_i, p_WPj, axis_j,
                                   parallel_angle_tolerance=joint.parallel_angle_tolerance)
    else:
        dims = JointDimensions(bearing_radius=joint.bearing_radius, bearing_length=joint.bearing_length,
                               journal_radius=joint.journal_radius, journal_length=joint.journal_length)
        batch = detect(dims, p_WPi, axis_i, p_WPj, axis_j,
                       parallel_angle_tolerance=joint.parallel_angle_tolerance)
    to_bearing = np.einsum("ij,njk->nik", bearing_frame_B(joint.bearing_axis).T,
                           np.transpose(rot_i, (0, 2, 1)))  # world -> (u, v, a)
    out = np.full((len(rows), MAX_CONTACTS, CONTACT_FLOATS), np.nan)
    pose = batch.contact_pose
    if len(pose):
        slot = batch.slot()
        relative = batch.point_bearing - p_WPi[pose]
        out[pose, slot, 0:3] = np.einsum("nij,nj->ni", to_bearing[pose], relative)
        out[pose, slot, 3:6] = np.einsum("nij,nj->ni", to_bearing[pose], batch.normal)
    return out


def decimation_step(rows: int, max_frames: int) -> int:
    return max(1, math.ceil(rows / max(1, max_frames)))


def viewer_data(run: Run, max_frames: int = DEFAULT_MAX_FRAMES,
                magnification: Optional[float] = None) -> ViewerData:
    """The manifest and frames of a run whose model is known."""
    if run.model is None:
        raise RunError(f"{run.source}: the viewer needs the run's model file for the shapes "
                       "(pass --model MODEL.json, or keep it in the run folder as model.json)")
    # Every table of a run has the same report times (run_folder checks the row counts).
    time = run.column("energy" if "energy" in run.tables else sorted(run.tables)[0], "time")
    step = decimation_step(len(time), max_frames)
    rows = np.arange(0, len(time), step)
    bodies = [b for b in run.model.get("bodies", []) if "body_" + b["name"] in run.tables]
    joints = [j for j in run.clearance_joints if j.table in run.tables]

    columns: List[np.ndarray] = [time[rows][:, None]]
    body_entries = []
    offset = 1
    for body in bodies:
        position, e = _body_pose(run, body["name"], rows)
        columns += [position, e]
        body_entries.append({"name": body["name"], "offset": offset,
                             "box": inertia_box(float(body["mass"]), body["inertia"])})
        offset += BODY_FLOATS

    joint_entries = []
    for joint in joints:
        table = run.tables[joint.table]
        forces = [table[f"{s}.normal_force"] for s in CONTACT_SLOTS if f"{s}.normal_force" in table]
        normal_force = np.sum(forces, axis=0) if forces else np.zeros_like(time)
        # The joint's whole force: a lubricated joint's film carries the load while F_N is 0.
        total_force = np.sqrt(sum(table[c] ** 2 for c in ("fx", "fy", "fz"))) if all(
            c in table for c in ("fx", "fy", "fz")) else normal_force
        min_thickness = table.get("film.min_thickness", np.full_like(time, np.nan))
        # Largest force over the rows each frame stands for (rows[k] .. rows[k + 1] - 1).
        peak = np.maximum.reduceat(normal_force, rows) if len(rows) else normal_force[:0]
        peak_total = np.maximum.reduceat(total_force, rows) if len(rows) else total_force[:0]
        contacts = _contacts_in_bearing_frame(run, joint, rows)
        rims = np.stack([run.column(joint.table, c)[rows] for c in ("rim_a_u", "rim_a_v", "rim_a_axial",
                                                                  "rim_b_u", "rim_b_v", "rim_b_axial")], axis=1)
        columns += [run.column(joint.table, "scenario")[rows][:, None],
                    run.column(joint.table, "contact_count")[rows][:, None], rims,
                    normal_force[rows][:, None], peak[:, None], total_force[rows][:, None],
                    peak_total[:, None], min_thickness[rows][:, None],
                    contacts.reshape(len(rows), MAX_CONTACTS * CONTACT_FLOATS)]
        frame_b = bearing_frame_B(joint.bearing_axis)
        joint_entries.append({
            "name": joint.name, "table": joint.table, "offset": offset,
            "bearing_body": joint.bearing_body, "journal_body": joint.journal_body,
            "bearing_point": joint.bearing_point.tolist(),
            "bearing_frame": frame_b.T.tolist(),  # rows u, v, a in the bearing body's frame
            "journal_point": joint.journal_point.tolist(),
            "journal_axis": joint.journal_axis.tolist(),
            "bearing_radius": joint.bearing_radius, "bearing_length": joint.bearing_length,
            "journal_radius": joint.journal_radius, "journal_length": joint.journal_length,
            "radial_clearance": joint.radial_clearance, "axial_clearance": joint.axial_clearance,
            "magnification": magnification or default_magnification(joint),
            "max_magnification": _magnification_limit(joint, 0.9),
            "peak_force": float(np.nanmax(normal_force, initial=0.0)),
            "peak_total_force": float(np.nanmax(total_force, initial=0.0)),
            "lubricated": "film.min_thickness" in table,
            # The table of this joint's scenario codes (the paper's, or the pin-in-hole one).
            "geometry": joint.geometry,
            "scenarios": scenario_table(joint.geometry),
        })
        offset += JOINT_HEAD_FLOATS + MAX_CONTACTS * CONTACT_FLOATS

    frames = np.ascontiguousarray(np.concatenate(columns, axis=1), dtype="<f4")
    gravity = run.model.get("gravity", [0.0, 0.0, -9.81])
    manifest = {
        "format": "clearjoint-view-1",
        "model_name": run.model.get("name", ""),
        "source": run.source,
        "row_count": int(len(time)),
        "frame_count": int(len(rows)),
        "decimation_step": int(step),
        "stride": int(frames.shape[1]),
        "start_time": float(time[0]), "end_time": float(time[-1]),
        "gravity": gravity,
        "bodies": body_entries,
        "unrecorded_bodies": [b["name"] for b in run.model.get("bodies", [])
                              if "body_" + b["name"] not in run.tables],
        "joints": joint_entries,
        "joint_points": _joint_points(run.model, {b["name"] for b in bodies}),
        "max_contacts": MAX_CONTACTS,
        "scenarios": scenario_table(),
    }
    return ViewerData(manifest=manifest, frames=frames)


def _joint_points(model: Dict[str, Any], drawn: set) -> List[Dict[str, Any]]:
    """Where each ideal joint attaches to each body it joins (markers on the shapes)."""
    points = []
    for joint in model.get("joints", []):
        for side in ("i", "j"):
            body = joint.get("body_" + side)
            if (body in drawn or body == "ground") and "point_" + side in joint:
                points.append({"joint": joint.get("name", ""), "body": body,
                               "point": list(map(float, joint["point_" + side]))})
    return points
