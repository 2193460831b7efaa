# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.lubrication: lubricated journal bearings (docs/lubrication.md).

- ``bearing_characteristics(eccentricity_ratio, width_ratio, *, motion="rotation",
  cavitation=None, method="grid", grid=None, allow_large_grid=False)``: what bearing handbooks tabulate for a plain
  360-degree journal bearing: the Sommerfeld number, the attitude angle, the side flow and the
  peak pressure, from the film solutions of the C++ library ``clearjoint::lubrication``.

A lubricated clearance joint in a multibody model is a ``"lubrication"`` object in its
``clearance_revolute`` force (docs/dynamics.md).
"""
from dataclasses import dataclass
from typing import Optional, Tuple

from .. import _core

__all__ = ["BearingCharacteristics", "bearing_characteristics"]


@dataclass(frozen=True)
class BearingCharacteristics:
    """A bearing's non-dimensional characteristics (lubrication/bearing_characteristics.hpp).

    ``sommerfeld_number``: So = F psi^2 / (B D eta omega), psi = c / R the relative clearance (for
    squeeze, d eps / dt in place of omega); Raimondi & Boyd's S is 1 / (2 pi So).
    ``attitude_angle``: beta [rad], from the load to the line of centres.
    ``side_flow_variable``: 2 pi Q_s / (R c omega B), Raimondi & Boyd's Q_s / (R c N B).
    ``max_pressure_ratio``: p_max / (F / (B D)).
    ``iterations``, ``converged``: the grid's linear solves and whether its active set settled
    (closed forms: 0 and True). ``cavitation`` and ``grid`` say what was solved.
    """
    sommerfeld_number: float
    attitude_angle: float
    side_flow_variable: float
    max_pressure_ratio: float
    iterations: int
    converged: bool
    cavitation: str
    grid: Optional[Tuple[int, int]]


def bearing_characteristics(eccentricity_ratio: float, width_ratio: float, *,
                            motion: str = "rotation", cavitation: Optional[str] = None,
                            method: str = "grid", grid: Optional[Tuple[int, int]] = None,
                            allow_large_grid: bool = False) -> BearingCharacteristics:
    """The characteristics of a plain journal bearing at eccentricity ratio eps = e / c.

    eccentricity_ratio: eps, 0 or in [1e-100, 1). width_ratio: B / D in [1e-50, 1e50]. Both real
    numbers (int, float or a NumPy integer or floating scalar; not bool, str, complex or None).
    motion: ``"rotation"`` (steady spin) or ``"squeeze"`` (pure approach along the line of
    centres). method: ``"grid"`` (finite width, ReynoldsGridSolver), ``"short"`` (Ocvirk),
    ``"long"`` (Sommerfeld) or ``"table"`` (the grid's half-Sommerfeld film tabulated over eps up
    to 0.98, built on first use for the bearing and grid and kept, also in the file cache
    ``$CLEARJOINT_CACHE_DIR`` (else ``$XDG_CACHE_HOME/clearjoint``, else ``~/.cache/clearjoint``;
    set and empty: none); docs/lubrication.md gives its measured error and the cache). cavitation: ``"half_sommerfeld"`` or ``"mass_conserving"``; None takes
    mass_conserving for the grid (fed at ambient pressure along the thickest film, as Raimondi &
    Boyd's tables) and half_sommerfeld, the only one they have, for the closed forms and the table.
    grid: (cells around, cells across), integers (NumPy's too), at least (8, 2); None: 96 x 24,
    which keeps So within about 1 % of Raimondi & Boyd. A grid whose estimated cost is above the
    solver's limits (64 MiB of band or 1e9 operations a linear solve, about half a second) is
    refused with the estimate unless allow_large_grid is True.

    Raises TypeError naming the argument for a value of the wrong type, ValueError naming it for
    a value out of range, an unknown name or a grid refused.
    """
    d = _core.bearing_characteristics(eccentricity_ratio, width_ratio, motion, cavitation, method, grid,
                                      allow_large_grid)
    return BearingCharacteristics(**d)
