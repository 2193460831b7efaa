# SPDX-License-Identifier: BSD-3-Clause
"""The one table of contact-scenario colours: every figure of a run (``clearjoint plot``), the
viewer page (``clearjoint view``, which receives this table from Python) and the docs' figures
take the colour of a scenario from here, so that a legend read once reads everywhere.

Scenarios are the paper's Fig. 2 cases, by their :class:`clearjoint.ContactScenario` code
(``force_<joint>.csv`` column ``scenario``): 0 none, 1-9 (a)-(i) misaligned, 10-12 (j)-(l)
parallel axes, 13 beyond the model. Free flight is a light grey so that the contacts stand out;
the three parallel-axis cases are darker shades of (a), (b) and their pair, because a line
contact is the aligned limit of a rim on the wall (a) and a face contact that of a rim on a base
(b); beyond the model is black, the colour of a warning.

A pin-in-hole joint (``"geometry": "pin_in_hole"``, docs/dynamics.md) writes
:class:`clearjoint.PinInHoleScenario` codes in the same column: its names and colours are
PIN_IN_HOLE_SCENARIO_COLOURS, chosen by the joint's geometry (every function here takes it; a run
whose model is unknown is read as the paper's joint). Its colours follow the same logic: edge
contacts are the blues and greens of rims on the wall, stop contacts the orange and red of rims
on a base, the aligned cases darker shades, beyond the model black.
"""
from typing import Dict, List, Optional

# Hex strings: matplotlib and the browser's canvas both read them.
SCENARIO_COLOURS: Dict[int, str] = {
    0: "#c8c8c8",   # none: free flight
    1: "#1f77b4",   # (a) one rim against the wall
    2: "#ff7f0e",   # (b) one rim against a base
    3: "#2ca02c",   # (c) both rims against the wall
    4: "#d62728",   # (d) each rim against its base
    5: "#9467bd",   # (e) one rim against the wall and the base on its side
    6: "#8c564b",   # (f) one rim against the wall, the other against its base
    7: "#e377c2",   # (g) both rims against the wall, one against a base
    8: "#bcbd22",   # (h) one rim against the wall, both against their bases
    9: "#17becf",   # (i) both rims against the wall and their bases
    10: "#0b3d6b",  # (j) line: parallel axes, journal along the wall
    11: "#a34a00",  # (k) face: parallel axes, a journal base flat on a bearing base
    12: "#5a2d82",  # (l) line and face
    13: "#000000",  # beyond the paper's model
}

#: The model file's ``geometry`` of a clearance joint (docs/dynamics.md): the paper's journal in a
#: bearing (the default when a model does not say) and the pin through a hole.
JOURNAL_BEARING = "journal_bearing"
PIN_IN_HOLE = "pin_in_hole"

PIN_IN_HOLE_SCENARIO_COLOURS: Dict[int, str] = {
    0: "#c8c8c8",   # none: free flight
    1: "#1f77b4",   # one hole edge against the pin
    2: "#2ca02c",   # both edges, at opposite sides (tilt)
    3: "#17becf",   # both edges, on one side
    4: "#0b3d6b",   # line: parallel axes, the pin along the bore
    5: "#ff7f0e",   # one stop against its link face
    6: "#d62728",   # both stops against their faces
    7: "#a34a00",   # face: a stop flush on its link face
    8: "#9467bd",   # edge and stop contacts together
    9: "#5a2d82",   # line and face
    10: "#000000",  # beyond the model
}

#: Colour for a code outside the table (a newer library than this module).
UNKNOWN_SCENARIO_COLOUR = "#ff00ff"


def _geometry_tables(geometry: Optional[str]):
    """(enum class name, colours) of a joint geometry; None and unknown names: the paper's."""
    if geometry == PIN_IN_HOLE:
        return "PinInHoleScenario", PIN_IN_HOLE_SCENARIO_COLOURS
    return "ContactScenario", SCENARIO_COLOURS


def _labels(enum_name: str) -> Dict[int, str]:
    """code -> label of one of the library's enum tables (the C++ table's labels)."""
    from .. import _core
    for name, _, members in _core._enum_tables():
        if name == enum_name:
            return {code: text for _, code, text in members}
    return {}


def scenario_colour(code: int, geometry: Optional[str] = None) -> str:
    """The colour of a scenario code of a joint of ``geometry`` (default: the paper's
    :class:`clearjoint.ContactScenario`)."""
    return _geometry_tables(geometry)[1].get(int(code), UNKNOWN_SCENARIO_COLOUR)


def scenario_name(code: int, geometry: Optional[str] = None) -> str:
    """The library's label of a scenario code of a joint of ``geometry`` ("(a) single radial",
    "one hole edge against the pin", "none", ...), or "scenario N" for a code the library does
    not know."""
    return _labels(_geometry_tables(geometry)[0]).get(int(code), f"scenario {int(code)}")


def scenario_table(geometry: Optional[str] = None) -> List[dict]:
    """Every scenario of the library's table for ``geometry`` as ``{"code", "label", "colour"}``,
    in code order (the viewer's legend)."""
    labels = _labels(_geometry_tables(geometry)[0])
    return [{"code": code, "label": label, "colour": scenario_colour(code, geometry)}
            for code, label in sorted(labels.items())]
