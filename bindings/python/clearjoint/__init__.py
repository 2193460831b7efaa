# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint: certified contact detection for spatial revolute joints with clearance.

The Python interface of the clearjoint C++ library, which implements F. Marques, F. Isaac,
N. Dourado, P. Flores, "An enhanced formulation to model spatial revolute joints with radial and
axial clearances", Mechanism and Machine Theory 116 (2017) 123-144. docs/python.md is the guide.

- ``simulate(model)``: run a multibody model file (or dict) and get its time series as arrays.

Lengths are in one unit of the caller's choice (metres in the shipped models), angles in radians.
"""
from ._core import SolverError, __version__
from ._simulate import SimulationResult, simulate

__all__ = ["SimulationResult", "SolverError", "__version__", "simulate"]
