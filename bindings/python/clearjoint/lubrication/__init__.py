# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.lubrication: lubricated journal bearings (docs/lubrication.md).

- ``bearing_characteristics(eccentricity_ratio, width_ratio, *, motion="rotation",
  cavitation=None, method="grid", grid=None)``: what bearing handbooks tabulate for a plain
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
                            method: str = "grid",
                            grid: Optional[Tuple[int, int]] = None) -> BearingCharacteristics:
    """The characteristics of a plain journal bearing at eccentricity ratio eps = e / c.

    eccentricity_ratio: eps in [0, 1). width_ratio: B / D > 0.
    motion: ``"rotation"`` (steady spin) or ``"squeeze"`` (pure approach along the line of
    centres). method: ``"grid"`` (finite width, ReynoldsGridSolver), ``"short"`` (Ocvirk) or
    ``"long"`` (Sommerfeld). cavitation: ``"half_sommerfeld"`` or ``"mass_conserving"``; None
    takes mass_conserving for the grid (fed at ambient pressure along the thickest film, as
    Raimondi & Boyd's tables) and half_sommerfeld, the only one they have, for the closed forms.
    grid: (cells around, cells across), at least (8, 2); None: 96 x 24, which keeps So within
    about 1 % of Raimondi & Boyd.

    Raises ValueError naming the argument for a value out of range or an unknown name.
    """
    if grid is not None:
        try:
            around, across = grid
        except (TypeError, ValueError):
            raise ValueError("grid = %r: must be a pair (cells around, cells across)" % (grid,)) from None
        for name, value in (("grid[0]", around), ("grid[1]", across)):
            if isinstance(value, bool) or not isinstance(value, int):
                raise ValueError("%s = %r: must be a whole number of cells" % (name, value))
        grid = (around, across)
    d = _core.bearing_characteristics(float(eccentricity_ratio), float(width_ratio), motion,
                                      cavitation, method, grid)
    return BearingCharacteristics(**d)
