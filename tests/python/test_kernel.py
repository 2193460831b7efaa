# SPDX-License-Identifier: BSD-3-Clause
"""The kernel queries: the shipped examples bit for bit against `clearjoint intersect`, single
and batched; broadcasting, threads and bad inputs."""
import json
import math
import pathlib
import struct
import subprocess

import numpy as np
import pytest

import clearjoint

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "rims.jsonl"


def bits(x):
    return struct.pack("<d", math.inf if x is None else float(x))


def same_vector(a, b):
    return [bits(v) for v in a] == [bits(v) for v in b]


def load_examples():
    return [json.loads(line) for line in EXAMPLES.read_text().splitlines() if line.strip()]


def query(example, **overrides):
    """The Python call for one line of rims.jsonl (the circle against a plane or a cylinder)."""
    c = example["circle"]
    options = dict(example.get("options", {}), **overrides)
    if "plane" in example:
        p = example["plane"]
        return clearjoint.intersect_circle_plane(c["center"], c["normal"], c["radius"],
                                                 p["point"], p["normal"], **options)
    w = example["cylinder"]
    return clearjoint.intersect_circle_cylinder(c["center"], c["normal"], c["radius"],
                                                w["axis_point"], w["axis"], w["radius"], **options)


@pytest.fixture(scope="module")
def cli_answers(cli):
    run = subprocess.run([str(cli), "intersect", str(EXAMPLES)], capture_output=True, text=True,
                         check=True)
    return {a["id"]: a for a in map(json.loads, run.stdout.splitlines())}


EXAMPLE_LINES = load_examples()


def assert_crossings_equal(crossings, expected):
    assert len(crossings) == len(expected)
    for crossing, want in zip(crossings, expected):
        assert bits(crossing.angle) == bits(want["angle"])
        assert bits(crossing.angle_error) == bits(want["angle_error"])
        assert same_vector(crossing.point, want["point"])
        assert bits(crossing.point_error) == bits(want["point_error"])
        assert crossing.multiplicity == want["multiplicity"]


@pytest.mark.parametrize("example", EXAMPLE_LINES, ids=[e["id"] for e in EXAMPLE_LINES])
def test_every_shipped_example_equals_the_command_lines_answer_bit_for_bit(example, cli_answers):
    want = cli_answers[example["id"]]
    result = query(example)
    assert result.topology.name == want["topology"]
    assert result.certificate.level.name == want["certificate"]["level"]
    assert result.certificate.reason_text == want["certificate"]["reason"]
    assert_crossings_equal(result.crossings, want["crossings"])
    arcs = ([result.penetration] if result.penetration is not None else []) \
        if "plane" in example else result.penetration_arcs
    assert [(bits(a.begin), bits(a.end), a.full) for a in arcs] == \
        [(bits(a["begin"]), bits(a["end"]), a["full"]) for a in want["penetration_arcs"]]
    if "plane" in example:
        assert result.side == want["side"]
        assert bits(result.max_signed_distance) == bits(want["max_signed_distance"])
        assert bits(result.max_signed_distance_error) == bits(want["max_signed_distance_error"])


def stacked(examples, kind):
    """The examples of one query as batch arguments (one row each)."""
    rows = [e for e in examples if kind in e and not e.get("options")]
    circle = lambda key: np.array([e["circle"][key] for e in rows], dtype=float)
    other = lambda key: np.array([e[kind][key] for e in rows], dtype=float)
    return rows, circle, other


def test_a_batch_of_the_plane_examples_equals_the_single_answers_row_by_row():
    rows, circle, plane = stacked(EXAMPLE_LINES, "plane")
    batch = clearjoint.intersect_circle_plane(circle("center"), circle("normal"), circle("radius"),
                                              plane("point"), plane("normal"))
    assert isinstance(batch, clearjoint.CirclePlaneBatch) and len(batch) == len(rows) >= 3
    for n, example in enumerate(rows):
        single = query(example)
        assert batch.topology[n] == int(single.topology)
        assert batch.side[n] == single.side
        assert batch.certificate[n] == int(single.certificate.level)
        assert batch.certificate_reason[n] == int(single.certificate.reason)
        assert bits(batch.max_signed_distance[n]) == bits(single.max_signed_distance)
        assert bits(batch.max_signed_distance_error[n]) == bits(single.max_signed_distance_error)
        assert batch.has_penetration[n] == (single.penetration is not None)
        if single.penetration is not None:
            assert bits(batch.penetration_begin[n]) == bits(single.penetration.begin)
            assert bits(batch.penetration_end[n]) == bits(single.penetration.end)
            assert batch.penetration_full[n] == single.penetration.full
        assert batch.crossing_count[n] == len(single.crossings)
        for x, crossing in enumerate(single.crossings):
            assert bits(batch.crossing_angle[n, x]) == bits(crossing.angle)
            assert same_vector(batch.crossing_point[n, x], crossing.point)
            assert bits(batch.crossing_point_error[n, x]) == bits(crossing.point_error)
            assert batch.crossing_multiplicity[n, x] == crossing.multiplicity
        assert np.all(np.isnan(batch.crossing_angle[n, len(single.crossings):]))


def test_a_batch_of_the_cylinder_examples_equals_the_single_answers_row_by_row():
    rows, circle, wall = stacked(EXAMPLE_LINES, "cylinder")
    batch = clearjoint.intersect_circle_cylinder(circle("center"), circle("normal"), circle("radius"),
                                                 wall("axis_point"), wall("axis"), wall("radius"))
    assert isinstance(batch, clearjoint.CircleCylinderBatch) and len(batch) == len(rows) >= 3
    for n, example in enumerate(rows):
        single = query(example)
        assert batch.topology[n] == int(single.topology)
        assert batch.certificate[n] == int(single.certificate.level)
        assert batch.certificate_reason[n] == int(single.certificate.reason)
        assert batch.arc_count[n] == len(single.penetration_arcs)
        for k, arc in enumerate(single.penetration_arcs):
            assert bits(batch.arc_begin[n, k]) == bits(arc.begin)
            assert bits(batch.arc_end[n, k]) == bits(arc.end)
            assert batch.arc_full[n, k] == arc.full
        assert batch.crossing_count[n] == len(single.crossings)
        for x, crossing in enumerate(single.crossings):
            assert bits(batch.crossing_angle[n, x]) == bits(crossing.angle)
            assert bits(batch.crossing_angle_error[n, x]) == bits(crossing.angle_error)
            assert same_vector(batch.crossing_point[n, x], crossing.point)
            assert batch.crossing_multiplicity[n, x] == crossing.multiplicity


# The batch columns of a result's list and optional fields: a prefix shared by their columns.
# Every other field of as_dict() (which is written through the result's field list) is a column
# of its own name.
BATCH_COLUMN_PREFIXES = {"crossings": "crossing_", "penetration": "penetration_", "penetration_arcs": "arc_"}


@pytest.mark.parametrize("kind", ["plane", "cylinder"])
def test_every_field_of_a_single_answer_has_its_batch_column(kind):
    # The batch columns are written by hand (bindings/python/src/kernel.cpp); a field added to the
    # result's field list is in as_dict() and must be in the batch too.
    rows, circle, other = stacked(EXAMPLE_LINES, kind)
    call = clearjoint.intersect_circle_plane if kind == "plane" else clearjoint.intersect_circle_cylinder
    arguments = ([other("point"), other("normal")] if kind == "plane"
                 else [other("axis_point"), other("axis"), other("radius")])
    batch = call(circle("center"), circle("normal"), circle("radius"), *arguments)
    columns = batch.fields()
    for key in query(rows[0]).as_dict():
        prefix = BATCH_COLUMN_PREFIXES.get(key)
        assert key in columns or (prefix and any(c.startswith(prefix) for c in columns)), \
            f"{type(batch).__name__} has no column for the field {key}"


def rims_against_a_wall(count, seed):
    """Journal rims of Table 2 (mm) in random poses near the wall of a bearing on the z axis."""
    rng = np.random.default_rng(seed)
    normal = np.column_stack([rng.uniform(-0.02, 0.02, (count, 2)), np.ones(count)])
    center = np.column_stack([rng.uniform(-0.15, 0.15, (count, 2)), rng.uniform(9.8, 10.0, count)])
    return center, normal


@pytest.mark.parametrize("threads", [2, 3])
def test_any_thread_count_gives_the_answers_of_one_thread(threads):
    center, normal = rims_against_a_wall(20000, seed=1)
    wall = ([0, 0, 0], [0, 0, 1], 10.0)
    one = clearjoint.intersect_circle_cylinder(center, normal, 9.9, *wall, threads=1)
    assert one == clearjoint.intersect_circle_cylinder(center, normal, 9.9, *wall, threads=threads)
    assert {int(t) for t in one.topology} >= {0, 2}  # inside and crossing both occur
    base = ([0, 0, 10.0], [0, 0, 1])
    one = clearjoint.intersect_circle_plane(center, normal, 9.9, *base, threads=1)
    assert one == clearjoint.intersect_circle_plane(center, normal, 9.9, *base, threads=threads)


def test_a_radius_per_row_broadcasts_with_single_vectors():
    radii = np.array([0.5, 1.0, 2.0])
    batch = clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], radii, [0.2, 0, 0], [0, 0, 1], 1.0)
    assert [clearjoint.CircleCylinderTopology(int(t)) for t in batch.topology] == [
        clearjoint.CircleCylinderTopology.inside, clearjoint.CircleCylinderTopology.crossing,
        clearjoint.CircleCylinderTopology.outside]
    assert batch.crossing_count[1] == 2 and batch.arc_count[1] == 1


@pytest.mark.parametrize("call, error, message", [
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], [1.0, -1.0], [0, 0, 0], [1, 0, 0]),
     ValueError, r"^circle_radius\[1\] = -1: must be positive$"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [[0, 0, 1], [0, 0, 0]], 1.0, [0, 0, 0], [1, 0, 0]),
     ValueError, r"^circle_normal\[1\] = \[0, 0, 0\]: must not be the zero vector$"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, math.nan, 0], [1, 0, 0]),
     ValueError, r"^plane_point = \[0, nan, 0\]: every component must be finite$"),
    (lambda: clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], 1.0, [[0, 0, 0], [0, 0, math.inf]],
                                                  [0, 0, 1], 1.0),
     ValueError, r"^cylinder_point\[1\] = \[0, 0, inf\]: every component must be finite$"),
    (lambda: clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [0, 0, 0], 1.0),
     ValueError, r"^cylinder_axis = \[0, 0, 0\]: must not be the zero vector$"),
    (lambda: clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [0, 0, 1], 0.0),
     ValueError, r"^cylinder_radius = 0: must be positive$"),
    (lambda: clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], [[1.0]], [0, 0, 0], [0, 0, 1], 1.0),
     ValueError, r"circle_radius: shape \(1, 1\) must be \(\) or \(N,\)"),
    (lambda: clearjoint.intersect_circle_plane(np.zeros((3, 3)), [0, 0, 1], np.ones(2), [0, 0, 0], [1, 0, 0]),
     ValueError, r"circle_radius has 2 rows and circle_center 3"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], "one", [0, 0, 0], [1, 0, 0]),
     TypeError, r"circle_radius: must be numbers"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], None, [0, 0, 0], [1, 0, 0]),
     TypeError, r"^circle_radius: must be numbers \(int or float\), got NoneType$"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], True, [0, 0, 0], [1, 0, 0]),
     TypeError, r"^circle_radius: must be numbers \(int or float\), got bool$"),
    (lambda: clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [0, 0, 1], 1 + 0j),
     TypeError, r"^cylinder_radius: must be numbers \(int or float\), got complex$"),
    (lambda: clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [0, 0, 1], 1.0,
                                                  certify=None),
     TypeError, r"^certify = None: must be True or False$"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [1, 0, 0],
                                               exact_fallback=2),
     TypeError, r"^exact_fallback = 2: must be True or False$"),
    (lambda: clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [1, 0, 0],
                                               threads=np.float64(2)),
     TypeError, r"^threads = 2.0: must be an int or None$"),
])
def test_bad_inputs_raise_naming_the_argument_and_row(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_single_results_read_well():
    plane = clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [1, 0, 0])
    assert repr(plane) == ("CirclePlaneIntersection(two_crossings, side=0, crossings=2, "
                           "max_signed_distance=1.0, certified)")
    assert repr(plane.penetration).startswith("RimArc(begin=")
    assert repr(plane.crossings[0]).startswith("RimCrossing(angle=")
