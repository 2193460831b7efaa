# SPDX-License-Identifier: BSD-3-Clause
"""Results fit NumPy and pandas: enums are IntEnums that compare with array codes, every result
pickles and has as_dict(), a DetectionBatch indexes and iterates like a sequence of poses and
gives its arrays as two tables, and mistaken calls say what to write instead."""
import enum
import json
import math
import pickle
import struct
import sys

import numpy as np
import pytest

import clearjoint
from cases import CASES, TABLE2, dims
from clearjoint import ContactScenario

METRES = clearjoint.JointDimensions(bearing_radius=0.01, bearing_length=0.02,
                                    journal_radius=0.0099, journal_length=0.0198)
ENUMS = [clearjoint.Certainty, clearjoint.CertificateReason, clearjoint.ContactScenario,
         clearjoint.ContactType, clearjoint.ContactBase, clearjoint.CirclePlaneTopology,
         clearjoint.CircleCylinderTopology]


def every_case_batch():
    """Every Table 2 scenario case of the C++ tests, one batch: scenarios none to beyond_model."""
    cases = [c for c in CASES if c.dimensions == TABLE2 and c.parallel_angle_tolerance == 0.0]
    return cases, clearjoint.detect(dims(TABLE2), [c.bearing[0] for c in cases],
                                    [c.bearing[1] for c in cases], [c.journal[0] for c in cases],
                                    [c.journal[1] for c in cases])


def bits(value):
    """A value with every float replaced by its bit pattern, for comparisons that see -0.0 and
    NaN payloads."""
    if isinstance(value, float):
        return struct.pack("<d", value)
    if isinstance(value, dict):
        return {k: bits(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [bits(v) for v in value]
    return value


# ---- enums ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("cls", ENUMS, ids=[e.__name__ for e in ENUMS])
def test_every_enum_is_an_int_enum_whose_members_equal_their_codes(cls):
    assert issubclass(cls, enum.IntEnum)
    assert [int(m) for m in cls] == list(range(len(cls)))
    for member in cls:
        assert member == int(member) and cls(int(member)) is member and cls[member.name] is member
    assert cls.__module__ == "clearjoint" and pickle.loads(pickle.dumps(list(cls))) == list(cls)


def test_an_array_of_scenario_codes_compares_with_the_enum_element_by_element():
    cases, batch = every_case_batch()
    expected = np.array([c.scenario == ContactScenario.beyond_model for c in cases])
    assert expected.any() and not expected.all()
    assert np.array_equal(batch.scenario == ContactScenario.beyond_model, expected)
    line_or_face = np.isin(batch.scenario, [ContactScenario.line, ContactScenario.face])
    assert np.array_equal(line_or_face, [c.scenario in (ContactScenario.line, ContactScenario.face)
                                         for c in cases])
    assert ContactScenario.beyond_model == 13 and 13 == ContactScenario.beyond_model


def test_results_hold_enum_members():
    result = clearjoint.detect(dims(TABLE2), [0, 0, 0], [0, 0, 1], [0, 0.15, 0.02], [0, 0, 1])
    assert result.scenario is ContactScenario.line
    assert result.certificate.level is clearjoint.Certainty.certified
    assert result.certificate.reason is clearjoint.CertificateReason.none
    assert result.contacts[0].type is clearjoint.ContactType.radial
    assert result.contacts[0].base is clearjoint.ContactBase.mid
    plane = clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [1, 0, 0])
    assert plane.topology is clearjoint.CirclePlaneTopology.two_crossings
    wall = clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0, 1], 0.5, [0, 0, 0], [0, 0, 1], 1.0)
    assert wall.topology is clearjoint.CircleCylinderTopology.inside


def test_label_and_reason_text_take_codes_as_well_as_members():
    assert clearjoint.scenario_label(13) == clearjoint.scenario_label(ContactScenario.beyond_model) == "beyond model"
    assert clearjoint.scenario_label(np.int8(1)) == "(a) single radial"
    assert clearjoint.certificate_reason_text(2) == "certificate switched off"
    with pytest.raises(ValueError, match=r"scenario = 14: not a ContactScenario code \(0 to 13\)"):
        clearjoint.scenario_label(14)
    with pytest.raises(TypeError, match="reason = 'none': must be a CertificateReason or its integer code"):
        clearjoint.certificate_reason_text("none")
    with pytest.raises(TypeError, match="scenario = True"):
        clearjoint.scenario_label(True)


def test_labels_map_over_a_column_of_codes():
    _, batch = every_case_batch()
    labels = [clearjoint.scenario_label(code) for code in batch.scenario]
    assert labels == [clearjoint.scenario_label(s) for s in batch.scenarios()]


# ---- single results: as_dict and pickle -----------------------------------------------------------

def single_results():
    results = [clearjoint.detect(dims(c.dimensions), *c.bearing, *c.journal,
                                 parallel_angle_tolerance=c.parallel_angle_tolerance) for c in CASES]
    results.append(clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [1, 0, 0]))
    results.append(clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 2], [0, 0, 1]))
    results.append(clearjoint.intersect_circle_cylinder([0, 0, 0], [0, 0.1, 1], 1.0, [0.2, 0, 0],
                                                        [0, 0, 1], 1.0))
    return results


def test_every_result_pickles_to_an_equal_result():
    for result in single_results():
        again = pickle.loads(pickle.dumps(result))
        assert type(again) is type(result)
        assert repr(again) == repr(result)
        assert bits(again.as_dict()) == bits(result.as_dict())


def test_the_parts_of_a_result_pickle_too():
    result = clearjoint.detect(dims(TABLE2), *next(c for c in CASES if c.name == "e").bearing,
                               *next(c for c in CASES if c.name == "e").journal)
    contact = result.contacts[0]
    for part in (result.certificate, contact, contact.crossings[0]):
        assert bits(pickle.loads(pickle.dumps(part)).as_dict()) == bits(part.as_dict())
    arc = clearjoint.intersect_circle_plane([0, 0, 0], [0, 0, 1], 1.0, [0, 0, 0], [1, 0, 0]).penetration
    assert repr(pickle.loads(pickle.dumps(arc))) == repr(arc)


def test_as_dict_holds_the_attributes_as_plain_python_values():
    case = next(c for c in CASES if c.name == "e")
    result = clearjoint.detect(dims(case.dimensions), *case.bearing, *case.journal)
    d = result.as_dict()
    assert d["scenario"] is ContactScenario.radial_and_axial_same_base
    assert (d["aligned"], d["contact_count"]) == (False, 2)
    assert d["certificate"] is result.certificate.level
    assert d["certificate_reason"] is result.certificate.reason
    contact, want = d["contacts"][0], result.contacts[0]
    assert (contact["type"], contact["base"]) == (want.type, want.base)
    assert bits(contact["depth"]) == bits(want.depth)
    assert bits(contact["point_journal"]) == bits(want.point_journal.tolist())
    assert bits(contact["normal"]) == bits(want.normal.tolist())
    assert len(contact["crossings"]) == len(want.crossings)
    assert bits(contact["crossings"][0]["angle"]) == bits(want.crossings[0].angle)
    assert json.loads(json.dumps(d))["scenario"] == 5  # enums write as their codes


# ---- DetectionBatch as a sequence of poses ---------------------------------------------------------

def test_a_batch_row_is_the_single_pose_answer_bit_for_bit():
    cases, batch = every_case_batch()
    for n, case in enumerate(cases):
        single = clearjoint.detect(dims(TABLE2), *case.bearing, *case.journal)
        assert isinstance(batch[n], clearjoint.JointContacts)
        assert repr(batch[n]) == repr(single)
        assert bits(batch[n].as_dict()) == bits(single.as_dict())


def test_a_batch_indexes_from_the_end_and_refuses_rows_it_lacks():
    _, batch = every_case_batch()
    assert repr(batch[-1]) == repr(batch[len(batch) - 1])
    assert repr(batch[np.int64(2)]) == repr(batch[2])
    with pytest.raises(IndexError, match=f"pose {len(batch)} out of range for a batch of {len(batch)} poses"):
        batch[len(batch)]
    with pytest.raises(IndexError):
        batch[-len(batch) - 1]
    with pytest.raises(TypeError, match="must be an integer"):
        batch[1.0]


def test_a_batch_iterates_over_its_poses():
    cases, batch = every_case_batch()
    poses = list(batch)
    assert len(poses) == len(batch) == len(cases)
    assert [p.scenario for p in poses] == [c.scenario for c in cases]


def test_poses_and_contacts_give_a_dict_of_equal_length_arrays_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas raises ImportError
    _, batch = every_case_batch()
    poses = batch.poses()
    assert list(poses) == ["scenario", "aligned", "certificate", "certificate_reason", "contact_count"]
    assert all(len(column) == len(batch) for column in poses.values())
    assert poses["scenario"] is batch.scenario
    contacts = batch.contacts()
    m = len(batch.depth)
    assert all(column.shape == (m,) for column in contacts.values())
    assert list(contacts)[:4] == ["pose", "slot", "type", "base"]
    assert np.array_equal(contacts["normal_y"], batch.normal[:, 1])
    assert np.array_equal(contacts["crossing_point_1_z"], batch.crossing_point[:, 1, 2], equal_nan=True)
    assert np.array_equal(contacts["crossing_angle_0"], batch.crossing_angle[:, 0], equal_nan=True)
    assert np.array_equal(contacts["certificate"], batch.contact_certificate)
    assert "contact_start" not in contacts and "start" not in contacts


def test_poses_and_contacts_give_data_frames_with_pandas():
    pandas = pytest.importorskip("pandas")
    _, batch = every_case_batch()
    poses, contacts = batch.poses(), batch.contacts()
    assert isinstance(poses, pandas.DataFrame) and isinstance(contacts, pandas.DataFrame)
    assert len(poses) == len(batch) and len(contacts) == len(batch.depth)
    assert (poses["scenario"] == ContactScenario.beyond_model).sum() == \
        np.count_nonzero(batch.scenario == ContactScenario.beyond_model)
    assert poses["scenario"].map(clearjoint.scenario_label).iloc[0] == clearjoint.scenario_label(batch.scenario[0])
    deepest = contacts.groupby("pose")["depth"].max()
    for n in deepest.index:
        assert deepest[n] == batch.depth[batch.contact_start[n]:batch.contact_start[n + 1]].max()


# ---- mistaken calls -------------------------------------------------------------------------------

def test_positional_dimensions_say_to_use_keywords():
    with pytest.raises(TypeError, match=r"JointDimensions takes keyword arguments only.*"
                                        r"JointDimensions\(bearing_radius=Ri"):
        clearjoint.JointDimensions(10, 20, 9.9, 19.8)


def test_dimensions_from_a_dict_say_to_unpack_it():
    values = dict(bearing_radius=10.0, bearing_length=20.0, journal_radius=9.9, journal_length=19.8)
    with pytest.raises(TypeError, match=r"not a dict: write JointDimensions\(\*\*d\)"):
        clearjoint.JointDimensions(values)
    with pytest.raises(TypeError, match=r"dims = \{.*\}: must be a clearjoint.JointDimensions "
                                        r"\(JointDimensions\(\*\*dims\) for a dict\)"):
        clearjoint.detect(values, [0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 0, 1])
    assert clearjoint.JointDimensions(**values).journal_radius == 9.9


def test_missing_or_unknown_dimension_keywords_are_named():
    with pytest.raises(TypeError, match="missing journal_length; unknown keyword journal_lenght;"):
        clearjoint.JointDimensions(bearing_radius=10.0, bearing_length=20.0, journal_radius=9.9,
                                   journal_lenght=19.8)
    assert "handle" not in str(pytest.raises(TypeError, clearjoint.JointDimensions).value)
