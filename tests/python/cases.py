# SPDX-License-Identifier: BSD-3-Clause
"""The joint configurations of the C++ detection tests (tests/geometry/joint/), rebuilt with the
same double arithmetic: Python's math.sin and math.cos are the C library's, as std::sin and
std::cos are, so every pose has the very bits the C++ tests use."""
import math
from dataclasses import dataclass
from typing import Tuple

import clearjoint
from clearjoint import ContactScenario as S

Vector = Tuple[float, float, float]

# tilted_journal_scenarios.hpp: Table 2 in millimetres (cr = ca = 0.1) and its two variants.
TABLE2 = (10.0, 20.0, 9.9, 19.8)
WIDE_RADIAL_CLEARANCE = (10.0, 20.0, 9.0, 19.8)
LONG_AXIAL_CLEARANCE = (10.0, 20.0, 9.9, 19.0)
BEARING_ON_Z = ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0))


def dims(d):
    return clearjoint.JointDimensions(bearing_radius=d[0], bearing_length=d[1],
                                      journal_radius=d[2], journal_length=d[3])


def tilted(y0: float, z0: float, tilt: float):
    """TiltedJournal::pose(): centre (0, y0, z0), axis (0, sin tilt, cos tilt)."""
    return (0.0, y0, z0), (0.0, math.sin(tilt), math.cos(tilt))


@dataclass
class Case:
    name: str
    dimensions: tuple
    journal: tuple  # (centre, axis)
    scenario: S
    bearing: tuple = BEARING_ON_Z
    parallel_angle_tolerance: float = 0.0
    #: The command line reads magnitudes in [1e-150, 1e150] only (docs/command-line.md).
    command_line: bool = True


def _cases():
    c = [
        # kMisalignedCases
        Case("none", TABLE2, tilted(0.0, 0.0, 0.005), S.none),
        Case("a", TABLE2, tilted(0.08, 0.0, 0.005), S.single_radial),
        Case("a_at_b", TABLE2, tilted(-0.08, 0.0, 0.005), S.single_radial),
        Case("b", TABLE2, tilted(0.0, 0.08, 0.005), S.single_axial),
        Case("b_at_b", TABLE2, tilted(0.0, -0.08, 0.005), S.single_axial),
        Case("c", LONG_AXIAL_CLEARANCE, tilted(0.0, 0.0, 0.015), S.radial_at_both_bases),
        Case("d", WIDE_RADIAL_CLEARANCE, tilted(0.0, 0.0, 0.02), S.axial_at_both_bases),
        Case("e", TABLE2, tilted(0.08, 0.08, 0.005), S.radial_and_axial_same_base),
        Case("f", TABLE2, tilted(0.08, -0.08, 0.005), S.radial_and_axial_opposite_bases),
        Case("g", TABLE2, tilted(0.0, 0.04, 0.013), S.two_radial_one_axial),
        Case("h", TABLE2, tilted(0.04, 0.0, 0.013), S.one_radial_two_axial),
        Case("i", TABLE2, tilted(0.0, 0.0, 0.013), S.all_four),
        # all_cases() of test_detect_contacts.cpp: the aligned ones
        Case("aligned none", TABLE2, ((0.01, 0.02, 0.03), (0.0, 0.0, 1.0)), S.none),
        Case("j", TABLE2, ((0.0, 0.15, 0.02), (0.0, 0.0, 1.0)), S.line),
        Case("k", TABLE2, ((0.03, 0.04, 0.13), (0.0, 0.0, 1.0)), S.face),
        Case("l", TABLE2, ((0.0, 0.15, -0.13), (0.0, 0.0, -1.0)), S.line_and_face),
        Case("aligned beyond", TABLE2, ((0.0, 0.25, 0.0), (0.0, 0.0, 1.0)), S.beyond_model),
        # The single-purpose tests of test_detect_contacts.cpp
        Case("centred aligned", TABLE2, ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0)), S.none),
        Case("exactly parallel non-unit axes", TABLE2, ((0.0, 0.0, 0.0), (-0.5, -1.5, -3.5)), S.none,
             bearing=((0.0, 0.0, 0.0), (1.0, 3.0, 7.0))),
        Case("one ulp from parallel", TABLE2,
             ((0.0, 0.0, 0.0), (-0.5, -1.5, math.nextafter(-3.5, 0.0))), S.none,
             bearing=((0.0, 0.0, 0.0), (1.0, 3.0, 7.0))),
        Case("tiny parallel axes", TABLE2, ((0.0, 0.0, 0.0), (-0.5, -1.5, -3.5)), S.none,
             bearing=((0.0, 0.0, 0.0), (2.0**-500, 3 * 2.0**-500, 7 * 2.0**-500)),
             command_line=False),
        Case("nearly parallel", TABLE2, tilted(0.15, 0.0, 1e-6), S.radial_at_both_bases),
        Case("nearly parallel within tolerance", TABLE2, tilted(0.15, 0.0, 1e-6), S.line,
             parallel_angle_tolerance=1e-5),
        Case("deep misaligned", TABLE2, tilted(0.2, 0.0, 0.005), S.beyond_model),
        Case("four wall crossings", (10.0, 20.0, 9.9, 2.0), tilted(1.0 - math.sin(0.5), 0.0, 0.5),
             S.beyond_model),
        Case("rim wholly beyond a base", TABLE2, tilted(0.0, 0.5, 0.005), S.beyond_model),
        Case("rims wholly beyond the wall", TABLE2,
             ((10.0 + 9.9 + 1e-3, 0.0, 0.0), (math.sin(1e-3), 0.0, math.cos(1e-3))), S.beyond_model),
    ]
    # PutsTheJournalPointAtTheArcMiddle...: y0 = 1.0, 1.01, ... accumulated as the C++ loop does.
    y0 = 1.0
    while y0 <= 1.8:
        c.append(Case(f"arc middle y0={y0!r}", TABLE2, tilted(y0, 0.0, 0.001), S.beyond_model))
        y0 += 0.01
    return c


CASES = _cases()
