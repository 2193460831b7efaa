# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint: certified contact detection for spatial revolute joints with clearance.

The Python interface of the clearjoint C++ library, which implements F. Marques, F. Isaac,
N. Dourado, P. Flores, "An enhanced formulation to model spatial revolute joints with radial and
axial clearances", Mechanism and Machine Theory 116 (2017) 123-144. docs/python.md is the guide.

- ``detect(dims, bearing_center, bearing_axis, journal_center, journal_axis)``: the contacts of
  a journal in its bearing, for one pose or a NumPy batch (Section 3, eqs. 3-26);
- ``detect_pin_in_hole(dims, hole_center, hole_axis, pin_center, pin_axis)``: the same for a
  pin longer than the hole it passes through, its play limited by stops (docs/contact-detection.md,
  "The pin-in-hole joint");
- ``intersect_circle_plane``, ``intersect_circle_cylinder``: the certified kernel queries
  (eqs. 11-15, 16-21);
- ``simulate(model)``: run a multibody model file (or dict) and get its time series as arrays,
  or write them into a folder (CSV or HDF5); ``read_run(folder)`` reads one back;
- ``Simulator(model)``: step a model yourself (controls, co-simulation, loads between steps);
- ``Model``: build a model from Python calls, written and read as a model file.

Lengths are in one unit of the caller's choice (metres in the shipped models), angles in radians,
vectors in the world frame.
"""
from ._core import (Certificate, CircleCylinderIntersection, CirclePlaneIntersection, Contact,
                    JointContacts, JointDimensions, PinInHoleContacts, PinInHoleDimensions, RimArc,
                    RimCrossing, SolverError, __version__,
                    certificate_reason_text)
from ._enums import (Certainty, CertificateReason, CircleCylinderTopology, CirclePlaneTopology,
                     ContactBase, ContactScenario, ContactType, PinInHoleScenario, scenario_label)
from ._detect import (MAX_CONTACTS, CircleCylinderBatch, CirclePlaneBatch, DetectionBatch,
                      PinInHoleBatch, detect, detect_pin_in_hole, intersect_circle_cylinder,
                      intersect_circle_plane)
from ._simulate import SimulationResult, read_run, simulate
from ._simulator import Simulator
from .model import Model

__all__ = [
    "MAX_CONTACTS", "Certainty", "Certificate", "CertificateReason", "CircleCylinderBatch",
    "CircleCylinderIntersection", "CircleCylinderTopology", "CirclePlaneBatch",
    "CirclePlaneIntersection", "CirclePlaneTopology", "Contact", "ContactBase", "ContactScenario",
    "ContactType", "DetectionBatch", "JointContacts", "JointDimensions", "Model", "PinInHoleBatch",
    "PinInHoleContacts", "PinInHoleDimensions", "PinInHoleScenario", "RimArc", "RimCrossing",
    "SimulationResult", "Simulator", "SolverError", "__version__", "certificate_reason_text", "detect",
    "detect_pin_in_hole",    "intersect_circle_cylinder", "intersect_circle_plane", "read_run", "scenario_label", "simulate",
]
