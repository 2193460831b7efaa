# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.detect: the C++ tests' scenario cases bit for bit, batches of mixed shapes,
broadcasting, threads, and bad inputs."""
import inspect
import json
import math
import pickle
import re
import struct
import subprocess

import numpy as np
import pytest

import clearjoint
from batch_rows import assert_row_equals_single
from cases import CASES, TABLE2, dims

CASE_IDS = [c.name for c in CASES]
CLI_CASES = [c for c in CASES if c.command_line]


def bits(x):
    """The double's bit pattern; the command line writes an unknown bound (inf) as null."""
    return struct.pack("<d", math.inf if x is None else float(x))


def same_vector(a, b):
    return [bits(v) for v in a] == [bits(v) for v in b]


def detect_case(case, **options):
    return clearjoint.detect(dims(case.dimensions), case.bearing[0], case.bearing[1],
                             case.journal[0], case.journal[1],
                             parallel_angle_tolerance=case.parallel_angle_tolerance, **options)


@pytest.fixture(scope="module")
def cli_answers(cli):
    """`clearjoint detect` on every case: the library's answers, printed in round-trip form."""
    lines = []
    for case in CLI_CASES:
        d = case.dimensions
        lines.append(json.dumps({
            "id": case.name,
            "bearing": {"radius": d[0], "length": d[1], "center": case.bearing[0],
                        "axis": case.bearing[1]},
            "journal": {"radius": d[2], "length": d[3], "center": case.journal[0],
                        "axis": case.journal[1]},
            "options": {"parallel_angle_tolerance": case.parallel_angle_tolerance}}))
    run = subprocess.run([str(cli), "detect"], input="\n".join(lines) + "\n", text=True,
                         capture_output=True, check=True)
    answers = [json.loads(line) for line in run.stdout.splitlines()]
    return {a["id"]: a for a in answers}


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
def test_every_scenario_case_of_the_cpp_tests_has_its_scenario(case):
    assert detect_case(case).scenario == case.scenario


@pytest.mark.parametrize("case", CLI_CASES, ids=[c.name for c in CLI_CASES])
def test_every_scenario_case_equals_the_command_lines_answer_bit_for_bit(case, cli_answers):
    expected = cli_answers[case.name]
    result = detect_case(case)
    assert result.aligned == expected["aligned"]
    assert result.certificate.level.name == expected["certificate"]
    assert result.certificate.reason_text == expected["certificate_reason"]
    assert (result.certificate.reason == clearjoint.CertificateReason.none) == (expected["certificate_reason"] == "")
    assert len(result.contacts) == len(expected["contacts"])
    for contact, want in zip(result.contacts, expected["contacts"]):
        # One spelling: the command line writes the members' names.
        assert contact.type.name == want["type"]
        assert contact.base.name == want["base"]
        assert bits(contact.depth) == bits(want["depth"])
        assert bits(contact.depth_error) == bits(want["depth_error"])
        assert same_vector(contact.point_journal, want["point_journal"])
        assert bits(contact.point_journal_error) == bits(want["point_journal_error"])
        assert same_vector(contact.point_bearing, want["point_bearing"])
        assert bits(contact.point_bearing_error) == bits(want["point_bearing_error"])
        assert same_vector(contact.normal, want["normal"])
        assert len(contact.crossings) == len(want["crossings"])
        for crossing, point, error in zip(contact.crossings, want["crossings"],
                                          want["crossing_errors"]):
            assert same_vector(crossing.point, point)
            assert bits(crossing.point_error) == bits(error)
        assert contact.certificate.level.name == want["certificate"]
        assert contact.certificate.reason_text == want["certificate_reason"]


def test_a_batch_of_every_table2_case_equals_the_single_pose_answers_row_by_row():
    cases = [c for c in CASES if c.dimensions == TABLE2 and c.parallel_angle_tolerance == 0.0]
    batch = clearjoint.detect(dims(TABLE2), [c.bearing[0] for c in cases],
                              [c.bearing[1] for c in cases], [c.journal[0] for c in cases],
                              [c.journal[1] for c in cases])
    assert isinstance(batch, clearjoint.DetectionBatch) and len(batch) == len(cases)
    assert batch.contact_start[-1] == len(batch.depth) == batch.contact_count.sum()
    for n, case in enumerate(cases):
        assert_row_equals_single(batch, n, detect_case(case))


def realistic_poses(count, seed):
    """Bearings anywhere within 0.2 m, any axis; journals tilted up to ~1.5 clearances' worth
    and offset up to 1.5 clearances (Table 2 in metres): about half the poses touch."""
    rng = np.random.default_rng(seed)
    bearing_center = rng.uniform(-0.2, 0.2, (count, 3))
    bearing_axis = rng.normal(size=(count, 3))
    bearing_axis /= np.linalg.norm(bearing_axis, axis=1)[:, None]
    helper = np.where(np.abs(bearing_axis[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]])
    p = np.cross(bearing_axis, helper)
    p /= np.linalg.norm(p, axis=1)[:, None]
    q = np.cross(bearing_axis, p)
    tilt = rng.uniform(0.0, 0.01, count)[:, None]
    lean = rng.uniform(0.0, 2 * np.pi, count)[:, None]
    journal_axis = np.cos(tilt) * bearing_axis + np.sin(tilt) * (np.cos(lean) * p + np.sin(lean) * q)
    radial = rng.uniform(0.0, 1.5e-4, count)[:, None]
    toward = rng.uniform(0.0, 2 * np.pi, count)[:, None]
    axial = rng.uniform(-1.5e-4, 1.5e-4, count)[:, None]
    journal_center = (bearing_center + radial * (np.cos(toward) * p + np.sin(toward) * q)
                      + axial * bearing_axis)
    return bearing_center, bearing_axis, journal_center, journal_axis


METRES = clearjoint.JointDimensions(bearing_radius=0.01, bearing_length=0.02,
                                    journal_radius=0.0099, journal_length=0.0198)


def test_realistic_poses_reach_most_scenarios():
    batch = clearjoint.detect(METRES, *realistic_poses(4000, seed=1))
    found = set(batch.scenarios())
    assert clearjoint.ContactScenario.none in found
    assert clearjoint.ContactScenario.single_radial in found
    assert len(found) >= 6, found


def test_a_batch_of_realistic_poses_equals_the_single_pose_answers_row_by_row():
    poses = realistic_poses(300, seed=2)
    batch = clearjoint.detect(METRES, *poses)
    for n in range(300):
        single = clearjoint.detect(METRES, *(p[n] for p in poses))
        assert_row_equals_single(batch, n, single)


@pytest.mark.parametrize("batched", [(0,), (1,), (2,), (3,), (0, 2), (1, 3), (0, 1, 2, 3)])
def test_mixed_shapes_broadcast_the_single_rows_over_the_batched_ones(batched):
    poses = realistic_poses(50, seed=3)
    args = [p if k in batched else p[7] for k, p in enumerate(poses)]
    batch = clearjoint.detect(METRES, *args)
    assert len(batch) == 50
    tiled = [p if k in batched else np.tile(p[7], (50, 1)) for k, p in enumerate(poses)]
    assert batch == clearjoint.detect(METRES, *tiled)
    for n in (0, 7, 49):
        assert_row_equals_single(batch, n, clearjoint.detect(METRES, *(a[n] for a in tiled)))


def test_strided_fortran_ordered_and_float32_arrays_give_the_answers_of_contiguous_float64():
    poses = realistic_poses(200, seed=12)
    contiguous = clearjoint.detect(METRES, *poses)
    wide = [np.repeat(p, 2, axis=0)[::2] for p in poses]  # every other row of a larger array
    assert not wide[0].flags.c_contiguous
    assert clearjoint.detect(METRES, *wide) == contiguous
    fortran = [np.asfortranarray(p) for p in poses]
    assert clearjoint.detect(METRES, *fortran) == contiguous
    single = [p.astype(np.float32) for p in poses]
    assert clearjoint.detect(METRES, *single) == clearjoint.detect(
        METRES, *(p.astype(np.float64) for p in single))


def test_a_fixed_bearing_broadcasts_over_journal_poses_given_as_lists_and_integers():
    batch = clearjoint.detect(dims(TABLE2), [0, 0, 0], [0, 0, 1],
                              [[0, 0, 0], [0, 0.15, 0.02], [0.03, 0.04, 0.13]], [0, 0, 1])
    assert batch.scenarios() == [clearjoint.ContactScenario.none, clearjoint.ContactScenario.line,
                                 clearjoint.ContactScenario.face]


def test_a_batch_of_one_returns_arrays_and_a_single_pose_returns_an_object():
    one = clearjoint.detect(METRES, *(p[:1] for p in realistic_poses(1, seed=4)))
    assert isinstance(one, clearjoint.DetectionBatch) and len(one) == 1
    single = clearjoint.detect(METRES, *(p[0] for p in realistic_poses(1, seed=4)))
    assert isinstance(single, clearjoint.JointContacts)
    assert_row_equals_single(one, 0, single)


def test_an_empty_batch_gives_empty_arrays():
    empty = np.empty((0, 3))
    batch = clearjoint.detect(METRES, empty, empty, empty, empty)
    assert len(batch) == 0 and batch.contact_start.tolist() == [0] and batch.depth.shape == (0,)
    assert batch.padded("depth").shape == (0, 6)


@pytest.mark.parametrize("threads", [2, 3, 8])
def test_any_thread_count_gives_the_answers_of_one_thread(threads):
    poses = realistic_poses(20000, seed=5)
    assert clearjoint.detect(METRES, *poses, threads=threads) == clearjoint.detect(METRES, *poses, threads=1)


def test_the_default_thread_count_gives_the_answers_of_one_thread():
    poses = realistic_poses(20000, seed=6)
    assert clearjoint.detect(METRES, *poses) == clearjoint.detect(METRES, *poses, threads=1)


def test_padded_lays_a_contact_field_out_per_pose_with_empty_slots_filled():
    batch = clearjoint.detect(METRES, *realistic_poses(500, seed=7))
    depth = batch.padded("depth")
    assert depth.shape == (500, 6)
    counts = np.sum(~np.isnan(depth), axis=1)
    assert np.array_equal(counts, batch.contact_count)
    n = int(np.argmax(batch.contact_count))
    start = batch.contact_start[n]
    assert np.array_equal(depth[n, :batch.contact_count[n]], batch.depth[start:start + batch.contact_count[n]])
    assert batch.padded("point_journal").shape == (500, 6, 3)
    assert batch.padded("contact_type")[n, 5] == -1 or batch.contact_count[n] == 6
    with pytest.raises(ValueError, match="field = 'scenario': must be one of the contact fields"):
        batch.padded("scenario")


def test_certify_false_gives_the_same_contacts_marked_uncertain():
    poses = realistic_poses(2000, seed=8)
    proved = clearjoint.detect(METRES, *poses)
    plain = clearjoint.detect(METRES, *poses, certify=False)
    assert np.all(plain.certificate == int(clearjoint.Certainty.uncertain))
    assert np.all(plain.certificate_reason == int(clearjoint.CertificateReason.certificate_switched_off))
    assert clearjoint.certificate_reason_text(clearjoint.CertificateReason.certificate_switched_off) == \
        "certificate switched off"
    assert np.array_equal(plain.scenario, proved.scenario)


def test_a_batch_pickles():
    batch = clearjoint.detect(METRES, *realistic_poses(100, seed=9))
    assert pickle.loads(pickle.dumps(batch)) == batch


def test_results_read_well():
    case = next(c for c in CASES if c.name == "e")
    result = detect_case(case)
    assert repr(result) == ("JointContacts((e) radial and axial at the same base, certified; "
                            f"radial at a depth {result.contacts[0].depth!r}, "
                            f"axial at a depth {result.contacts[1].depth!r})")
    assert repr(result.contacts[0]).startswith("Contact(radial at a, depth=")
    assert repr(dims(TABLE2)) == ("JointDimensions(bearing_radius=10.0, bearing_length=20.0, "
                                  "journal_radius=9.9, journal_length=19.8)")
    batch = clearjoint.detect(METRES, *realistic_poses(3, seed=9))
    assert repr(batch).startswith("DetectionBatch(3 rows: scenario, aligned, certificate, certificate_reason")


# ---- bad inputs ----------------------------------------------------------------------------------

def bad_batch(row, argument, value, count=10):
    poses = [np.array(p) for p in realistic_poses(count, seed=10)]
    index = ["bearing_center", "bearing_axis", "journal_center", "journal_axis"].index(argument)
    poses[index][row] = value
    return poses


@pytest.mark.parametrize("argument, value, message", [
    ("journal_center", [np.nan, 0, 0], r"journal_center\[3\] = \[nan, 0, 0\]: every component must be finite"),
    ("journal_axis", [0, 0, 0], r"journal_axis\[3\] = \[0, 0, 0\]: must not be the zero vector"),
    ("bearing_center", [0, np.inf, 0], r"bearing_center\[3\] = \[0, inf, 0\]: every component must be finite"),
    ("bearing_axis", [0, 0, 0], r"bearing_axis\[3\] = \[0, 0, 0\]: must not be the zero vector"),
])
def test_a_bad_value_raises_value_error_naming_the_argument_and_row(argument, value, message):
    with pytest.raises(ValueError, match=message):
        clearjoint.detect(METRES, *bad_batch(3, argument, value))


@pytest.mark.parametrize("threads", [1, 2, 5])
def test_the_first_bad_row_is_reported_whatever_the_thread_count(threads):
    poses = bad_batch(15000, "journal_axis", [0, 0, 0], count=20000)
    poses[3][5000] = [0, 0, 0]
    with pytest.raises(ValueError, match=r"journal_axis\[5000\] = "):
        clearjoint.detect(METRES, *poses, threads=threads)


def test_a_bad_broadcast_row_is_named_without_an_index():
    poses = realistic_poses(5, seed=11)
    with pytest.raises(ValueError, match=r"^bearing_axis = \[0, 0, 0\]: must not be the zero vector$"):
        clearjoint.detect(METRES, poses[0], [0, 0, 0], poses[2], poses[3])


def test_a_bad_single_pose_raises_value_error_naming_the_argument():
    with pytest.raises(ValueError, match=r"^journal_center = \[nan, 0, 0\]: every component must be finite$"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], [np.nan, 0, 0], [0, 0, 1])


@pytest.mark.parametrize("shape", [(2,), (4,), (3, 2), (2, 3, 3), ()])
def test_a_pose_argument_of_another_shape_raises_value_error(shape):
    with pytest.raises(ValueError, match=r"journal_center: shape \(.*\) must be \(3,\) or \(N, 3\)"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], np.zeros(shape), [0, 0, 1])


def test_a_batch_too_large_to_copy_raises_memory_error_naming_the_argument():
    # A broadcast view of 10^12 rows holds no memory; as contiguous float64 it would take 24 TB.
    huge = np.broadcast_to(np.zeros(3), (10**12, 3))
    with pytest.raises(MemoryError, match=r"journal_center: shape \(1000000000000, 3\) does not fit in memory"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], huge, [0, 0, 1])


def test_batched_arguments_of_different_lengths_raise_value_error_naming_both():
    with pytest.raises(ValueError, match=r"journal_axis has 4 rows and journal_center 5: batched "
                                         r"arguments must have the same length N"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], np.zeros((5, 3)), np.ones((4, 3)))


def test_arguments_that_are_not_numbers_raise_type_error():
    with pytest.raises(TypeError, match="bearing_axis: must be numbers"):
        clearjoint.detect(METRES, [0, 0, 0], ["x", "y", "z"], [0, 0, 0], [0, 0, 1])


@pytest.mark.parametrize("tolerance", [-1.0, math.pi / 2, math.nan])
def test_a_parallel_angle_tolerance_outside_its_range_raises_value_error(tolerance):
    with pytest.raises(ValueError, match=r"parallel_angle_tolerance = .*: must lie in \[0, pi/2\) radians"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], np.zeros((2, 3)), [0, 0, 1],
                          parallel_angle_tolerance=tolerance)


@pytest.mark.parametrize("threads, error, message", [
    (0, ValueError, "threads = 0: must be at least 1"),
    (-2, ValueError, "threads = -2: must be at least 1"),
    (-2**70, ValueError, f"threads = {-2**70}: must be at least 1"),
    ("2", TypeError, "threads = '2': must be an int or None"),
    (2.0, TypeError, "threads = 2.0: must be an int or None"),
    (True, TypeError, "threads = True: must be an int or None"),
    (np.bool_(True), TypeError, "threads = True: must be an int or None"),
])
def test_a_bad_thread_count_raises(threads, error, message):
    with pytest.raises(error, match=message):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], np.zeros((2, 3)), [0, 0, 1], threads=threads)


@pytest.mark.parametrize("field, value, message", [
    ("bearing_radius", -1.0, r"JointDimensions.bearing_radius = -1: must be positive"),
    ("journal_length", math.nan, r"JointDimensions.journal_length = nan: must be finite"),
    ("journal_radius", 10.0, r"JointDimensions.journal_radius = 10: must be smaller than bearing_radius = 10"),
    ("journal_length", 25.0, r"JointDimensions.journal_length = 25: must be smaller than bearing_length = 20"),
])
def test_bad_dimensions_raise_value_error_naming_the_field(field, value, message):
    values = dict(bearing_radius=10.0, bearing_length=20.0, journal_radius=9.9, journal_length=19.8)
    values[field] = value
    with pytest.raises(ValueError, match=message):
        clearjoint.JointDimensions(**values)


def test_dimensions_take_keyword_arguments_only():
    with pytest.raises(TypeError):
        clearjoint.JointDimensions(10.0, 20.0, 9.9, 19.8)
    d = dims(TABLE2)
    assert (d.radial_clearance, d.axial_clearance) == (10.0 - 9.9, 0.5 * (20.0 - 19.8))
    assert pickle.loads(pickle.dumps(d)).journal_radius == 9.9


@pytest.mark.parametrize("threads", [np.int64(2), np.uint8(3), 2**70, 10**6])
def test_any_integer_is_a_thread_count_and_huge_ones_are_capped(threads):
    poses = realistic_poses(3000, seed=13)
    assert clearjoint.detect(METRES, *poses, threads=threads) == clearjoint.detect(METRES, *poses, threads=1)


# ---- arguments NumPy would coerce: refused ---------------------------------------------------------

@pytest.mark.parametrize("value, shown", [
    (np.array(["2020-01-01", "2020-01-02", "2020-01-03"], dtype="datetime64[D]"), "an array of datetime64"),
    (np.array([0, 0, 1 + 1e-9j]), "an array of complex128"),
    ([0, 0, 1j], r"list \(dtype complex128\)"),
    (np.array([False, False, True]), "an array of bool"),
    ([False, False, True], r"list \(dtype bool\)"),
    (["0", "0", "1"], r"list \(dtype <U1\)"),
    ([0, None, 1], "list"),
    (None, "NoneType"),
])
def test_values_that_are_not_real_numbers_raise_type_error_naming_the_argument(value, shown):
    with pytest.raises(TypeError, match=f"^journal_axis: must be numbers \\(int or float\\), got {shown}"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], [0, 0, 0], value)


def test_a_masked_array_with_masked_values_raises_and_one_without_gives_its_data():
    poses = list(realistic_poses(20, seed=14))
    masked = np.ma.masked_array(poses[2], mask=np.zeros_like(poses[2], dtype=bool))
    masked.mask[5, 1] = True
    with pytest.raises(ValueError, match="journal_center: a masked array with masked values"):
        clearjoint.detect(METRES, poses[0], poses[1], masked, poses[3])
    masked.mask[5, 1] = False
    assert clearjoint.detect(METRES, poses[0], poses[1], masked, poses[3]) == clearjoint.detect(METRES, *poses)


@pytest.mark.parametrize("option", ["certify", "exact_fallback"])
@pytest.mark.parametrize("value", [None, 2, 1, "yes"])
def test_a_switch_that_is_not_true_or_false_raises_type_error(option, value):
    with pytest.raises(TypeError, match=f"^{option} = {value!r}: must be True or False$"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 0, 1], **{option: value})


def test_numpy_bools_are_switches():
    single = clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 0, 1], certify=np.bool_(False))
    assert single.certificate.level == clearjoint.Certainty.uncertain


@pytest.mark.parametrize("value", [True, None, "0.1", 1j])
def test_a_parallel_angle_tolerance_that_is_not_a_number_raises_type_error(value):
    with pytest.raises(TypeError, match=f"^parallel_angle_tolerance = {re.escape(repr(value))}: must be a number"):
        clearjoint.detect(METRES, [0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 0, 1],
                          parallel_angle_tolerance=value)


@pytest.mark.parametrize("value", [True, None, "10", 10 + 0j, np.array([10.0, 11.0])])
def test_dimensions_that_are_not_numbers_raise_type_error_naming_the_field(value):
    values = dict(bearing_radius=10.0, bearing_length=20.0, journal_radius=9.9, journal_length=19.8)
    values["bearing_radius"] = value
    with pytest.raises(TypeError, match="^JointDimensions.bearing_radius = .*: must be a number"):
        clearjoint.JointDimensions(**values)


def test_dimensions_take_numpy_scalars_and_python_ints():
    d = clearjoint.JointDimensions(bearing_radius=np.float32(10), bearing_length=np.int64(20),
                                   journal_radius=9.5, journal_length=19)
    assert (d.bearing_radius, d.bearing_length, d.journal_radius, d.journal_length) == (10.0, 20.0, 9.5, 19.0)


# ---- every DetectionOptions member -------------------------------------------------------------------

def test_exact_fallback_false_leaves_a_tangency_uncertain_with_its_reason():
    # A rim exactly tangent to bearing base A: journal axis (0, 3, 4) (a 3-4-5 triangle), its
    # rim A of radius 5 centred 3 below the base, so its highest point lies on the base.
    d = clearjoint.JointDimensions(bearing_radius=10.0, bearing_length=20.0, journal_radius=5.0,
                                   journal_length=10.0)
    decided = clearjoint.detect(d, [0, 0, 0], [0, 0, 1], [0, 1, 3], [0, 3, 4])
    assert decided.certificate.level != clearjoint.Certainty.uncertain
    assert decided.scenario == clearjoint.ContactScenario.single_axial
    left = clearjoint.detect(d, [0, 0, 0], [0, 0, 1], [0, 1, 3], [0, 3, 4], exact_fallback=False)
    assert left.certificate.level == clearjoint.Certainty.uncertain
    assert left.certificate.reason == clearjoint.CertificateReason.plane_filter_undecided_exact_fallback_off
    batch = clearjoint.detect(d, [0, 0, 0], [0, 0, 1], [[0, 1, 3], [0, 0, 0]], [0, 3, 4], exact_fallback=False)
    assert batch.certificate_reason[0] == clearjoint.CertificateReason.plane_filter_undecided_exact_fallback_off


def test_detect_has_a_keyword_for_every_detection_option_with_the_librarys_default():
    # The library's option list by key (a member added to DetectionOptions is in it, or the
    # library does not build): detect must take each, keyword-only, defaulting as C++ does.
    defaults = clearjoint._core._detection_option_defaults()
    for detect in (clearjoint.detect,):
        parameters = inspect.signature(detect).parameters
        for key, default in defaults.items():
            assert key in parameters, f"detect has no keyword {key}"
            assert parameters[key].kind is inspect.Parameter.KEYWORD_ONLY
            assert parameters[key].default == default, key


def test_detect_passes_each_detection_option_on_to_the_library():
    # One option at a time, to a value the library refuses: the refusal names the option, so it
    # reached the library's reader under its own name.
    wrong = {"certify": 2, "exact_fallback": 2, "parallel_angle_tolerance": "wide"}
    for key in clearjoint._core._detection_option_defaults():
        with pytest.raises(TypeError, match=rf"^{key} = "):
            clearjoint.detect(dims(TABLE2), [0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 0, 1], **{key: wrong[key]})
