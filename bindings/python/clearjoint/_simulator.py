# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.Simulator: a model stepped from Python, for controls, co-simulation and a caller's
own event logic (dynamics/include/clearjoint/dynamics/simulator.hpp)."""
from __future__ import annotations

import os
import threading
from typing import Any, Dict, List, Mapping, Union

import numpy as np

from . import _core
from ._simulate import Model, _model_text

# The kinds of NumPy dtype read as real numbers: signed and unsigned integers and floats. Booleans
# ('b'), complex numbers ('c'), text ('U', 'S') and objects ('O') are refused, not converted:
# np.asarray(..., dtype=float64) would turn "0.5" into 0.5 and True into 1.0, and drop the
# imaginary part of a complex number with only a warning.
_REAL_KINDS = "iuf"


def _real_number(value: Any, name: str) -> float:
    """`value` as a float if it is a real number (int, float, NumPy integer or floating; not bool,
    str or complex): TypeError naming `name` otherwise."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} = {value!r}: must be a real number")
    try:
        return float(value)
    except OverflowError:
        raise ValueError(f"{name} = {value!r}: too large for a double") from None


def _real_array(value: Any, name: str) -> np.ndarray:
    """`value` as a float64 array if every entry is a real number: TypeError naming `name` for
    booleans, text, complex numbers or objects."""
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as error:  # ragged nesting
        raise TypeError(f"{name}: must be an array of real numbers ({error})") from None
    if array.dtype.kind not in _REAL_KINDS:
        raise TypeError(f"{name}: must be an array of real numbers, not of {array.dtype} "
                        f"({np.array2string(array.ravel()[:4], threshold=4)}...)")
    with np.errstate(over="raise"):
        try:
            return np.ascontiguousarray(array, dtype=np.float64)
        except (OverflowError, FloatingPointError):
            raise ValueError(f"{name}: holds integers too large for a double") from None


class Simulator:
    """A model built once (consistent initial conditions) and integrated step by step.

    >>> sim = clearjoint.Simulator("models/slider_crank_spatial_clearance.json")
    >>> while not sim.finished:
    ...     omega = sim.body_state("crank")["angular_velocity_body"][2]
    ...     sim.apply_load("crank", force=[0, 0, 0], moment=[0, 0, 0.5 * (2.0 - omega)])
    ...     sim.advance_to(min(sim.time + 1e-3, sim.end_time))
    ...     for impact in sim.take_impacts(): print(impact)

    ``time``, ``end_time``, ``finished``; ``state`` (the packed state vector, a copy) and
    ``set_state(y)``; ``body_state(name)`` (position, Euler parameters, velocity in the world
    frame, angular velocity in the body frame); ``apply_load(body, force, moment)`` (world
    frame, at the mass centre, held until set again) and ``clear_loads()``; ``step()`` (one
    accepted step) and ``advance_to(t)`` (steps until t, the last one shortened to end there;
    t in [time, end_time]); ``take_impacts()`` (the impacts recorded since the last call: time,
    joint, slot, impact_speed); ``statistics()``. Integration runs without the GIL; Ctrl-C stops
    ``advance_to`` within about 0.1 s with KeyboardInterrupt, leaving the simulator at a step.
    ``joint_state(name)`` gives a clearance joint's contacts, forces and film at the current state.
    A simulator shared by threads runs one of these calls at a time.
    """

    def __init__(self, model: Model) -> None:
        text, source = _model_text(model)
        self._core = _core.Simulator(text, source)
        # One operation at a time: step() and advance_to() run without the GIL, so two threads
        # sharing a simulator would otherwise integrate the same state at once and leave it
        # depending on their interleaving. Lock.acquire releases the GIL while it waits, so a
        # waiting thread cannot block advance_to's signal checks.
        self._lock = threading.Lock()

    @property
    def time(self) -> float:
        with self._lock:
            return self._core.time

    @property
    def end_time(self) -> float:
        return self._core.end_time

    @property
    def finished(self) -> bool:
        with self._lock:
            return self._core.finished

    @property
    def state(self) -> np.ndarray:
        with self._lock:
            return self._core.state

    def set_state(self, state: Any) -> None:
        """Continue from `state` (as wide as ``state``: real numbers, each body's Euler parameters
        of norm 1 within 1e-6). A refused state changes nothing."""
        values = _real_array(state, "state")
        with self._lock:
            self._core.set_state(values)

    def body_state(self, body: str) -> Dict[str, np.ndarray]:
        with self._lock:
            return self._core.body_state(body)

    def joint_state(self, name: str) -> Dict[str, Any]:
        """The clearance joint `name` at the current state, as its joint table has it: ``contacts``
        (a JointContacts, as detect gives; a PinInHoleContacts, as detect_pin_in_hole gives, for a
        pin-in-hole joint), ``force_on_journal`` and ``moment_on_journal`` (world
        frame, N and N m about the journal's point: contacts plus film), each contact's
        ``contact_force_on_journal`` (rows in the order of ``contacts``), ``slots`` (per contact
        slot: active, depth, approach_speed, impact_speed, normal_force, friction_force; eqs.
        23-24), ``film`` (None for a dry joint; else regime (0 dry, 1 film, 2 blend, as the force
        table's film.regime), weight, min_thickness, eccentricity_ratio, attitude_angle,
        max_pressure, force_on_journal, moment_on_journal, power), ``axis_angle`` and the rim
        centres ``rim_a_in_bearing``/``rim_b_in_bearing`` (bearing frame u, v, a). The bearing
        body gets the opposite force."""
        if not isinstance(name, str):
            raise TypeError(f"name = {name!r}: must be a joint's name (a str)")
        with self._lock:
            return self._core.joint_state(name)

    def apply_load(self, body: str, force: Any = (0.0, 0.0, 0.0), moment: Any = (0.0, 0.0, 0.0)) -> None:
        force_values, moment_values = _real_array(force, "force"), _real_array(moment, "moment")
        with self._lock:
            self._core.apply_load(body, force_values, moment_values)

    def clear_loads(self) -> None:
        with self._lock:
            self._core.clear_loads()

    def step(self) -> None:
        with self._lock:
            self._core.step()

    def advance_to(self, t: float) -> None:
        target = _real_number(t, "t")
        with self._lock:
            self._core.advance_to(target)

    def take_impacts(self) -> List[Dict[str, Any]]:
        with self._lock:
            return self._core.take_impacts()

    def statistics(self) -> Dict[str, int]:
        with self._lock:
            return self._core.statistics()

    def __repr__(self) -> str:
        return f"Simulator(time={self.time!r}, end_time={self.end_time!r}, finished={self.finished!r})"
