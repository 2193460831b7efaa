# SPDX-License-Identifier: BSD-3-Clause
"""The shipped slider-cranks with a pin-in-hole clearance joint run, and the misaligned pin of the
spatial one meets the hole at its edges."""
import json

import numpy as np
import pytest

import clearjoint

# 50 ms: the planar rod's pin settles on its line contact within the first few milliseconds; the
# spatial crank's hole meets the tilted pin at an edge and the heads meet the link within 30 ms.
# Each run takes about a tenth of a second.
SHORT_END_TIME = 0.05
REPORT_STEP = 1e-4

EDGE_SCENARIOS = {clearjoint.PinInHoleScenario.one_edge, clearjoint.PinInHoleScenario.both_edges_opposite,
                  clearjoint.PinInHoleScenario.both_edges_same_side, clearjoint.PinInHoleScenario.edges_and_stops}


def short_run(models_dir, name):
    with open(models_dir / name) as f:
        model = json.load(f)
    model["solver"]["end_time"] = SHORT_END_TIME
    model["solver"]["report_step"] = REPORT_STEP
    result = clearjoint.simulate(model)
    (table,) = [t for t in result.tables if t.startswith("force_")]
    return result[table]


def scenarios(forces):
    return {clearjoint.PinInHoleScenario(int(s)) for s in np.asarray(forces["scenario"])}


@pytest.mark.parametrize("name", ["slider_crank_planar_clearance_pin_in_hole.json",
                                  "slider_crank_spatial_pin_in_hole_misaligned.json"])
def test_a_shipped_pin_in_hole_slider_crank_runs_in_contact_within_its_model(models_dir, name):
    forces = short_run(models_dir, name)
    assert len(forces["time"]) == round(SHORT_END_TIME / REPORT_STEP) + 1
    found = scenarios(forces)
    assert clearjoint.PinInHoleScenario.beyond_model not in found
    assert found != {clearjoint.PinInHoleScenario.none}  # the joint carries load
    assert np.all(np.isfinite(forces["fx"]))


def test_the_planar_pin_rides_on_its_line_contact_as_the_aligned_journal_does(models_dir):
    forces = short_run(models_dir, "slider_crank_planar_clearance_pin_in_hole.json")
    assert scenarios(forces) <= {clearjoint.PinInHoleScenario.none, clearjoint.PinInHoleScenario.line}
    assert np.nanmax(forces["line.normal_force"]) > 0.0


def test_the_misaligned_pin_meets_the_hole_at_its_edges(models_dir):
    forces = short_run(models_dir, "slider_crank_spatial_pin_in_hole_misaligned.json")
    assert scenarios(forces) & EDGE_SCENARIOS
    # The tilt keeps the axes apart: never the aligned line contact.
    assert clearjoint.PinInHoleScenario.line not in scenarios(forces)
    edge_force = np.asarray(forces["radial_a.normal_force"]) + np.asarray(forces["radial_b.normal_force"])
    assert edge_force.max() > 0.0


def test_the_non_smooth_integrator_refuses_a_pin_in_hole_joint_naming_the_geometry(models_dir):
    with open(models_dir / "slider_crank_planar_clearance_pin_in_hole.json") as f:
        model = json.load(f)
    model["solver"]["end_time"] = 0.01
    model["solver"]["method"] = "moreau_jean"
    with pytest.raises(ValueError, match=r"clearance joint 'rod-slider pin': \"geometry\": \"pin_in_hole\" is not "
                                         r"supported by solver.method = \"moreau_jean\""):
        clearjoint.simulate(model)


def test_a_stepped_pin_in_hole_joint_reports_its_contacts_in_the_pin_in_hole_table(models_dir):
    with open(models_dir / "slider_crank_planar_clearance_pin_in_hole.json") as f:
        model = json.load(f)
    model["solver"]["end_time"] = 0.01
    sim = clearjoint.Simulator(model)
    seen = set()
    while not sim.finished:
        sim.step()
        contacts = sim.joint_state("rod-slider pin")["contacts"]
        assert isinstance(contacts, clearjoint.PinInHoleContacts)
        seen.add(contacts.scenario)
    assert clearjoint.PinInHoleScenario.line in seen
