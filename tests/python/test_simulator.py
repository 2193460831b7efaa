# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.Simulator: a model stepped from Python (controls, co-simulation, loads)."""
import json
import math
import os
import signal
import threading
import time

import numpy as np
import pytest

import clearjoint


@pytest.fixture
def clearance_model(models_dir):
    with open(models_dir / "slider_crank_spatial_clearance.json") as f:
        model = json.load(f)
    model["solver"]["end_time"] = 0.05
    model["solver"]["report_step"] = 1e-3
    return model


def falling_ball(end_time=1.0):
    return {"bodies": [{"name": "ball", "mass": 2.0, "inertia": [1, 1, 1], "position": [0, 0, 0]}],
            "gravity": [0, 0, -9.81], "solver": {"end_time": end_time, "report_step": 0.01}}


def test_stepping_to_the_end_gives_the_state_simulate_reports(clearance_model):
    sim = clearjoint.Simulator(clearance_model)
    while not sim.finished:
        sim.step()
    result = clearjoint.simulate(clearance_model)
    crank = sim.body_state("crank")
    assert sim.time >= clearance_model["solver"]["end_time"]
    # The reports interpolate at end_time; the stepper's state lies at the last step's end, so
    # compare through the summary's step count instead of positions.
    assert sim.statistics()["steps"] == result.summary["steps"]
    assert np.all(np.isfinite(crank["position"]))


def test_advance_to_lands_on_the_time_asked(clearance_model):
    sim = clearjoint.Simulator(clearance_model)
    for t in (1e-4, 3.3e-3, 0.02):
        sim.advance_to(t)
        assert sim.time == pytest.approx(t, rel=1e-15)
    with pytest.raises(ValueError, match=r"advance_to\(0\.01\): must lie in"):
        sim.advance_to(0.01)


def test_an_applied_force_adds_its_uniform_acceleration():
    loaded, free = clearjoint.Simulator(falling_ball()), clearjoint.Simulator(falling_ball())
    loaded.apply_load("ball", force=[4.0, 0.0, 0.0])
    loaded.advance_to(0.5)
    free.advance_to(0.5)
    dx = loaded.body_state("ball")["position"][0] - free.body_state("ball")["position"][0]
    assert dx == pytest.approx(4.0 * 0.5 ** 2 / (2 * 2.0), abs=1e-9)


def test_a_load_on_an_unknown_body_or_not_finite_is_named():
    sim = clearjoint.Simulator(falling_ball())
    with pytest.raises(ValueError, match='body = "nobody"'):
        sim.apply_load("nobody", force=[1, 0, 0])
    with pytest.raises(ValueError, match="must be finite"):
        sim.apply_load("ball", force=[math.nan, 0, 0])
    with pytest.raises(TypeError, match="force: must be 3 numbers"):
        sim.apply_load("ball", force=[1, 0])


def test_impacts_arrive_once_each_in_time_order(clearance_model):
    sim = clearjoint.Simulator(clearance_model)
    impacts = []
    while not sim.finished:
        sim.advance_to(min(sim.time + 5e-3, sim.end_time))
        impacts += sim.take_impacts()
    assert impacts, "the short run has impacts"
    assert [i["time"] for i in impacts] == sorted(i["time"] for i in impacts)
    assert {i["joint"] for i in impacts} == {"ground-crank clearance"}
    assert all(i["impact_speed"] > 0 and i["slot"] in ("radial_a", "radial_b", "line", "axial_a", "axial_b")
               for i in impacts)
    assert sim.take_impacts() == []


def test_a_state_set_between_steps_is_continued_from():
    sim = clearjoint.Simulator(falling_ball())
    sim.advance_to(0.5)
    y = sim.state
    y[2] = 100.0
    sim.set_state(y)
    assert sim.body_state("ball")["position"][2] == 100.0
    with pytest.raises(ValueError, match="3 values for a state of"):
        sim.set_state([0.0, 0.0, 0.0])


@pytest.mark.parametrize("t", ["0.01", True, 0.01 + 0j, None, [0.01]])
def test_advance_to_refuses_anything_but_a_real_number_naming_t(t):
    sim = clearjoint.Simulator(falling_ball())
    with pytest.raises(TypeError, match="t = .*: must be a real number"):
        sim.advance_to(t)
    assert sim.time == 0.0


@pytest.mark.parametrize("entry", ["0.5", True, 0.5 + 0j, object()])
def test_set_state_refuses_text_booleans_complex_numbers_and_objects(entry):
    sim = clearjoint.Simulator(falling_ball())
    before = sim.state
    y = [entry] * len(before)
    with pytest.raises(TypeError, match="state: must be an array of real numbers"):
        sim.set_state(y)
    assert np.array_equal(sim.state, before)


@pytest.mark.parametrize("scale", [0.0, 0.5])
def test_a_zero_or_non_unit_quaternion_is_refused_leaving_the_simulator_usable(clearance_model, scale):
    # A zero quaternion once broke the simulator ("Jacobian lost rank") until it was rebuilt.
    sim = clearjoint.Simulator(clearance_model)
    sim.advance_to(1e-3)
    before = sim.state
    y = before.copy()
    y[3:7] *= scale
    with pytest.raises(ValueError, match=r"state\[3:7\] = .*must have norm 1 \(within 1e-06\)"):
        sim.set_state(y)
    assert np.array_equal(sim.state, before)
    sim.advance_to(2e-3)
    assert sim.time == pytest.approx(2e-3, abs=1e-15)


def test_ctrl_c_stops_a_long_advance_promptly(models_dir):
    sim = clearjoint.Simulator(models_dir / "slider_crank_spatial_clearance.json")
    timer = threading.Timer(0.3, os.kill, args=(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            sim.advance_to(sim.end_time)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 1.3
    assert 0.0 < sim.time < sim.end_time


def test_the_motor_control_example_holds_the_crank_speed(models_dir):
    # The docs' loop: a proportional-integral torque on the crank, updated every 0.1 ms.
    sim = clearjoint.Simulator(models_dir / "slider_crank_spatial_clearance.json")
    set_point, integral, worst, period = 2 * math.pi, 0.0, 0.0, 1e-4
    while sim.time < 0.3 - 1e-12:
        error = set_point - sim.body_state("crank")["angular_velocity_body"][1]
        integral += error * period
        sim.apply_load("crank", moment=[0.0, 1.0 * error + 50.0 * integral, 0.0])
        if sim.time > 0.15:
            worst = max(worst, abs(error) / set_point)
        sim.advance_to(min(sim.time + period, 0.3))
    assert worst < 0.10


JOINT = "ground-crank clearance"  # models/slider_crank_spatial_clearance.json's clearance joint


def rotation(euler_parameters):
    """The rotation matrix of unit Euler parameters (e0, e1, e2, e3), written out again from
    Nikravesh's A = (2 e0^2 - 1) I + 2 (e e^T + e0 e~), not taken from the library."""
    e0, e = euler_parameters[0], np.asarray(euler_parameters[1:])
    tilde = np.array([[0.0, -e[2], e[1]], [e[2], 0.0, -e[0]], [-e[1], e[0], 0.0]])
    return (2 * e0 * e0 - 1) * np.eye(3) + 2 * (np.outer(e, e) + e0 * tilde)


def joint_contacts_seen(clearance_model):
    """Steps the model to its end, reading the crank and the joint after every step as a
    controller would: the steps shrink through each impact, so most readings fall in contact."""
    sim = clearjoint.Simulator(clearance_model)
    seen = []
    while not sim.finished:
        sim.step()
        seen.append((sim.body_state("crank"), sim.joint_state(JOINT)))
    return seen


def test_joint_state_while_stepping_holds_the_contacts_detect_finds_at_the_bodies_poses(clearance_model):
    # The joint's answer against the kernel called from Python on poses rebuilt in the test: the
    # bearing rides on the crank (point (0, 0, -0.05), axis y), the journal is fixed to ground at
    # the origin along y (the model's Table 2 dimensions).
    force = next(f for f in clearance_model["forces"] if f["name"] == JOINT)
    bearing, journal = force["bearing"], force["journal"]
    dims = clearjoint.JointDimensions(bearing_radius=bearing["radius"], bearing_length=bearing["length"],
                                      journal_radius=journal["radius"], journal_length=journal["length"])
    in_contact = 0
    for crank, state in joint_contacts_seen(clearance_model):
        turn = rotation(crank["euler_parameters"])
        expected = clearjoint.detect(dims, crank["position"] + turn @ bearing["point"], turn @ bearing["axis"],
                                     journal["point"], journal["axis"])
        contacts = state["contacts"]
        assert contacts.scenario == expected.scenario
        assert contacts.contact_count == expected.contact_count
        for mine, theirs in zip(contacts.contacts[:contacts.contact_count], expected.contacts):
            # Two roundings of the same pose (the library's rotation and this one) differ by a few
            # ulps of the 0.05 m lever arm, about 1e-17 m; the depths are 1e-6 m and larger.
            assert mine.depth == pytest.approx(theirs.depth, abs=1e-15)
        in_contact += contacts.contact_count > 0
    # 581 of the 928 steps of the first 50 ms end in contact (measured): the comparison is not
    # all "none"; the floor leaves room for a change of step sizes.
    assert in_contact >= 300


def test_joint_state_force_is_the_sum_of_its_contact_forces(clearance_model):
    loaded = 0
    for _, state in joint_contacts_seen(clearance_model):
        per_contact = state["contact_force_on_journal"]
        assert per_contact.shape == (state["contacts"].contact_count, 3)
        assert state["film"] is None  # a dry joint
        total = per_contact.sum(axis=0)
        scale = max(1.0, float(np.abs(per_contact).max(initial=0.0)))
        np.testing.assert_allclose(state["force_on_journal"], total, rtol=0, atol=1e-12 * scale)
        # A slot out of contact carries no force.
        for name, slot in state["slots"].items():
            if not slot["active"]:
                assert slot["normal_force"] == 0 and slot["friction_force"] == 0, (name, slot)
        magnitude = math.hypot(*state["force_on_journal"])
        parts = sum(math.hypot(s["normal_force"], s["friction_force"]) for s in state["slots"].values())
        assert magnitude <= parts * (1 + 1e-12) + 1e-12  # the triangle inequality over the slots
        loaded += magnitude > 1.0
    assert loaded >= 300  # 540 of 928 steps carry more than 1 N (measured)


def test_joint_state_of_an_unknown_joint_or_a_name_that_is_not_text_is_refused_naming_it(clearance_model):
    sim = clearjoint.Simulator(clearance_model)
    with pytest.raises(ValueError, match='joint = "crank-rod": no clearance joint of that name'):
        sim.joint_state("crank-rod")
    with pytest.raises(TypeError, match=r"name = 3: must be a joint's name"):
        sim.joint_state(3)


def test_threads_sharing_a_simulator_take_its_steps_one_at_a_time(clearance_model):
    # Two threads of 300 steps each on one simulator end where one thread's 600 steps end: each
    # step is taken whole from the state the previous one left, whatever the interleaving.
    shared, alone = clearjoint.Simulator(clearance_model), clearjoint.Simulator(clearance_model)

    def steps():
        for _ in range(300):
            shared.step()

    threads = [threading.Thread(target=steps) for _ in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for _ in range(600):
        alone.step()
    assert shared.time == alone.time
    np.testing.assert_array_equal(shared.state, alone.state)
