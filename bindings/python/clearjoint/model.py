# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.Model: a multibody model built from Python calls, written and read as the model file
of ``clearjoint simulate`` (docs/dynamics.md, "Model files"; docs/schema/model.schema.json).

The builder checks the types of its arguments as it takes them (a message names the field the
argument becomes, ``bodies[1].mass = "heavy": must be a number (not str)``). Everything else,
from names and references to bodies to ranges and the consistency of the joints, is checked by
``validate()``: the C++ reader and builder of model files, so that a message is the one the
file would get (``joints[0].body_i = "crnk": no body of that name ...``; the reader's own
messages start with ``<Model>: `` where a file's would start with its path).
"""
from __future__ import annotations

import copy
import json
import math
import os
from collections.abc import Mapping
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._simulate import _model_text

#: The world frame's name in joints and forces (dynamics: kGroundName).
GROUND = "ground"

#: What ``validate()`` calls the model in its messages, as "<dict>" names a dict given to
#: ``clearjoint.simulate``.
_SOURCE = "<Model>"

#: Keys every object of a model file may have besides its fields (docs/dynamics.md).
_ANYWHERE = ("comment", "notes")

_Converter = Callable[[Any, str], Any]
_Spec = Dict[str, _Converter]
_Path = Union[str, "os.PathLike[str]"]


# --- Values: each converter takes a value and the path of its field, and returns the JSON value
# the field holds or raises naming the path (TypeError for a wrong type, ValueError otherwise).

def _member(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _quote(value: Any) -> str:
    """The value as the C++ reader quotes it (JSON), or its repr when JSON has no form for it."""
    try:
        return json.dumps(value)
    except (TypeError, ValueError):
        return repr(value)


def _refuse(path: str, value: Any, what: str, error: type = TypeError) -> None:
    raise error(f"{path} = {_quote(value)}: {what}")


def _is_number(value: Any) -> bool:
    # bool is an int to Python and NumPy's bool_ converts to float: both are refused.
    return (isinstance(value, (int, float, np.integer, np.floating))
            and not isinstance(value, (bool, np.bool_)))


def _number(value: Any, path: str) -> float:
    if not _is_number(value):
        _refuse(path, value, f"must be a number (not {type(value).__name__})")
    try:
        number = float(value)
    except OverflowError:
        _refuse(path, value, "beyond the range of a double", ValueError)
    if not math.isfinite(number):
        _refuse(path, value, "must be finite (JSON has no NaN or infinity)", ValueError)
    return number


def _count(value: Any, path: str) -> Union[int, float]:
    """A number that counts (max_steps, decimation, grid cells): an integer stays an integer; the
    C++ reader checks that it is whole and in range."""
    number = _number(value, path)
    return int(value) if isinstance(value, (int, np.integer)) else number


def _text(value: Any, path: str) -> str:
    if not isinstance(value, str):
        _refuse(path, value, f"must be a string (not {type(value).__name__})")
    return str(value)


def _flag(value: Any, path: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        _refuse(path, value, f"must be True or False (not {type(value).__name__})")
    return bool(value)


def _items(value: Any, path: str, what: str) -> Sequence[Any]:
    """The entries of a list, tuple or 1-D array; a string is refused (it is a sequence too)."""
    if isinstance(value, np.ndarray) and value.ndim == 1:
        return list(value)
    if isinstance(value, (list, tuple)):
        return value
    _refuse(path, value, f"must be {what} (not {type(value).__name__})")
    return ()


def _vector(size: int, entry: _Converter = _number) -> _Converter:
    def convert(value: Any, path: str) -> List[Any]:
        items = _items(value, path, f"an array of {size} numbers")
        if len(items) != size:
            _refuse(path, value, f"must be an array of {size} numbers", ValueError)
        return [entry(item, f"{path}[{k}]") for k, item in enumerate(items)]
    return convert


def _strings(value: Any, path: str) -> List[str]:
    return [_text(item, f"{path}[{k}]") for k, item in
            enumerate(_items(value, path, "a list of strings"))]


def _fields(spec: _Spec, values: Mapping, path: str, required: Sequence[str] = ()) -> Dict[str, Any]:
    """The JSON object of `values` (a Mapping of field to value), each converted by its entry of
    `spec`, in the order given."""
    if not isinstance(values, Mapping):
        _refuse(path, values, f"must be a dict (a JSON object), not {type(values).__name__}")
    for key in required:
        if key not in values:
            raise ValueError(f"{_member(path, key)}: missing")
    result: Dict[str, Any] = {}
    for key, value in values.items():
        if not isinstance(key, str):
            raise TypeError(f"{path}: key {key!r} is a {type(key).__name__}; model keys are strings")
        convert = spec.get(key) or (_text if key in _ANYWHERE else None)
        if convert is None:
            raise ValueError(f"{_member(path, key)}: unknown field (expected {', '.join(spec)})")
        result[key] = convert(value, _member(path, key))
    return result


def _object(spec: _Spec) -> _Converter:
    return lambda value, path: _fields(spec, value, path)


def _list_of(spec: _Spec, required: Sequence[str] = ()) -> _Converter:
    def convert(value: Any, path: str) -> List[Dict[str, Any]]:
        return [_fields(spec, item, f"{path}[{k}]", required)
                for k, item in enumerate(_items(value, path, "a list of dicts"))]
    return convert


# --- The fields of each object of a model file, in the order of docs/dynamics.md. The test
# test_model_builder.py checks them against docs/schema/model.schema.json.

_VECTOR3 = _vector(3)

_BODY: _Spec = {"name": _text, "mass": _number, "inertia": _VECTOR3, "position": _VECTOR3,
                "euler_parameters": _vector(4), "velocity": _VECTOR3, "angular_velocity": _VECTOR3}
_BODY_REQUIRED = ("name", "mass", "inertia", "position")

_JOINT: _Spec = {"name": _text, "type": _text, "body_i": _text, "body_j": _text, "point_i": _VECTOR3,
                 "point_j": _VECTOR3, "axis_i": _VECTOR3, "axis_j": _VECTOR3, "angle_rate": _number,
                 "angle_acceleration": _number}
_JOINT_REQUIRED = ("name", "type", "body_i", "body_j")

_POINT_LOAD: _Spec = {"type": _text, "name": _text, "body": _text, "point": _VECTOR3,
                      "force": _VECTOR3, "moment": _VECTOR3}
_SPRING_DAMPER: _Spec = {"type": _text, "name": _text, "body_i": _text, "body_j": _text,
                         "point_i": _VECTOR3, "point_j": _VECTOR3, "stiffness": _number,
                         "damping": _number, "free_length": _number}

_CLEARANCE_PART: _Spec = {"body": _text, "point": _VECTOR3, "axis": _VECTOR3, "radius": _number,
                          "length": _number}
_NORMAL_FORCE: _Spec = {"model": _text, "stiffness": _number, "exponent": _number,
                        "restitution": _number, "minimum_impact_speed": _number}
_FRICTION: _Spec = {"coefficient": _number, "velocity_coefficient": _number}
# The detection options by the library's own list (geometry/option_fields.hpp), as the model
# reader takes them: an option added there is taken here too.
_DETECTION: _Spec = {key: (_flag if isinstance(default, bool) else _number)
                     for key, default in _core._detection_option_defaults().items()}
_LUBRICATION: _Spec = {"viscosity": _number, "cavitation": _text, "method": _text,
                       "grid": _vector(2, _count), "allow_large_grid": _flag,
                       "groove_direction": _VECTOR3,
                       "supply_pressure": _number, "film_thickness_limit": _number,
                       "transition_width": _number}
# The pin of a pin-in-hole joint ("geometry": "pin_in_hole"); its hole is a _CLEARANCE_PART.
_PIN: _Spec = {"body": _text, "point": _VECTOR3, "axis": _VECTOR3, "radius": _number,
               "stops": _list_of({"position": _number, "outer_radius": _number}, ("position", "outer_radius"))}
_CLEARANCE_REVOLUTE: _Spec = {"type": _text, "name": _text, "geometry": _text,
                              "bearing": _object(_CLEARANCE_PART), "journal": _object(_CLEARANCE_PART),
                              "hole": _object(_CLEARANCE_PART), "pin": _object(_PIN),
                              "normal_force": _object(_NORMAL_FORCE), "friction": _object(_FRICTION),
                              "detection": _object(_DETECTION), "lubrication": _object(_LUBRICATION)}

#: Force elements by their "type".
_FORCES: Dict[str, _Spec] = {"point_load": _POINT_LOAD, "spring_damper": _SPRING_DAMPER,
                             "clearance_revolute": _CLEARANCE_REVOLUTE}

_HOLD_POSITION: _Spec = {"body": _text, "components": _strings}
_HOLD_VELOCITY: _Spec = {"body": _text, "component": _text, "value": _number}
_INITIAL_CONDITIONS: _Spec = {"hold_positions": _list_of(_HOLD_POSITION, ("body", "components")),
                              "hold_velocities": _list_of(_HOLD_VELOCITY, ("body", "component", "value"))}
_SOLVER: _Spec = {"start_time": _number, "end_time": _number, "report_step": _number,
                  "relative_tolerance": _number, "absolute_tolerance": _number,
                  "initial_step": _number, "minimum_step": _number, "max_steps": _count,
                  "baumgarte_alpha": _number, "baumgarte_beta": _number}
_OUTPUT: _Spec = {"bodies": _strings, "force_elements": _strings, "decimation": _count}

#: The model's own keys, in the order to_dict() writes them.
_TOP_LEVEL = ("name", "comment", "notes", "gravity", "bodies", "joints", "forces",
              "initial_conditions", "solver", "output")

#: Every position component a hold_positions entry can hold (model_builder.hpp).
ALL_COMPONENTS = ("x", "y", "z", "rx", "ry", "rz")


def _given(**values: Any) -> Dict[str, Any]:
    """The keyword arguments given (not None), in their order: the fields of one object."""
    return {key: value for key, value in values.items() if value is not None}


class Model:
    """A multibody model built from Python calls: the model file of ``clearjoint simulate``.

    >>> m = clearjoint.Model("pendulum", gravity=[0, -9.81, 0])
    >>> m.add_body("bob", mass=1.0, inertia=[1e-3, 1e-3, 1e-3], position=[1, 0, 0])
    >>> m.add_revolute("pivot", "ground", "bob", point_j=[-1, 0, 0], axis_i=[0, 0, 1])
    >>> m.set_solver(end_time=1.0, report_step=1e-3)
    >>> result = clearjoint.simulate(m.to_dict())

    Each ``add_*`` and ``set_*`` method takes the fields of one object of the model file
    (docs/dynamics.md, "Model files") as keyword arguments of the same names; None leaves a field
    out (the file's default). Every method also takes ``comment`` and ``notes``, as every object
    of a file may have them. Bodies are named by their names, the world frame ``"ground"``.

    ``to_dict()``, ``to_json()`` and ``save(path)`` write the model file; ``from_dict(d)`` and
    ``load(path)`` read one back, field for field. ``validate()`` checks the model with the C++
    code that reads model files. Arguments of the wrong type raise TypeError at once, naming the
    field they become (``bodies[1].mass = true: must be a number (not bool)``).
    """

    def __init__(self, name: Optional[str] = None, *, gravity: Optional[Sequence[float]] = None,
                 notes: Optional[str] = None, comment: Optional[str] = None) -> None:
        self._top: Dict[str, Any] = {}
        self._bodies: List[Dict[str, Any]] = []
        self._joints: Optional[List[Dict[str, Any]]] = None
        self._forces: Optional[List[Dict[str, Any]]] = None
        self._initial_conditions: Optional[Dict[str, Any]] = None
        self._solver: Optional[Dict[str, Any]] = None
        self._output: Optional[Dict[str, Any]] = None
        self.name, self.gravity, self.notes, self.comment = name, gravity, notes, comment

    # --- The model's own fields: None leaves them out.

    def _set_top(self, key: str, value: Any, convert: _Converter) -> None:
        if value is None:
            self._top.pop(key, None)
        else:
            self._top[key] = convert(value, key)

    @property
    def name(self) -> Optional[str]:
        """The model's name (the file's "name"; absent: the reader names it after its source)."""
        return self._top.get("name")

    @name.setter
    def name(self, value: Optional[str]) -> None:
        self._set_top("name", value, _text)

    @property
    def gravity(self) -> Optional[List[float]]:
        """The gravity vector in the world frame [m/s^2] (absent: none)."""
        return copy.copy(self._top.get("gravity"))

    @gravity.setter
    def gravity(self, value: Optional[Sequence[float]]) -> None:
        self._set_top("gravity", value, _VECTOR3)

    @property
    def notes(self) -> Optional[str]:
        """The model's notes (free text kept in the file)."""
        return self._top.get("notes")

    @notes.setter
    def notes(self, value: Optional[str]) -> None:
        self._set_top("notes", value, _text)

    @property
    def comment(self) -> Optional[str]:
        """The model's comment (free text kept in the file)."""
        return self._top.get("comment")

    @comment.setter
    def comment(self, value: Optional[str]) -> None:
        self._set_top("comment", value, _text)

    # --- Bodies, joints and force elements: each appended as the next entry of its list.

    def _append(self, section: str, spec: _Spec, fields: Mapping, required: Sequence[str]) -> str:
        entries = getattr(self, "_" + section) or []
        entry = _fields(spec, fields, f"{section}[{len(entries)}]", required)
        setattr(self, "_" + section, entries + [entry])  # nothing changes unless all fields pass
        return entry.get("name", "")

    def add_body(self, name: str, *, mass: float, inertia: Sequence[float], position: Sequence[float],
                 euler_parameters: Optional[Sequence[float]] = None,
                 velocity: Optional[Sequence[float]] = None,
                 angular_velocity: Optional[Sequence[float]] = None,
                 comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A rigid body: mass [kg], principal moments of inertia [kg m^2] about its body axes,
        mass centre position and orientation (Euler parameters, default [1, 0, 0, 0]) in the
        world frame, velocity (world frame) and angular velocity (body frame) at the start.
        Returns the name."""
        return self._append("bodies", _BODY, dict(
            name=name, mass=mass, inertia=inertia, position=position,
            **_given(euler_parameters=euler_parameters, velocity=velocity,
                     angular_velocity=angular_velocity, comment=comment, notes=notes)),
            _BODY_REQUIRED)

    def add_joint(self, name: str, type: str, body_i: str, body_j: str, *,
                  point_i: Optional[Sequence[float]] = None, point_j: Optional[Sequence[float]] = None,
                  axis_i: Optional[Sequence[float]] = None, axis_j: Optional[Sequence[float]] = None,
                  angle_rate: Optional[float] = None, angle_acceleration: Optional[float] = None,
                  comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """An ideal joint of any ``type`` (spherical, revolute, universal, cylindrical,
        translational, fixed, angle_driver) between body_i and body_j, points and axes in each
        body's frame (docs/dynamics.md, "Joints"). The ``add_<type>`` methods take the fields
        their type reads. Returns the name."""
        return self._append("joints", _JOINT, dict(
            name=name, type=type, body_i=body_i, body_j=body_j,
            **_given(point_i=point_i, point_j=point_j, axis_i=axis_i, axis_j=axis_j,
                     angle_rate=angle_rate, angle_acceleration=angle_acceleration,
                     comment=comment, notes=notes)),
            _JOINT_REQUIRED)

    def add_spherical(self, name: str, body_i: str, body_j: str, *,
                      point_i: Optional[Sequence[float]] = None,
                      point_j: Optional[Sequence[float]] = None,
                      comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A spherical joint: point_i on body_i and point_j on body_j coincide (3 equations)."""
        return self.add_joint(name, "spherical", body_i, body_j, point_i=point_i, point_j=point_j,
                              comment=comment, notes=notes)

    def add_revolute(self, name: str, body_i: str, body_j: str, *,
                     point_i: Optional[Sequence[float]] = None,
                     point_j: Optional[Sequence[float]] = None,
                     axis_i: Optional[Sequence[float]] = None, axis_j: Optional[Sequence[float]] = None,
                     comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """An ideal revolute joint: the points coincide and the axes stay on one line (5
        equations); axis_j defaults to axis_i, axis_i to the body's z axis."""
        return self.add_joint(name, "revolute", body_i, body_j, point_i=point_i, point_j=point_j,
                              axis_i=axis_i, axis_j=axis_j, comment=comment, notes=notes)

    def add_universal(self, name: str, body_i: str, body_j: str, *,
                      point_i: Optional[Sequence[float]] = None,
                      point_j: Optional[Sequence[float]] = None,
                      axis_i: Optional[Sequence[float]] = None, axis_j: Optional[Sequence[float]] = None,
                      comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A universal joint: the points coincide and the cross axes axis_i, axis_j stay
        perpendicular (4 equations)."""
        return self.add_joint(name, "universal", body_i, body_j, point_i=point_i, point_j=point_j,
                              axis_i=axis_i, axis_j=axis_j, comment=comment, notes=notes)

    def add_cylindrical(self, name: str, body_i: str, body_j: str, *,
                        point_i: Optional[Sequence[float]] = None,
                        point_j: Optional[Sequence[float]] = None,
                        axis_i: Optional[Sequence[float]] = None,
                        axis_j: Optional[Sequence[float]] = None,
                        comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A cylindrical joint: the axes through the points stay on one line (4 equations)."""
        return self.add_joint(name, "cylindrical", body_i, body_j, point_i=point_i, point_j=point_j,
                              axis_i=axis_i, axis_j=axis_j, comment=comment, notes=notes)

    def add_translational(self, name: str, body_i: str, body_j: str, *,
                          point_i: Optional[Sequence[float]] = None,
                          point_j: Optional[Sequence[float]] = None,
                          axis_i: Optional[Sequence[float]] = None,
                          axis_j: Optional[Sequence[float]] = None,
                          comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A translational (prismatic) joint: cylindrical, with the relative rotation about the
        axis locked at its value at the start (5 equations)."""
        return self.add_joint(name, "translational", body_i, body_j, point_i=point_i,
                              point_j=point_j, axis_i=axis_i, axis_j=axis_j, comment=comment,
                              notes=notes)

    def add_fixed(self, name: str, body_i: str, body_j: str, *,
                  point_i: Optional[Sequence[float]] = None, point_j: Optional[Sequence[float]] = None,
                  comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A fixed joint: the points coincide and the relative orientation stays the one at the
        start (6 equations)."""
        return self.add_joint(name, "fixed", body_i, body_j, point_i=point_i, point_j=point_j,
                              comment=comment, notes=notes)

    def add_angle_driver(self, name: str, body_i: str, body_j: str, *,
                         axis_i: Optional[Sequence[float]] = None,
                         angle_rate: Optional[float] = None,
                         angle_acceleration: Optional[float] = None,
                         comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A driver: body_j turns relative to body_i about axis_i (body_i's frame) by
        angle_rate t + angle_acceleration t^2 / 2 [rad] from its pose at the start (1 equation)."""
        return self.add_joint(name, "angle_driver", body_i, body_j, axis_i=axis_i,
                              angle_rate=angle_rate, angle_acceleration=angle_acceleration,
                              comment=comment, notes=notes)

    def add_point_load(self, name: str, body: str, *, point: Optional[Sequence[float]] = None,
                       force: Optional[Sequence[float]] = None,
                       moment: Optional[Sequence[float]] = None,
                       comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A constant force [N] and moment [N m], world frame, at ``point`` (body frame) of the
        body."""
        return self._append("forces", _POINT_LOAD, dict(
            type="point_load", name=name, body=body,
            **_given(point=point, force=force, moment=moment, comment=comment, notes=notes)),
            ("type", "name", "body"))

    def add_spring_damper(self, name: str, body_i: str, body_j: str, *, stiffness: float,
                          free_length: float, damping: Optional[float] = None,
                          point_i: Optional[Sequence[float]] = None,
                          point_j: Optional[Sequence[float]] = None,
                          comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A linear spring [N/m] and damper [N s/m] between point_i of body_i and point_j of
        body_j (body frames), along the line through them; free_length [m]."""
        return self._append("forces", _SPRING_DAMPER, dict(
            type="spring_damper", name=name, body_i=body_i, body_j=body_j,
            **_given(point_i=point_i, point_j=point_j), stiffness=stiffness,
            **_given(damping=damping), free_length=free_length,
            **_given(comment=comment, notes=notes)),
            ("type", "name", "body_i", "body_j", "stiffness", "free_length"))

    def add_clearance_revolute(self, name: str, *, normal_force: Mapping[str, Any],
                               bearing: Optional[Mapping[str, Any]] = None,
                               journal: Optional[Mapping[str, Any]] = None,
                               geometry: Optional[str] = None,
                               hole: Optional[Mapping[str, Any]] = None,
                               pin: Optional[Mapping[str, Any]] = None,
                               friction: Optional[Mapping[str, Any]] = None,
                               detection: Optional[Mapping[str, Any]] = None,
                               lubrication: Optional[Mapping[str, Any]] = None,
                               comment: Optional[str] = None, notes: Optional[str] = None) -> str:
        """A revolute joint with radial and axial clearance (paper Sections 3-4), a force
        element. Each argument is a dict of the model file's fields (docs/dynamics.md):

        - ``bearing``, ``journal``: ``body``, ``point``, ``axis`` (body frame), ``radius``,
          ``length``;
        - or, with ``geometry="pin_in_hole"`` (docs/dynamics.md), ``hole``: ``body``, ``point``,
          ``axis``, ``radius``, ``length`` and ``pin``: ``body``, ``point``, ``axis``, ``radius``,
          ``stops`` (a list of 0-2 dicts of ``position``, ``outer_radius``);
        - ``normal_force``: ``model`` (hertz, lankarani_nikravesh, hunt_crossley, flores),
          ``stiffness``, ``exponent``, ``restitution``, ``minimum_impact_speed``;
        - ``friction`` (absent: frictionless): ``coefficient``, ``velocity_coefficient``;
        - ``detection``: ``certify``, ``exact_fallback``, ``parallel_angle_tolerance``;
        - ``lubrication`` (absent: a dry joint): ``viscosity``, ``film_thickness_limit``,
          ``transition_width``, ``method``, ``cavitation``, ``grid``, ``allow_large_grid``,
          ``groove_direction``, ``supply_pressure`` (docs/lubrication.md).
        """
        parts = ("hole", "pin") if geometry == "pin_in_hole" else ("bearing", "journal")
        return self._append("forces", _CLEARANCE_REVOLUTE, dict(
            type="clearance_revolute", name=name, normal_force=normal_force,
            **_given(geometry=geometry, bearing=bearing, journal=journal, hole=hole, pin=pin,
                     friction=friction, detection=detection, lubrication=lubrication,
                     comment=comment, notes=notes)),
            ("type", "name") + parts + ("normal_force",))

    # --- Initial conditions, solver and output.

    def set_initial_conditions(self, *, hold_positions: Optional[Sequence[Mapping[str, Any]]] = None,
                               hold_velocities: Optional[Sequence[Mapping[str, Any]]] = None,
                               comment: Optional[str] = None, notes: Optional[str] = None) -> None:
        """Replace the initial conditions: ``hold_positions`` ([{"body", "components"}]) and
        ``hold_velocities`` ([{"body", "component", "value"}]) are kept as given while the others
        are made consistent with the joints (docs/dynamics.md, "Initial conditions")."""
        self._initial_conditions = _fields(_INITIAL_CONDITIONS, _given(
            hold_positions=hold_positions, hold_velocities=hold_velocities, comment=comment,
            notes=notes), "initial_conditions")

    def _hold(self, kind: str, spec: _Spec, fields: Dict[str, Any]) -> None:
        conditions = self._initial_conditions if self._initial_conditions is not None else {}
        entries = conditions.get(kind, [])
        entry = _fields(spec, fields, f"initial_conditions.{kind}[{len(entries)}]")
        self._initial_conditions = conditions
        conditions[kind] = entries + [entry]

    def hold_position(self, body: str, components: Sequence[str] = ALL_COMPONENTS, *,
                      comment: Optional[str] = None, notes: Optional[str] = None) -> None:
        """Keep these position components of the body ("x", "y", "z" and the small rotations
        "rx", "ry", "rz"; default all six) at the given pose when the initial conditions are
        made consistent."""
        self._hold("hold_positions", _HOLD_POSITION,
                   dict(body=body, components=components, **_given(comment=comment, notes=notes)))

    def hold_velocity(self, body: str, component: str, value: float, *,
                      comment: Optional[str] = None, notes: Optional[str] = None) -> None:
        """Prescribe one velocity component of the body at the start ("vx".."vz" world frame
        [m/s], "wx".."wz" [rad/s]); the others are made consistent with the joints."""
        self._hold("hold_velocities", _HOLD_VELOCITY,
                   dict(body=body, component=component, value=value,
                        **_given(comment=comment, notes=notes)))

    def set_solver(self, *, start_time: Optional[float] = None, end_time: Optional[float] = None,
                   report_step: Optional[float] = None, relative_tolerance: Optional[float] = None,
                   absolute_tolerance: Optional[float] = None, initial_step: Optional[float] = None,
                   minimum_step: Optional[float] = None, max_steps: Optional[int] = None,
                   baumgarte_alpha: Optional[float] = None, baumgarte_beta: Optional[float] = None,
                   comment: Optional[str] = None, notes: Optional[str] = None) -> None:
        """Set the integration settings given (times [s], tolerances, step limits, Baumgarte's
        alpha and beta; docs/dynamics.md, "Integration"); the others stay as they are."""
        self._solver = dict(self._solver or {}, **_fields(_SOLVER, _given(
            start_time=start_time, end_time=end_time, report_step=report_step,
            relative_tolerance=relative_tolerance, absolute_tolerance=absolute_tolerance,
            initial_step=initial_step, minimum_step=minimum_step, max_steps=max_steps,
            baumgarte_alpha=baumgarte_alpha, baumgarte_beta=baumgarte_beta, comment=comment,
            notes=notes), "solver"))

    def set_output(self, *, bodies: Optional[Sequence[str]] = None,
                   force_elements: Optional[Sequence[str]] = None, decimation: Optional[int] = None,
                   comment: Optional[str] = None, notes: Optional[str] = None) -> None:
        """Set what a run writes: the ``bodies`` and ``force_elements`` with tables (absent: all
        of each) and ``decimation`` (a row at every k-th report time); the others stay as they
        are."""
        self._output = dict(self._output or {}, **_fields(_OUTPUT, _given(
            bodies=bodies, force_elements=force_elements, decimation=decimation, comment=comment,
            notes=notes), "output"))

    # --- The model file.

    def to_dict(self) -> Dict[str, Any]:
        """The model file as a dict (a new one: changing it leaves the model as it is)."""
        sections = dict(self._top, bodies=self._bodies, joints=self._joints, forces=self._forces,
                        initial_conditions=self._initial_conditions, solver=self._solver,
                        output=self._output)
        return copy.deepcopy({key: sections[key] for key in _TOP_LEVEL if sections.get(key) is not None})

    def to_json(self, *, indent: Optional[int] = 1) -> str:
        """The model file's text (JSON, ``indent`` as json.dumps takes it)."""
        return json.dumps(self.to_dict(), indent=indent, allow_nan=False)

    def validate(self) -> None:
        """Check the model with the C++ code that reads and builds model files: the reader's
        checks of every field, body names resolved, names unique, and the initial conditions made
        consistent (docs/dynamics.md, "Initial conditions"). Raises ValueError naming the field
        as for a file (``bodies[1].name = "rod": used by bodies[0] already``; ``<Model>:
        bodies[1].mass = -1: must be positive``), or clearjoint.SolverError when the joints
        cannot be satisfied at the start."""
        _validate_text(self.to_json(indent=None), _SOURCE)

    def save(self, path: _Path, *, validate: bool = True) -> None:
        """Write the model file (JSON, as models/*.json are written); with ``validate``, only a
        model that ``validate()`` passes."""
        _check_flag(validate, "validate")
        if validate:
            self.validate()
        with open(os.fspath(path), "w", encoding="utf-8") as f:
            f.write(self.to_json() + "\n")

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], *, validate: bool = True) -> "Model":
        """The model of a model-file dict (``json.load`` of a file), field for field:
        ``Model.from_dict(d).to_dict() == d``. With ``validate``, the dict is first checked as
        ``clearjoint.simulate`` checks it (messages start with "<dict>: ")."""
        _check_flag(validate, "validate")
        if not isinstance(data, Mapping):
            raise TypeError(f"model = {type(data).__name__}: must be a dict in the model-file format")
        if validate:
            _validate_text(*_model_text(data))
        return cls._from_mapping(data)

    @classmethod
    def load(cls, path: _Path, *, validate: bool = True) -> "Model":
        """The model of a model file; with ``validate``, checked as ``clearjoint simulate``
        checks the file (messages start with its path)."""
        _check_flag(validate, "validate")
        text, source = _model_text(path)
        if validate:
            _validate_text(text, source)
        return cls._from_mapping(json.loads(text, object_pairs_hook=_refuse_repeated_keys))

    @classmethod
    def _from_mapping(cls, data: Mapping[str, Any]) -> "Model":
        top = _fields({key: _keep for key in _TOP_LEVEL}, data, "")
        model = cls(top.get("name"), gravity=top.get("gravity"), notes=top.get("notes"),
                    comment=top.get("comment"))
        for section, convert in (("bodies", model._read_bodies), ("joints", model._read_joints),
                                 ("forces", model._read_forces)):
            if section in top:
                convert(_items(top[section], section, "a list of dicts"))
        if "initial_conditions" in top:
            model._initial_conditions = _fields(_INITIAL_CONDITIONS, top["initial_conditions"],
                                                "initial_conditions")
        if "solver" in top:
            model._solver = _fields(_SOLVER, top["solver"], "solver")
        if "output" in top:
            model._output = _fields(_OUTPUT, top["output"], "output")
        return model

    def _read_bodies(self, entries: Sequence[Any]) -> None:
        for entry in entries:
            self._append("bodies", _BODY, entry, _BODY_REQUIRED)

    def _read_joints(self, entries: Sequence[Any]) -> None:
        self._joints = self._joints or []
        for entry in entries:
            self._append("joints", _JOINT, entry, _JOINT_REQUIRED)

    def _read_forces(self, entries: Sequence[Any]) -> None:
        self._forces = self._forces or []
        for entry in entries:
            path = f"forces[{len(self._forces)}]"
            kind = entry.get("type") if isinstance(entry, Mapping) else None
            if kind not in _FORCES:
                raise ValueError(f"{path}.type = {_quote(kind)}: unknown force type (known: "
                                 f"{', '.join(_FORCES)}; gravity is the model's gravity vector)")
            self._append("forces", _FORCES[kind], entry, ("type", "name"))

    # --- Comparison and display.

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Model) and self.to_dict() == other.to_dict()

    __hash__ = None  # type: ignore[assignment]  # mutable

    def __repr__(self) -> str:
        counts = ", ".join(f"{len(entries or [])} {section}" for section, entries in
                           (("bodies", self._bodies), ("joints", self._joints), ("forces", self._forces)))
        return f"Model({self.name!r}: {counts})"


def _keep(value: Any, path: str) -> Any:
    """A top-level section, converted by its own reader."""
    return value


def _check_flag(value: Any, name: str) -> None:
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} = {value!r}: must be True or False")


def _refuse_repeated_keys(pairs: List[Tuple[str, Any]]) -> Dict[str, Any]:
    """json.loads' object hook: a key given twice is an error, as for the C++ reader."""
    result: Dict[str, Any] = {}
    for key, value in pairs:
        if key in result:
            raise ValueError(f"{key}: key given twice in one object (each key may appear once)")
        result[key] = value
    return result


def _validate_text(text: str, source: str) -> None:
    """Check a model file's text with the C++ reader and builder of model files: there is no
    check-only entry in the compiled module, and building a Simulator is the cheapest route that
    runs all of them (parse_model and build_model, the initial conditions included) without
    integrating a step."""
    _core.Simulator(text, source)
