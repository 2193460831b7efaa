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
"""
from typing import Dict, List

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

#: Colour for a code outside the table (a newer library than this module).
UNKNOWN_SCENARIO_COLOUR = "#ff00ff"


def scenario_colour(code: int) -> str:
    """The colour of a :class:`clearjoint.ContactScenario` code."""
    return SCENARIO_COLOURS.get(int(code), UNKNOWN_SCENARIO_COLOUR)


def scenario_name(code: int) -> str:
    """The library's label of a scenario code ("(a) single radial", "none", ...), or "scenario N"
    for a code the library does not know."""
    from .. import ContactScenario, scenario_label
    try:
        return scenario_label(ContactScenario(int(code)))
    except ValueError:
        return f"scenario {int(code)}"


def scenario_table() -> List[dict]:
    """Every scenario of the library's table as ``{"code", "label", "colour"}``, in code order
    (the viewer's legend)."""
    from .._enums import ContactScenario
    return [{"code": int(scenario), "label": scenario_name(scenario), "colour": scenario_colour(scenario)}
            for scenario in ContactScenario]
