# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.detect_pin_in_hole: the closed forms of issue 48, the command line's answers bit for
bit, batches row by row, the scenario enum from the library's table, and bad inputs."""
import json
import math
import os
import pathlib
import struct
import subprocess

import numpy as np
import pytest

import clearjoint
from clearjoint import PinInHoleDimensions, PinInHoleScenario

# A hole of radius 10 and length 20 along z at the origin, a pin of radius 9.9 (cr = 0.1), heads
# at -10.5 and +10.5 of outer radius 16 (ca = 0.5): the joint of
# tests/geometry/joint/test_detect_pin_in_hole_contacts.cpp.
STOPS = ((-10.5, 16.0), (10.5, 16.0))
DIMS = dict(hole_radius=10.0, hole_length=20.0, pin_radius=9.9, stops=STOPS)
HOLE = ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0])
#: The closed forms are evaluated in double and the detection on inputs of size ~10: a few ulps
#: of 10 each; 1e-12, the issue's figure, leaves a wide margin.
CLOSED_FORM_TOLERANCE = 1e-12


def bits(x):
    """The double's bit pattern; the command line writes an unknown bound (inf) as null."""
    return struct.pack("<d", math.inf if x is None else float(x))


def detect(center, axis, **options):
    return clearjoint.detect_pin_in_hole(PinInHoleDimensions(**DIMS), HOLE[0], HOLE[1], center, axis,
                                         **options)


def tilted_axis(t):
    return [0.0, math.sin(t), math.cos(t)]


def test_an_aligned_pin_offset_radially_leans_along_the_bore_in_a_line_contact():
    # The hole's mid circle point (10, 0, 0) is 10 - 0.15 from the pin's axis: 0.05 inside the pin.
    answer = detect([0.15, 0.0, 0.0], [0.0, 0.0, 1.0])
    assert answer.scenario == PinInHoleScenario.line
    assert answer.aligned
    [line] = answer.contacts
    assert line.type == clearjoint.ContactType.radial and line.base == clearjoint.ContactBase.mid
    assert abs(line.depth - 0.05) < CLOSED_FORM_TOLERANCE
    assert np.allclose(line.point_bearing, [10.0, 0.0, 0.0], rtol=0, atol=CLOSED_FORM_TOLERANCE)
    assert np.allclose(line.normal, [1.0, 0.0, 0.0], rtol=0, atol=CLOSED_FORM_TOLERANCE)
    assert answer.certificate.level != clearjoint.Certainty.uncertain


def test_a_pin_tilted_about_the_holes_centre_bears_on_both_edges_at_opposite_sides():
    # Edge A's deepest point (0, 10, 10) is 10 sqrt(1 - sin 2t) from the axis (0, sin t, cos t).
    t = 0.0125
    answer = detect([0.0, 0.0, 0.0], tilted_axis(t))
    assert answer.scenario == PinInHoleScenario.both_edges_opposite
    assert [c.base for c in answer.contacts] == [clearjoint.ContactBase.a, clearjoint.ContactBase.b]
    depth = 9.9 - 10.0 * math.sqrt(1.0 - math.sin(2.0 * t))
    for contact in answer.contacts:
        assert abs(contact.depth - depth) < CLOSED_FORM_TOLERANCE
        assert abs(contact.depth - depth) <= contact.depth_error + 1e-15


def test_a_pin_pushed_axially_bears_on_one_stop_flush_on_its_face():
    # Pushed 0.75 along +z: the stop at -10.5 comes to -9.75, 0.25 beyond face B (z = -10).
    answer = detect([0.0, 0.0, 0.75], [0.0, 0.0, 1.0])
    assert answer.scenario == PinInHoleScenario.face
    [face] = answer.contacts
    assert face.type == clearjoint.ContactType.axial and face.base == clearjoint.ContactBase.b
    assert abs(face.depth - 0.25) < CLOSED_FORM_TOLERANCE
    assert np.allclose(face.normal, [0.0, 0.0, 1.0], rtol=0, atol=CLOSED_FORM_TOLERANCE)


def poses():
    """The closed-form poses and 200 random ones around them (seeded): offsets up to 0.25,
    tilts up to 0.03 rad, axial pushes up to 0.8, so that edges, lines, stops and beyond-model
    answers all occur."""
    rng = np.random.default_rng(48)
    centers = [[0.15, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.75], [0.0, 0.0, 0.52]]
    axes = [[0.0, 0.0, 1.0], tilted_axis(0.0125), [0.0, 0.0, 1.0], tilted_axis(0.005)]
    for _ in range(200):
        centers.append((rng.uniform(-0.25, 0.25, 3) * [1.0, 1.0, 3.2]).tolist())
        tilt = rng.uniform(-0.03, 0.03, 2)
        axes.append([tilt[0], tilt[1], 1.0] if rng.random() < 0.8 else [0.0, 0.0, 1.0])
    return centers, axes


@pytest.fixture(scope="module")
def cli_answers(cli):
    """`clearjoint detect` on every pose, "joint": "pin_in_hole", in round-trip form."""
    centers, axes = poses()
    lines = [json.dumps({"id": n, "joint": "pin_in_hole",
                         "hole": {"radius": DIMS["hole_radius"], "length": DIMS["hole_length"],
                                  "center": HOLE[0], "axis": HOLE[1]},
                         "pin": {"radius": DIMS["pin_radius"], "center": c, "axis": a,
                                 "stops": [{"position": p, "outer_radius": r} for p, r in STOPS]}})
             for n, (c, a) in enumerate(zip(centers, axes))]
    run = subprocess.run([str(cli), "detect"], input="\n".join(lines) + "\n", text=True,
                         capture_output=True, check=True)
    return [json.loads(line) for line in run.stdout.splitlines()]


def test_every_pose_equals_the_command_lines_answer_bit_for_bit(cli_answers):
    centers, axes = poses()
    scenarios = set()
    for center, axis, want in zip(centers, axes, cli_answers):
        result = detect(center, axis)
        scenarios.add(result.scenario)
        assert want["joint"] == "pin_in_hole"
        assert result.scenario.name == want["scenario"]
        assert result.aligned == want["aligned"]
        assert result.certificate.level.name == want["certificate"]
        assert result.certificate.reason_text == want["certificate_reason"]
        assert len(result.contacts) == len(want["contacts"]) == result.contact_count
        for contact, expected in zip(result.contacts, want["contacts"]):
            assert contact.type.name == expected["type"]
            assert contact.base.name == expected["base"]
            for key in ("depth", "depth_error", "point_journal_error", "point_bearing_error"):
                assert bits(getattr(contact, key)) == bits(expected[key]), key
            for key in ("point_journal", "point_bearing", "normal"):
                assert [bits(v) for v in getattr(contact, key)] == [bits(v) for v in expected[key]], key
            assert len(contact.crossings) == len(expected["crossings"])
            for crossing, point, error in zip(contact.crossings, expected["crossings"],
                                              expected["crossing_errors"]):
                assert [bits(v) for v in crossing.point] == [bits(v) for v in point]
                assert bits(crossing.point_error) == bits(error)
            assert contact.certificate.level.name == expected["certificate"]
            assert contact.certificate.reason_text == expected["certificate_reason"]
    # The comparison covers contacts of every kind, not only free poses.
    assert {PinInHoleScenario.none, PinInHoleScenario.line, PinInHoleScenario.face,
            PinInHoleScenario.both_edges_opposite, PinInHoleScenario.one_stop} <= scenarios


def test_a_batch_gives_the_single_pose_answers_row_by_row():
    centers, axes = poses()
    batch = clearjoint.detect_pin_in_hole(PinInHoleDimensions(**DIMS), HOLE[0], HOLE[1],
                                          np.array(centers), np.array(axes))
    assert len(batch) == len(centers)
    for row, center, axis in zip(batch, centers, axes):
        single = detect(center, axis)
        assert row.as_dict() == single.as_dict()
        assert [bits(c.depth) for c in row.contacts] == [bits(c.depth) for c in single.contacts]


def test_the_scenario_enum_is_the_librarys_table_and_the_answer_schemas_list():
    schema_dir = pathlib.Path(os.environ["CLEARJOINT_TESTS_DIR"]).parent / "docs" / "schema"
    schema = json.loads((schema_dir / "detect-answer.schema.json").read_text())
    listed = schema["$defs"]["pin_in_hole_answer"]["properties"]["scenario"]["enum"]
    assert [member.name for member in PinInHoleScenario] == listed
    assert [int(member) for member in PinInHoleScenario] == list(range(len(listed)))


def test_results_and_dimensions_read_well():
    dims = PinInHoleDimensions(**DIMS)
    assert repr(dims) == ("PinInHoleDimensions(hole_radius=10.0, hole_length=20.0, pin_radius=9.9, "
                          "stops=((-10.5, 16.0), (10.5, 16.0)))")
    assert dims.stops == STOPS
    assert abs(dims.radial_clearance - 0.1) < 1e-15 and dims.axial_clearance == 0.5
    free = PinInHoleDimensions(hole_radius=10.0, hole_length=20.0, pin_radius=9.9, stops=())
    assert free.axial_clearance == math.inf
    answer = detect([0.0, 0.0, 0.75], [0.0, 0.0, 1.0])
    assert repr(answer).startswith("PinInHoleContacts(face, aligned, certified; axial at b depth 0.25")
    assert json.loads(json.dumps(answer.as_dict()))["scenario"] == int(PinInHoleScenario.face)


@pytest.mark.parametrize("field, value, message", [
    ("pin_radius", 10.0, "PinInHoleDimensions.pin_radius = 10: must be smaller than hole_radius"),
    ("hole_length", -20.0, "PinInHoleDimensions.hole_length = -20: must be positive"),
    ("hole_radius", math.nan, "PinInHoleDimensions.hole_radius = nan"),
    ("stops", ((-10.5, 16.0), (5.0, 16.0)), "PinInHoleDimensions.stops[1].position = 5: the stop lies inside the hole"),
    ("stops", ((10.5, 9.0),), "PinInHoleDimensions.stops[0].outer_radius = 9: must be larger than hole_radius"),
    ("stops", ((-10.5, 16.0), (10.5, 16.0), (11.0, 16.0)), "PinInHoleDimensions.stops = ((-10.5, 16.0), (10.5, 16.0), (11.0, 16.0)): at most 2 stops"),
])
def test_bad_dimensions_raise_value_error_naming_the_field(field, value, message):
    with pytest.raises(ValueError) as error:
        PinInHoleDimensions(**dict(DIMS, **{field: value}))
    assert message in str(error.value)


@pytest.mark.parametrize("stops, message", [
    ("ab", "PinInHoleDimensions.stops = 'ab': must be a sequence of (position, outer_radius) pairs"),
    ((10.5,), "PinInHoleDimensions.stops[0] = 10.5: must be a (position, outer_radius) pair"),
    ((("a", 16.0),), "PinInHoleDimensions.stops[0].position"),
])
def test_stops_that_are_not_pairs_of_numbers_raise_type_error_naming_the_entry(stops, message):
    with pytest.raises(TypeError) as error:
        PinInHoleDimensions(**dict(DIMS, stops=stops))
    assert message in str(error.value)


def test_a_bad_pose_raises_value_error_naming_the_argument_and_row():
    with pytest.raises(ValueError, match=r"pin_axis = \[0, 0, 0\]: must not be the zero vector"):
        detect([0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    axes = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match=r"pin_axis\[1\] = \[0, 0, 0\]: must not be the zero vector"):
        clearjoint.detect_pin_in_hole(PinInHoleDimensions(**DIMS), HOLE[0], HOLE[1], [0.0, 0.0, 0.0], axes)


def test_dimensions_of_the_papers_joint_are_refused_with_a_type_error():
    paper = clearjoint.JointDimensions(bearing_radius=10.0, bearing_length=20.0, journal_radius=9.9,
                                       journal_length=19.8)
    with pytest.raises(TypeError, match="must be a clearjoint.PinInHoleDimensions"):
        clearjoint.detect_pin_in_hole(paper, HOLE[0], HOLE[1], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0])


def test_scenario_label_names_a_pin_in_hole_member_from_the_pin_in_hole_table():
    labels = {code: text for _, code, text in next(
        members for name, _, members in clearjoint._core._enum_tables() if name == "PinInHoleScenario")}
    for member in clearjoint.PinInHoleScenario:
        assert clearjoint.scenario_label(member) == labels[int(member)], member
    # A plain code, or a ContactScenario member, is still the paper's (Fig. 2).
    assert clearjoint.scenario_label(1) == clearjoint.scenario_label(clearjoint.ContactScenario(1)) == "(a) single radial"


def test_dimensions_without_stops_are_a_free_sliding_pin_and_a_nan_size_is_named():
    free = clearjoint.PinInHoleDimensions(hole_radius=10.0, hole_length=20.0, pin_radius=9.9)
    assert free.stops == ()
    answer = clearjoint.detect_pin_in_hole(free, [0, 0, 0], [0, 0, 1], [0, 0, 30.0], [0, 0, 1])
    assert answer.contact_count == 0
    with pytest.raises(ValueError, match="pin_radius = nan"):
        clearjoint.detect_pin_in_hole(clearjoint.PinInHoleDimensions(hole_radius=10.0, hole_length=20.0,
                                                                     pin_radius=float("nan")),
                                      [0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 0, 1])
