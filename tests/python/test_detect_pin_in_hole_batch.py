# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.detect_pin_in_hole on NumPy batches: the packed arrays (PinInHoleBatch) hold, row
by row and bit for bit, the answers of single calls; the batch is also a sequence of
PinInHoleContacts; threads change nothing; bad input is named with its argument and row."""
import math
import pickle

import numpy as np
import pytest

import clearjoint
from clearjoint import PinInHoleBatch, PinInHoleContacts, PinInHoleDimensions, PinInHoleScenario

from batch_rows import assert_row_equals_single, bits

# The shipped examples' joint (examples/pin_in_hole_scenarios.jsonl), metres: hole radius 10 mm,
# length 20 mm, pin radius 9.5 mm, heads at +-11.5 mm of outer radius 13 mm.
DIMS = PinInHoleDimensions(hole_radius=0.01, hole_length=0.02, pin_radius=0.0095,
                           stops=((-0.0115, 0.013), (0.0115, 0.013)))


def realistic_poses(count, seed):
    """As tests/bindings/equivalence/write_pin_in_hole_inputs.cpp draws them: the pin off the
    hole's axis by up to 1.5 cr and along it by up to 1.5 ca, tilted by up to 2 cr / L (one pose
    in four by at most 1e-9 rad: near-parallel); the hole anywhere within 0.2 m, any axis."""
    rng = np.random.default_rng(seed)
    cr, ca, length = DIMS.radial_clearance, DIMS.axial_clearance, DIMS.hole_length
    hole_center = rng.uniform(-0.2, 0.2, (count, 3))
    hole_axis = rng.normal(size=(count, 3))
    hole_axis /= np.linalg.norm(hole_axis, axis=1)[:, None]
    helper = np.where(np.abs(hole_axis[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]])
    p = np.cross(hole_axis, helper)
    p /= np.linalg.norm(p, axis=1)[:, None]
    q = np.cross(hole_axis, p)
    max_tilt = np.where(np.arange(count) % 4 == 3, 1e-9, 2 * cr / length)[:, None]
    tilt = max_tilt * rng.uniform(0.0, 1.0, (count, 1))
    lean = rng.uniform(0.0, 2 * np.pi, (count, 1))
    pin_axis = np.cos(tilt) * hole_axis + np.sin(tilt) * (np.cos(lean) * p + np.sin(lean) * q)
    radial = 1.5 * cr * np.sqrt(rng.uniform(0.0, 1.0, (count, 1)))
    toward = rng.uniform(0.0, 2 * np.pi, (count, 1))
    axial = 1.5 * ca * rng.uniform(-1.0, 1.0, (count, 1))
    pin_center = hole_center + radial * (np.cos(toward) * p + np.sin(toward) * q) + axial * hole_axis
    return hole_center, hole_axis, pin_center, pin_axis


def test_a_packed_batch_of_realistic_poses_equals_the_single_pose_answers_bit_for_bit():
    poses = realistic_poses(600, seed=48)
    batch = clearjoint.detect_pin_in_hole(DIMS, *poses)
    assert isinstance(batch, PinInHoleBatch) and len(batch) == 600
    assert batch.contact_start[-1] == len(batch.depth) == batch.contact_count.sum()
    for n in range(600):
        single = clearjoint.detect_pin_in_hole(DIMS, *(p[n] for p in poses))
        assert_row_equals_single(batch, n, single)
    # The comparison covers contacts of several kinds, not only free poses: 7 scenarios measured
    # on these 600 poses; the floor leaves a margin of 2.
    assert len(set(batch.scenarios())) >= 5, set(batch.scenarios())


def test_the_batch_is_a_sequence_of_the_single_pose_answers():
    poses = realistic_poses(40, seed=2)
    batch = clearjoint.detect_pin_in_hole(DIMS, *poses)
    answers = list(batch)
    assert len(answers) == 40 and all(isinstance(a, PinInHoleContacts) for a in answers)
    for n, answer in enumerate(answers):
        single = clearjoint.detect_pin_in_hole(DIMS, *(p[n] for p in poses))
        assert answer.as_dict() == single.as_dict()
        assert [bits(c.depth) for c in answer.contacts] == [bits(c.depth) for c in single.contacts]
    assert batch[-1].as_dict() == answers[39].as_dict()
    assert batch.scenarios() == [a.scenario for a in answers]
    assert all(isinstance(s, PinInHoleScenario) for s in batch.scenarios())
    with pytest.raises(IndexError, match="pose 40 out of range for a batch of 40 poses"):
        batch[40]
    with pytest.raises(TypeError, match="PinInHoleBatch index 'a': must be an integer"):
        batch["a"]


def test_a_fixed_hole_broadcasts_over_pin_poses_given_as_lists():
    # Aligned (cr = 0.5 mm, ca = 1.5 mm): centred, none; 0.6 mm sideways, 0.1 mm into the bore:
    # line; 1 mm along the axis, none; 2 mm, the head at -11.5 mm 0.5 mm into face B: face.
    batch = clearjoint.detect_pin_in_hole(DIMS, [0, 0, 0], [0, 0, 1],
                                          [[0, 0, 0], [0.0006, 0, 0], [0, 0, 0.001], [0, 0, 0.002]],
                                          [0, 0, 1])
    assert batch.scenarios() == [PinInHoleScenario.none, PinInHoleScenario.line, PinInHoleScenario.none,
                                 PinInHoleScenario.face]


@pytest.mark.parametrize("threads", [2, 3])
def test_any_thread_count_gives_the_answers_of_one_thread(threads):
    poses = realistic_poses(5000, seed=5)
    one = clearjoint.detect_pin_in_hole(DIMS, *poses, threads=1)
    assert clearjoint.detect_pin_in_hole(DIMS, *poses, threads=threads) == one
    assert clearjoint.detect_pin_in_hole(DIMS, *poses) == one


def test_a_batch_of_one_returns_arrays_and_an_empty_batch_empty_arrays():
    poses = realistic_poses(1, seed=4)
    one = clearjoint.detect_pin_in_hole(DIMS, *poses)
    assert isinstance(one, PinInHoleBatch) and len(one) == 1
    assert_row_equals_single(one, 0, clearjoint.detect_pin_in_hole(DIMS, *(p[0] for p in poses)))
    empty = np.empty((0, 3))
    batch = clearjoint.detect_pin_in_hole(DIMS, empty, empty, empty, empty)
    assert len(batch) == 0 and batch.contact_start.tolist() == [0] and batch.depth.shape == (0,)


def test_options_reach_every_row_of_a_batch():
    poses = realistic_poses(300, seed=8)
    proved = clearjoint.detect_pin_in_hole(DIMS, *poses)
    plain = clearjoint.detect_pin_in_hole(DIMS, *poses, certify=False)
    assert np.all(plain.certificate == int(clearjoint.Certainty.uncertain))
    assert np.array_equal(plain.contact_count, proved.contact_count)
    for n in range(0, 300, 7):
        assert_row_equals_single(plain, n, clearjoint.detect_pin_in_hole(DIMS, *(p[n] for p in poses),
                                                                         certify=False))
    tolerant = clearjoint.detect_pin_in_hole(DIMS, *poses, parallel_angle_tolerance=1e-6)
    # The near-parallel quarter (tilts up to 1e-9 rad) is treated as parallel, not the others
    # (tilts uniform up to 2 cr / L = 0.05 rad: none of this seed's 225 below 1e-6 rad).
    assert np.array_equal(tolerant.aligned, np.arange(300) % 4 == 3) and not np.any(proved.aligned)
    for n in (0, 3, 150):
        single = clearjoint.detect_pin_in_hole(DIMS, *(p[n] for p in poses), parallel_angle_tolerance=1e-6)
        assert_row_equals_single(tolerant, n, single)


def test_a_batch_pickles_and_its_tables_name_the_contact_columns():
    batch = clearjoint.detect_pin_in_hole(DIMS, *realistic_poses(100, seed=9))
    assert pickle.loads(pickle.dumps(batch)) == batch
    contacts = batch.contacts()
    assert len(contacts["depth"]) == len(batch.depth) and "point_bearing_x" in contacts
    assert batch.padded("depth").shape == (100, clearjoint.MAX_CONTACTS)


@pytest.mark.parametrize("argument, index, value, message", [
    (3, 2, [0.0, 0.0, 0.0], r"pin_axis\[2\] = \[0, 0, 0\]: must not be the zero vector"),
    (2, 5, [0.0, math.nan, 0.0], r"pin_center\[5\] = \[[-0-9.e]+, nan, [-0-9.e]+\]: every component must be finite"),
    (1, 7, [math.inf, 0.0, 1.0], r"hole_axis\[7\] = \[inf, 0, 1\]"),
    (0, 1, [1e200, 0.0, 0.0], r"hole_center\[1\] = \[1e\+200, 0, 0\]"),
])
@pytest.mark.parametrize("threads", [1, 2])
def test_a_bad_row_raises_value_error_naming_the_argument_and_row(argument, index, value, message, threads):
    poses = [p.copy() for p in realistic_poses(4000, seed=10)]
    poses[argument][index] = value
    poses[argument][3000] = value  # a later bad row, maybe on another thread: the first is named
    with pytest.raises(ValueError, match=message):
        clearjoint.detect_pin_in_hole(DIMS, *poses, threads=threads)


@pytest.mark.parametrize("shape", [(5, 2), (5, 3, 1), (3, 5), (4,)])
def test_a_pose_argument_of_another_shape_raises_value_error_naming_it(shape):
    with pytest.raises(ValueError, match=r"pin_center: shape \(.*\) must be \(3,\) or \(N, 3\)"):
        clearjoint.detect_pin_in_hole(DIMS, [0, 0, 0], [0, 0, 1], np.zeros(shape), [0, 0, 1])


def test_batched_arguments_of_different_lengths_raise_value_error_naming_both():
    with pytest.raises(ValueError, match="pin_axis has 3 rows and pin_center 4"):
        clearjoint.detect_pin_in_hole(DIMS, [0, 0, 0], [0, 0, 1], np.zeros((4, 3)), np.tile([0, 0, 1.0], (3, 1)))


def test_a_batch_too_large_to_copy_raises_memory_error_naming_the_argument():
    # A broadcast view of 10^12 rows holds no memory; as contiguous float64 it would take 24 TB.
    huge = np.broadcast_to(np.zeros(3), (10**12, 3))
    with pytest.raises(MemoryError, match=r"pin_center: shape \(1000000000000, 3\) does not fit in memory"):
        clearjoint.detect_pin_in_hole(DIMS, [0, 0, 0], [0, 0, 1], huge, [0, 0, 1])
    # The interpreter carries on.
    assert len(clearjoint.detect_pin_in_hole(DIMS, [0, 0, 0], [0, 0, 1], np.zeros((2, 3)), [0, 0, 1])) == 2


@pytest.mark.parametrize("threads, error, message", [
    (0, ValueError, "threads = 0: must be at least 1"),
    (1.5, TypeError, "threads"),
])
def test_a_bad_thread_count_raises(threads, error, message):
    with pytest.raises(error, match=message):
        clearjoint.detect_pin_in_hole(DIMS, [0, 0, 0], [0, 0, 1], np.zeros((2, 3)), [0, 0, 1], threads=threads)
