# SPDX-License-Identifier: BSD-3-Clause
"""The library's enums as :class:`enum.IntEnum` classes, built from the compiled module's rows of
member names, codes and labels, which are the C++ library's enum tables
(clearjoint/geometry/model/enum_table.hpp): each value is written down once, for every front-end.

Being IntEnums, members compare equal to their codes: ``batch.scenario ==
ContactScenario.beyond_model`` compares element by element, ``np.isin`` works, and
``ContactScenario(13)`` and ``int(ContactScenario.beyond_model)`` convert both ways.
"""
from __future__ import annotations

import enum

from . import _core


def _int_enum(name: str, doc: str, members: list) -> type:
    cls = enum.IntEnum(name, [(member, code) for member, code, _ in members], module="clearjoint",
                       qualname=name)
    listing = "\n".join(f"- ``{member}`` {code}" + (f": {text}" if text else "")
                        for member, code, text in members)
    cls.__doc__ = f"{doc}\n\n{listing}\n"
    return cls


_CLASSES = {name: _int_enum(name, doc, members) for name, doc, members in _core._enum_tables()}

Certainty = _CLASSES["Certainty"]
CertificateReason = _CLASSES["CertificateReason"]
ContactScenario = _CLASSES["ContactScenario"]
ContactType = _CLASSES["ContactType"]
PinInHoleScenario = _CLASSES["PinInHoleScenario"]
ContactBase = _CLASSES["ContactBase"]
CirclePlaneTopology = _CLASSES["CirclePlaneTopology"]
CircleCylinderTopology = _CLASSES["CircleCylinderTopology"]
# Not a result's enum: the clearance joint's output columns, which clearjoint.plot names.
ContactSlot = _CLASSES["ContactSlot"]

# Each table's labels by code, for scenario_label: a PinInHoleScenario member is an int like a
# ContactScenario code, so its class, not its value, says which table labels it.
_LABELS = {name: {code: text for _, code, text in members} for name, _, members in _core._enum_tables()}


def scenario_label(scenario) -> str:
    """The scenario's label for people ("(a) single radial", "one hole edge against the pin",
    "none", ...): a PinInHoleScenario member by the pin-in-hole table, a ContactScenario member or a
    plain code by the paper's (Fig. 2); clearjoint detect writes the key instead."""
    if isinstance(scenario, PinInHoleScenario):
        return _LABELS["PinInHoleScenario"][int(scenario)]
    return _core.scenario_label(scenario)

