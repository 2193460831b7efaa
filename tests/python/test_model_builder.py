# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.Model: the shipped slider-cranks rebuilt by builder calls equal their files and run
bit for bit alike, every shipped model survives a round trip, every field of the model schema can
be written, bad arguments and bad models are refused naming the field, and the guide's example
runs."""
import importlib.util
import json
import math
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import clearjoint

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCHEMA = ROOT / "docs" / "schema" / "model.schema.json"
GUIDE = ROOT / "docs" / "python.md"

# A short run of each model, as test_simulate.py's: 20 ms reaches the first impacts of the
# clearance joints (the journal meets the wall within 10 ms) in a fraction of a second.
SHORT_END_TIME = 0.02
SHORT_REPORT_STEP = 1e-3


def shipped(models_dir, name):
    with open(models_dir / name) as f:
        return json.load(f)


def tables_bytes(result):
    """Every column of a run as bytes: equal bytes are equal bits, NaN and -0.0 included."""
    return {table: {column: np.ascontiguousarray(values).tobytes() for column, values in columns.items()}
            for table, columns in result.tables.items()}


def assert_same_short_run(model_dict, file_dict):
    """clearjoint.simulate on both, shortened alike, gives the same bits in every table."""
    runs = []
    for d in (model_dict, file_dict):
        d = json.loads(json.dumps(d))
        d["solver"]["end_time"] = SHORT_END_TIME
        d["solver"]["report_step"] = SHORT_REPORT_STEP
        runs.append(clearjoint.simulate(d))
    assert set(runs[0].tables) == set(runs[1].tables)
    assert len(runs[0]["energy"]["time"]) == round(SHORT_END_TIME / SHORT_REPORT_STEP) + 1
    assert tables_bytes(runs[0]) == tables_bytes(runs[1])


# --- The paper's slider-cranks (Section 6), written as builder calls from Tables 1-3, as
# models/make_slider_crank_models.py writes them as dicts. Only the long free texts (each
# model's name and notes) are taken from the file; every number, name and comment is here.

ORIGIN, X, Y, Z = [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]
ALL_SIX = ["x", "y", "z", "rx", "ry", "rz"]

PAPER_SOLVER = dict(
    comment="Paper Table 2: ode45 (here Dormand-Prince 5(4) with dense output), reported step "
            "1e-5 s, tolerance 1e-7, 1 s, Baumgarte alpha = beta = 5.",
    start_time=0.0, end_time=1.0, report_step=1e-5, relative_tolerance=1e-7,
    absolute_tolerance=1e-7, baumgarte_alpha=5.0, baumgarte_beta=5.0)

TABLE2_COMMENT = ("paper Table 2; the study varies the journal (Rj = Ri - cr, Lj = Li - 2 ca), "
                  "the bearing stays")

# Sec. 6.1 (Table 1): crank and rod lengths [m].
L1, L2 = 0.1524, 0.3048
# Sec. 6.2 (Table 3): crank and rod lengths, the slider guide's offset from the crank plane [m].
LC, LR, OFFSET = 0.10, 0.29, 0.12
SLIDER_X = math.sqrt(LR**2 - OFFSET**2 - LC**2)


def add_table2_joint(m, name, bearing, journal, lubrication=None):
    """The clearance joint of Table 2: Ri = 10 mm, Li = 20 mm, clearances 0.1 mm; K = 1e11,
    Lankarani-Nikravesh with ce = 0.9, friction mu = 0.1."""
    m.add_clearance_revolute(
        name, comment=TABLE2_COMMENT,
        bearing=dict(bearing, radius=0.01, length=0.02),
        journal=dict(journal, radius=0.0099, length=0.0198),
        normal_force=dict(model="lankarani_nikravesh", stiffness=1e11, exponent=1.5, restitution=0.9,
                          minimum_impact_speed=1e-3),
        friction=dict(coefficient=0.1, velocity_coefficient=1000.0),
        detection=dict(parallel_angle_tolerance=0.0),
        lubrication=lubrication)


PIN_COMMENT = "paper Table 2 clearances: Rp = Rh - cr, heads' faces ca beyond the link's faces"


def add_table2_pin(m, name, hole, pin):
    """add_table2_joint's joint as a pin through a hole: Rh = 10 mm, L = 20 mm, Rp = 9.9 mm, heads
    of radius 15 mm whose faces stand 0.1 mm beyond the link's faces."""
    head = 0.02 / 2 + 1e-4
    m.add_clearance_revolute(
        name, comment=PIN_COMMENT, geometry="pin_in_hole",
        hole=dict(hole, radius=0.01, length=0.02),
        pin=dict(pin, radius=0.0099, stops=[dict(position=head, outer_radius=1.5 * 0.01),
                                            dict(position=-head, outer_radius=1.5 * 0.01)]),
        normal_force=dict(model="lankarani_nikravesh", stiffness=1e11, exponent=1.5, restitution=0.9,
                          minimum_impact_speed=1e-3),
        friction=dict(coefficient=0.1, velocity_coefficient=1000.0),
        detection=dict(parallel_angle_tolerance=0.0))


def planar_model(texts, rod=None, clearance=False, lubrication=None, pin_in_hole=False):
    """Sec. 6.1: crank about +z in the x-y plane, slider along x, top dead centre."""
    m = clearjoint.Model(texts["name"], gravity=[0.0, -9.81, 0.0], notes=texts["notes"])
    m.add_body("crank", mass=0.15, inertia=[0.002, 0.002, 0.002], position=[L1 / 2, 0.0, 0.0],
               angular_velocity=[0.0, 0.0, 150.0])
    m.add_body("rod", mass=0.30, inertia=[0.002, 0.002, 0.002], position=[L1 + L2 / 2, 0.0, 0.0],
               **(rod or {}))
    m.add_body("slider", mass=0.15, inertia=[0.001, 0.001, 0.001], position=[L1 + L2, 0.0, 0.0])
    m.add_revolute("crank-ground", "ground", "crank", point_i=ORIGIN, point_j=[-L1 / 2, 0.0, 0.0],
                   axis_i=Z, axis_j=Z)
    if clearance:
        # The rod's eta (body y) runs along it: its end is at +L2/2 on y.
        m.add_spherical("crank-rod", "crank", "rod", point_i=[L1 / 2, 0.0, 0.0],
                        point_j=[0.0, -L2 / 2, 0.0])
    else:
        m.add_spherical("crank-rod", "crank", "rod", point_i=[L1 / 2, 0.0, 0.0],
                        point_j=[-L2 / 2, 0.0, 0.0])
        m.add_spherical("rod-slider", "rod", "slider", point_i=[L2 / 2, 0.0, 0.0], point_j=ORIGIN,
                        comment="the paper's revolute clearance joint, replaced by an ideal spherical joint")
    m.add_translational("slider-ground", "ground", "slider", point_i=ORIGIN, point_j=ORIGIN,
                        axis_i=X, axis_j=X)
    if clearance:
        if pin_in_hole:
            add_table2_pin(m, "rod-slider pin", dict(body="slider", point=ORIGIN, axis=Z),
                           dict(body="rod", point=[0.0, L2 / 2, 0.0], axis=Z))
        else:
            add_table2_joint(m, "rod-slider clearance", dict(body="slider", point=ORIGIN, axis=Z),
                             dict(body="rod", point=[0.0, L2 / 2, 0.0], axis=Z), lubrication)
        m.set_initial_conditions(comment="crank pose and angular velocity held; the other guesses "
                                         "already satisfy the joints")
    else:
        m.set_initial_conditions(comment="crank pose held; the rest is corrected by Newton-Raphson "
                                         "(the guess is already exact)")
    m.hold_position("crank", ALL_SIX)
    m.hold_velocity("crank", "wz", 150.0)
    m.set_solver(**PAPER_SOLVER)
    m.set_output(bodies=["crank", "rod", "slider"])
    return m


# The rod's frame of the clearance models: -90 degrees about z (eta along the rod), then the
# misalignment about eta; the ideal mechanism's velocities at top dead centre.
ROD_ALIGNED = dict(euler_parameters=[0.7071067811865476, 0.0, 0.0, -0.7071067811865475],
                   velocity=[0.0, 150.0 * L1 / 2, 0.0], angular_velocity=[0.0, 0.0, -75.0])
ROD_MISALIGNED = dict(  # turned 0.2 degrees about eta
    euler_parameters=[0.707105704201605, 0.00123413352292393, 0.0012341335229239302, -0.7071057042016049],
    velocity=[0.0, 150.0 * L1 / 2, 0.0], angular_velocity=[0.26179885614177995, 0.0, -74.99954307433428])

# The lubricated Sec. 6.1: an ISO VG 46 oil at 40 C in the short-bearing (Ocvirk) film.
OIL = dict(comment="ISO VG 46 oil at 40 C; see make_slider_crank_models.py", viscosity=0.04,
           cavitation="half_sommerfeld", method="short", film_thickness_limit=2e-6,
           transition_width=2e-6)


def spatial_model(texts, clearance=False, pin_tilt_degrees=None):
    """Sec. 6.2: crank about +y, vertical at the start; slider along x on a guide offset in y."""
    m = clearjoint.Model(texts["name"], gravity=[0.0, 0.0, -9.81], notes=texts["notes"])
    m.add_body("crank", mass=0.12, inertia=[1e-4, 1e-4, 1e-5], position=[0.0, 0.0, LC / 2],
               angular_velocity=[0.0, 2 * math.pi, 0.0])
    # The rod's frame: eta from the crank pin to the slider, xi = eta x z, zeta = xi x eta.
    m.add_body("rod", mass=0.50, inertia=[0.004, 0.0004, 0.004],
               position=[SLIDER_X / 2, OFFSET / 2, LC / 2],
               euler_parameters=[0.8356569510090066, -0.1486370335465707, 0.09259596078916618,
                                 -0.5205866695703394])
    m.add_body("slider", mass=0.50, inertia=[1e-4, 1e-4, 1e-4], position=[SLIDER_X, OFFSET, 0.0])
    if not clearance:
        m.add_revolute("crank-ground", "ground", "crank", point_i=ORIGIN, point_j=[0.0, 0.0, -LC / 2],
                       axis_i=Y, axis_j=Y)
    m.add_spherical("crank-rod", "crank", "rod", point_i=[0.0, 0.0, LC / 2], point_j=[0.0, -LR / 2, 0.0])
    m.add_universal("rod-slider", "rod", "slider", point_i=[0.0, LR / 2, 0.0], point_j=ORIGIN,
                    axis_i=X, axis_j=Z)
    m.add_translational("slider-ground", "ground", "slider", point_i=[0.0, OFFSET, 0.0], point_j=ORIGIN,
                        axis_i=X, axis_j=X)
    m.hold_position("crank")  # all six components
    if clearance and pin_tilt_degrees is not None:
        # The pin in the ground tilted from y about x.
        tilt = math.radians(pin_tilt_degrees)
        add_table2_pin(m, "ground-crank pin", dict(body="crank", point=[0.0, 0.0, -LC / 2], axis=Y),
                       dict(body="ground", point=ORIGIN, axis=[0.0, math.cos(tilt), math.sin(tilt)]))
    elif clearance:
        add_table2_joint(m, "ground-crank clearance", dict(body="crank", point=[0.0, 0.0, -LC / 2], axis=Y),
                         dict(body="ground", point=ORIGIN, axis=Y))
    if clearance:
        m.set_initial_conditions(
            comment="crank vertical, centred on the journal, 2 pi rad/s about +y: v = w x r = (2 pi 0.05, 0, 0)",
            hold_positions=[dict(body="crank", components=ALL_SIX)],
            hold_velocities=[dict(body="crank", component=c, value=v) for c, v in
                             (("vx", 2 * math.pi * LC / 2), ("vy", 0.0), ("vz", 0.0), ("wx", 0.0),
                              ("wy", 2 * math.pi), ("wz", 0.0))])
    else:
        m.set_initial_conditions(comment="crank pose (vertical) and angular velocity held; rod and slider follow")
        m.hold_position("crank")
        m.hold_velocity("crank", "wy", 2 * math.pi)
    m.set_solver(**PAPER_SOLVER)
    m.set_output(bodies=["crank", "rod", "slider"])
    return m


BUILT = {
    "slider_crank_planar_ideal.json": lambda t: planar_model(t),
    "slider_crank_planar_clearance_aligned.json": lambda t: planar_model(t, ROD_ALIGNED, clearance=True),
    "slider_crank_planar_clearance_misaligned.json": lambda t: planar_model(t, ROD_MISALIGNED, clearance=True),
    "slider_crank_planar_clearance_lubricated.json": lambda t: planar_model(t, ROD_ALIGNED, clearance=True,
                                                                            lubrication=OIL),
    "slider_crank_spatial_ideal.json": lambda t: spatial_model(t),
    "slider_crank_spatial_clearance.json": lambda t: spatial_model(t, clearance=True),
    "slider_crank_planar_clearance_pin_in_hole.json": lambda t: planar_model(t, ROD_ALIGNED, clearance=True,
                                                                             pin_in_hole=True),
    "slider_crank_spatial_pin_in_hole_misaligned.json": lambda t: spatial_model(t, clearance=True,
                                                                                pin_tilt_degrees=0.3),
}


@pytest.mark.parametrize("name", sorted(BUILT))
def test_a_shipped_slider_crank_rebuilt_by_builder_calls_equals_its_file_and_runs_bit_for_bit_alike(models_dir, name, tmp_path):
    file_dict = shipped(models_dir, name)
    model = BUILT[name](file_dict)
    model.validate()
    assert model.to_dict() == file_dict
    model.save(tmp_path / name)
    assert json.loads((tmp_path / name).read_text()) == file_dict
    assert_same_short_run(model.to_dict(), file_dict)


def test_every_model_file_is_rebuilt_and_every_shipped_one_is_built_by_the_test(models_dir):
    files = sorted(p.name for p in models_dir.glob("*.json"))
    assert files == sorted(BUILT)


# Every model file shipped, relative to the repository: the slider-cranks users, tests and docs load
# (models/) and the base model of the reproduction's clearance studies (reproduction/models/).
SHIPPED = sorted(str(p.relative_to(ROOT)) for folder in ("models", "reproduction/models")
                 for p in (ROOT / folder).rglob("*.json"))


@pytest.mark.parametrize("name", SHIPPED)
def test_a_shipped_model_read_and_written_back_equals_its_file_and_runs_bit_for_bit_alike(models_dir, name):
    file_dict = shipped(models_dir.parent, name)
    from_dict = clearjoint.Model.from_dict(file_dict)
    loaded = clearjoint.Model.load(models_dir.parent / name)
    assert from_dict.to_dict() == file_dict
    assert loaded == from_dict
    assert_same_short_run(loaded.to_dict(), file_dict)


def test_the_shipped_models_are_exactly_the_files_make_slider_crank_models_writes():
    # No file the generator does not write (a dead model), none it writes left out or stale.
    spec = importlib.util.spec_from_file_location("make_slider_crank_models",
                                                  ROOT / "models" / "make_slider_crank_models.py")
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    written = generator.model_files()
    assert sorted(written) == SHIPPED
    for relative, model in written.items():
        assert shipped(ROOT, relative) == json.loads(json.dumps(model)), relative


def test_changing_the_dict_of_to_dict_leaves_the_model_as_it_was(models_dir):
    model = clearjoint.Model.load(models_dir / "slider_crank_spatial_clearance.json")
    d = model.to_dict()
    d["bodies"][0]["inertia"][0] = 1.0
    d["forces"][0]["bearing"]["radius"] = 1.0
    assert model.to_dict() == shipped(models_dir, "slider_crank_spatial_clearance.json")


def test_set_solver_changes_only_the_settings_given(models_dir):
    model = clearjoint.Model.load(models_dir / "slider_crank_planar_ideal.json")
    model.set_solver(end_time=0.1)
    expected = shipped(models_dir, "slider_crank_planar_ideal.json")["solver"]
    expected["end_time"] = 0.1
    assert model.to_dict()["solver"] == expected


# --- Every field of the format.

def schema_fields():
    """The fields of each object of docs/schema/model.schema.json, by a name for the object."""
    schema = json.loads(SCHEMA.read_text())
    top = schema["properties"]
    defs = schema["$defs"]
    forces = {f["properties"]["type"]["const"]: f["properties"] for f in defs["force"]["oneOf"]}
    clearance = forces["clearance_revolute"]
    fields = {"model": top, "body": defs["body"]["properties"], "joint": defs["joint"]["properties"],
              "point_load": forces["point_load"], "spring_damper": forces["spring_damper"],
              "clearance_revolute": clearance, "clearance_part": defs["clearance_part"]["properties"],
              "pin": defs["pin"]["properties"], "stops": defs["pin"]["properties"]["stops"]["items"]["properties"],
              "initial_conditions": top["initial_conditions"]["properties"],
              "hold_positions": top["initial_conditions"]["properties"]["hold_positions"]["items"]["properties"],
              "hold_velocities": top["initial_conditions"]["properties"]["hold_velocities"]["items"]["properties"],
              "solver": top["solver"]["properties"], "output": top["output"]["properties"]}
    for nested in ("normal_force", "friction", "detection", "lubrication"):
        fields[nested] = clearance[nested]["properties"]
    return {name: set(properties) for name, properties in fields.items()}


def used_fields(d):
    """The fields the model dict `d` uses, by the same names of objects as schema_fields()."""
    used = {}

    def add(kind, obj):
        used.setdefault(kind, set()).update(obj)

    add("model", d)
    for body in d["bodies"]:
        add("body", body)
    for joint in d["joints"]:
        add("joint", joint)
    for force in d["forces"]:
        add(force["type"], force)
        if force["type"] == "clearance_revolute":
            for part in ("bearing", "journal", "hole"):
                if part in force:
                    add("clearance_part", force[part])
            if "pin" in force:
                add("pin", force["pin"])
                for stop in force["pin"]["stops"]:
                    add("stops", stop)
            for nested in ("normal_force", "friction", "detection", "lubrication"):
                if nested in force:
                    add(nested, force[nested])
    for kind in ("initial_conditions", "solver", "output"):
        add(kind, d[kind])
    for kind in ("hold_positions", "hold_velocities"):
        for entry in d["initial_conditions"][kind]:
            add(kind, entry)
    return used


def every_field_model():
    """A pendulum on a lubricated clearance joint, pushed by a spring, a load and a driven arm:
    one model that writes every field of the format."""
    m = clearjoint.Model("every field", gravity=[0.0, -9.81, 0.0], notes="notes", comment="comment")
    m.add_body("arm", mass=1.0, inertia=[0.01, 0.01, 0.001], position=[0.0, -0.2, 0.0],
               euler_parameters=[1.0, 0.0, 0.0, 0.0], velocity=[0.0, 0.0, 0.0],
               angular_velocity=[0.0, 0.0, 0.0], comment="c", notes="n")
    m.add_body("wheel", mass=0.5, inertia=[0.002, 0.002, 0.004], position=[0.5, 0.0, 0.0])
    m.add_body("block", mass=0.2, inertia=[1e-4, 1e-4, 1e-4], position=[1.0, 0.0, 0.0])
    m.add_revolute("wheel pin", "ground", "wheel", point_i=[0.5, 0.0, 0.0], point_j=ORIGIN, axis_i=Z,
                   axis_j=Z, comment="c", notes="n")
    m.add_angle_driver("wheel motor", "ground", "wheel", axis_i=Z, angle_rate=1.0, angle_acceleration=0.5)
    m.add_fixed("block weld", "ground", "block", point_i=[1.0, 0.0, 0.0], point_j=ORIGIN)
    m.add_spring_damper("spring", "wheel", "arm", point_i=[0.05, 0.0, 0.0], point_j=[0.0, -0.1, 0.0],
                        stiffness=10.0, damping=0.1, free_length=0.55, comment="c", notes="n")
    m.add_point_load("push", "arm", point=[0.0, -0.2, 0.0], force=[0.1, 0.0, 0.0],
                     moment=[0.0, 0.0, 0.01], comment="c", notes="n")
    # A pin of the wheel through a hole in the block: the pin-in-hole geometry's fields.
    m.add_clearance_revolute(
        "wheel pin clearance", geometry="pin_in_hole",
        hole=dict(body="block", point=[-0.5, 0.0, 0.0], axis=Z, radius=0.01, length=0.02),
        pin=dict(body="wheel", point=ORIGIN, axis=Z, radius=0.0099, comment="c", notes="n",
                 stops=[dict(position=0.0101, outer_radius=0.015, comment="c", notes="n")]),
        normal_force=dict(model="hertz", stiffness=1e10))
    m.add_clearance_revolute(
        "pivot", comment="c", notes="n",
        bearing=dict(body="arm", point=[0.0, 0.2, 0.0], axis=Z, radius=0.01, length=0.02, comment="c",
                     notes="n"),
        journal=dict(body="ground", point=ORIGIN, axis=Z, radius=0.0099, length=0.0198),
        normal_force=dict(model="hunt_crossley", stiffness=1e10, exponent=1.5, restitution=0.8,
                          minimum_impact_speed=1e-3, comment="c", notes="n"),
        friction=dict(coefficient=0.1, velocity_coefficient=1000.0, comment="c", notes="n"),
        detection=dict(certify=True, exact_fallback=False, parallel_angle_tolerance=1e-9, comment="c",
                       notes="n"),
        lubrication=dict(viscosity=0.04, film_thickness_limit=2e-6, transition_width=1e-6, method="grid",
                         cavitation="mass_conserving", grid=[16, 4], allow_large_grid=False,
                         groove_direction=[0.0, 1.0, 0.0],
                         supply_pressure=1e4, comment="c", notes="n"))
    m.set_initial_conditions(comment="c", notes="n")
    m.hold_position("block", ["x", "y", "z", "rx", "ry", "rz"], comment="c", notes="n")
    m.hold_velocity("arm", "vx", 0.0, comment="c", notes="n")
    m.set_solver(start_time=0.0, end_time=0.01, report_step=1e-3, relative_tolerance=1e-7,
                 absolute_tolerance=1e-7, initial_step=1e-6, minimum_step=1e-14, max_steps=100000,
                 baumgarte_alpha=5.0, baumgarte_beta=5.0, comment="c", notes="n")
    m.set_output(bodies=["arm", "wheel"], force_elements=["pivot", "spring"], decimation=2, comment="c",
                 notes="n")
    return m


def test_the_builder_writes_every_field_of_the_model_schema_and_the_model_file_reader_takes_them():
    m = every_field_model()
    assert used_fields(m.to_dict()) == schema_fields()
    m.validate()
    assert clearjoint.Model.from_dict(m.to_dict()) == m
    result = clearjoint.simulate(m.to_dict())
    # Decimation 2 over 10 reports: the rows of report times 0, 2, ..., 10.
    assert len(result["body_arm"]["time"]) == 6
    assert "force_pivot" in result.tables and "body_block" not in result.tables


def test_the_builder_methods_take_the_fields_of_their_objects_as_keyword_arguments():
    import inspect

    def parameters(method):
        return set(inspect.signature(method).parameters) - {"self"}

    fields = schema_fields()
    assert parameters(clearjoint.Model.add_body) == fields["body"]
    assert parameters(clearjoint.Model.add_joint) == fields["joint"]
    assert parameters(clearjoint.Model.add_point_load) == fields["point_load"] - {"type"}
    assert parameters(clearjoint.Model.add_spring_damper) == fields["spring_damper"] - {"type"}
    assert parameters(clearjoint.Model.add_clearance_revolute) == fields["clearance_revolute"] - {"type"}
    assert parameters(clearjoint.Model.set_initial_conditions) == fields["initial_conditions"]
    assert parameters(clearjoint.Model.hold_position) == fields["hold_positions"]
    assert parameters(clearjoint.Model.hold_velocity) == fields["hold_velocities"]
    assert parameters(clearjoint.Model.set_solver) == fields["solver"]
    assert parameters(clearjoint.Model.set_output) == fields["output"]
    assert parameters(clearjoint.Model) == {"name", "gravity", "notes", "comment"}


# --- Bad input: arguments refused as they are given, naming the field they would become.

def small_model():
    m = clearjoint.Model("small", gravity=[0.0, -9.81, 0.0])
    m.add_body("crank", mass=1.0, inertia=[0.01, 0.01, 0.01], position=[0.1, 0.0, 0.0])
    return m


@pytest.mark.parametrize("call, error, message", [
    (lambda m: m.add_body("rod", mass="heavy", inertia=[1, 1, 1], position=ORIGIN), TypeError,
     'bodies[1].mass = "heavy": must be a number (not str)'),
    (lambda m: m.add_body("rod", mass=True, inertia=[1, 1, 1], position=ORIGIN), TypeError,
     "bodies[1].mass = true: must be a number (not bool)"),
    (lambda m: m.add_body("rod", mass=np.bool_(True), inertia=[1, 1, 1], position=ORIGIN), TypeError,
     "bodies[1].mass = True: must be a number (not bool_)"),
    (lambda m: m.add_body("rod", mass=None, inertia=[1, 1, 1], position=ORIGIN), TypeError,
     "bodies[1].mass = null: must be a number (not NoneType)"),
    (lambda m: m.add_body("rod", mass=1.0, inertia="1 1 1", position=ORIGIN), TypeError,
     'bodies[1].inertia = "1 1 1": must be an array of 3 numbers (not str)'),
    (lambda m: m.add_body("rod", mass=1.0, inertia=[1, 1, "1"], position=ORIGIN), TypeError,
     'bodies[1].inertia[2] = "1": must be a number (not str)'),
    (lambda m: m.add_body("rod", mass=1.0, inertia=[1, 1], position=ORIGIN), ValueError,
     "bodies[1].inertia = [1, 1]: must be an array of 3 numbers"),
    (lambda m: m.add_body("rod", mass=1.0, inertia=np.ones((1, 3)), position=ORIGIN), TypeError,
     "bodies[1].inertia = array([[1., 1., 1.]]): must be an array of 3 numbers (not ndarray)"),
    (lambda m: m.add_body("rod", mass=float("nan"), inertia=[1, 1, 1], position=ORIGIN), ValueError,
     "bodies[1].mass = NaN: must be finite (JSON has no NaN or infinity)"),
    (lambda m: m.add_body(7, mass=1.0, inertia=[1, 1, 1], position=ORIGIN), TypeError,
     "bodies[1].name = 7: must be a string (not int)"),
    (lambda m: m.add_revolute("pin", "ground", 3), TypeError,
     "joints[0].body_j = 3: must be a string (not int)"),
    (lambda m: m.add_point_load("push", "crank", force=[0, 0, True]), TypeError,
     "forces[0].force[2] = true: must be a number (not bool)"),
    (lambda m: m.add_clearance_revolute("gap", bearing=dict(body="crank", axis=Z, radius="10 mm", length=0.02),
                                        journal={}, normal_force={}), TypeError,
     'forces[0].bearing.radius = "10 mm": must be a number (not str)'),
    (lambda m: m.add_clearance_revolute("gap", bearing={}, journal={}, normal_force={},
                                        lubrication=dict(viscosty=0.04)), ValueError,
     "forces[0].lubrication.viscosty: unknown field (expected viscosity, cavitation, method, grid, "
     "allow_large_grid, groove_direction, supply_pressure, film_thickness_limit, transition_width)"),
    (lambda m: m.add_clearance_revolute("gap", bearing={}, journal={}, normal_force={},
                                        detection=dict(certify=1)), TypeError,
     "forces[0].detection.certify = 1: must be True or False (not int)"),
    (lambda m: m.add_clearance_revolute("gap", bearing=[0.01, 0.02], journal={}, normal_force={}), TypeError,
     "forces[0].bearing = [0.01, 0.02]: must be a dict (a JSON object), not list"),
    (lambda m: m.hold_position("crank", "x"), TypeError,
     'initial_conditions.hold_positions[0].components = "x": must be a list of strings (not str)'),
    (lambda m: m.hold_velocity("crank", "wz", "fast"), TypeError,
     'initial_conditions.hold_velocities[0].value = "fast": must be a number (not str)'),
    (lambda m: m.set_solver(end_time="1 s"), TypeError, 'solver.end_time = "1 s": must be a number (not str)'),
    (lambda m: m.set_output(bodies="crank"), TypeError,
     'output.bodies = "crank": must be a list of strings (not str)'),
    (lambda m: setattr(m, "gravity", [0, -9.81]), ValueError, "gravity = [0, -9.81]: must be an array of 3 numbers"),
])
def test_an_argument_of_the_wrong_type_is_refused_naming_the_field_and_the_model_is_unchanged(call, error, message):
    m = small_model()
    before = m.to_dict()
    with pytest.raises(error) as caught:
        call(m)
    assert str(caught.value) == message
    assert m.to_dict() == before


@pytest.mark.parametrize("change, message", [
    # Checked by the C++ model builder (dynamics/src/model_builder.cpp), as for a file.
    (lambda m: m.add_revolute("pin", "ground", "crnk"),
     'joints[0].body_j = "crnk": no body of that name (use "ground" for the world frame)'),
    (lambda m: m.add_body("crank", mass=1.0, inertia=[0.01, 0.01, 0.01], position=ORIGIN),
     'bodies[1].name = "crank": used by bodies[0] already'),
    (lambda m: (m.add_spherical("pin", "ground", "crank"), m.add_spherical("pin", "ground", "crank")),
     'joints[1].name = "pin": used by joints[0] already'),
    (lambda m: m.add_point_load("push", "wheel"),
     'forces[0].body = "wheel": no body of that name (use "ground" for the world frame)'),
    (lambda m: m.hold_velocity("crank", "omega", 1.0),
     'initial_conditions.hold_velocities[0].component = "omega": must be one of vx, vy, vz, wx, wy, wz'),
    # Checked by the C++ model reader (dynamics/src/model_file.cpp): the model's name first.
    (lambda m: m.add_body("rod", mass=-1.0, inertia=[0.01, 0.01, 0.01], position=ORIGIN),
     "<Model>: bodies[1].mass = -1: must be positive"),
    (lambda m: m.add_joint("pin", "hinge", "ground", "crank"),
     '<Model>: joints[0].type = "hinge": unknown joint type'),
    (lambda m: m.add_clearance_revolute("gap", bearing=dict(body="crank", axis=Z, length=0.02),
                                        journal=dict(body="ground", axis=Z, radius=0.0099, length=0.0198),
                                        normal_force=dict(model="hertz", stiffness=1e10)),
     "<Model>: forces[0].bearing.radius: missing"),
    (lambda m: m.set_output(decimation=0.5), "<Model>: output.decimation = 0.5: must be a whole number"),
])
def test_validate_refuses_a_bad_model_with_the_message_a_model_file_gets(change, message):
    m = small_model()
    m.validate()
    change(m)
    with pytest.raises(ValueError) as caught:
        m.validate()
    assert str(caught.value).startswith(message), str(caught.value)
    with pytest.raises(ValueError) as from_simulate:
        clearjoint.simulate(m.to_dict())
    assert str(from_simulate.value) == str(caught.value).replace("<Model>", "<dict>")


def test_save_refuses_a_bad_model_and_writes_nothing(tmp_path):
    m = small_model()
    m.add_revolute("pin", "ground", "crnk")
    with pytest.raises(ValueError, match=r'joints\[0\]\.body_j = "crnk"'):
        m.save(tmp_path / "bad.json")
    assert not (tmp_path / "bad.json").exists()
    m.save(tmp_path / "bad.json", validate=False)
    assert clearjoint.Model.load(tmp_path / "bad.json", validate=False) == m


def test_reading_a_bad_model_gives_the_message_of_simulate(tmp_path, models_dir):
    d = shipped(models_dir, "slider_crank_planar_ideal.json")
    d["bodies"][1]["mas"] = 0.3
    with pytest.raises(ValueError) as read:
        clearjoint.Model.from_dict(d)
    with pytest.raises(ValueError) as ran:
        clearjoint.simulate(d)
    assert str(read.value) == str(ran.value)
    assert str(read.value).startswith("<dict>: bodies[1].mas: unknown field")
    # Without validation the builder's own reading names the field alike.
    with pytest.raises(ValueError, match=r"^bodies\[1\]\.mas: unknown field \(expected name, mass, "):
        clearjoint.Model.from_dict(d, validate=False)
    path = tmp_path / "typo.json"
    path.write_text(json.dumps(d))
    with pytest.raises(ValueError, match=re.escape(f"{path}: bodies[1].mas: unknown field")):
        clearjoint.Model.load(path)


def test_reading_refuses_what_the_builder_would_refuse(models_dir):
    d = shipped(models_dir, "slider_crank_spatial_clearance.json")
    d["forces"][0]["friction"]["coefficient"] = "0.1"
    with pytest.raises(ValueError, match=r'^<dict>: forces\[0\]\.friction\.coefficient = "0\.1": must be a number'):
        clearjoint.Model.from_dict(d)
    with pytest.raises(TypeError, match=r'^forces\[0\]\.friction\.coefficient = "0\.1": must be a number'):
        clearjoint.Model.from_dict(d, validate=False)
    d = shipped(models_dir, "slider_crank_spatial_clearance.json")
    d["forces"][0]["type"] = "gap"
    with pytest.raises(ValueError, match=r'^forces\[0\]\.type = "gap": unknown force type'):
        clearjoint.Model.from_dict(d, validate=False)
    with pytest.raises(TypeError, match=r"^model = list: must be a dict"):
        clearjoint.Model.from_dict([d])
    with pytest.raises(TypeError, match=r"^validate = 1: must be True or False"):
        clearjoint.Model.from_dict(d, validate=1)


def test_loading_without_validation_refuses_a_key_given_twice(tmp_path):
    path = tmp_path / "twice.json"
    path.write_text('{"name": "a", "name": "b", "bodies": []}')
    with pytest.raises(ValueError, match=r"key given twice"):
        clearjoint.Model.load(path, validate=False)


def test_an_inconsistent_mechanism_is_refused_by_validate_as_by_simulate():
    m = small_model()
    # The pin at the world origin and at the crank's centre, the crank held at x = 0.1: the
    # revolute joint cannot close.
    m.add_revolute("pin", "ground", "crank", axis_i=Z)
    m.hold_position("crank", ["x"])
    with pytest.raises(clearjoint.SolverError, match=r"at joint 'pin' \(revolute\)") as caught:
        m.validate()
    with pytest.raises(clearjoint.SolverError) as from_simulate:
        clearjoint.simulate(m.to_dict())
    assert str(from_simulate.value) == str(caught.value)


# --- The guide's example (docs/python.md, "Building a model in Python").

def guide_section(title):
    text = GUIDE.read_text()
    section = text.split(f"## {title}\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", section, flags=re.S)


def test_the_guides_builder_example_runs_and_builds_the_lubricated_slider_crank(tmp_path, models_dir):
    blocks = guide_section("Building a model in Python")
    assert len(blocks) == 1
    (tmp_path / "models").symlink_to(models_dir)
    script = tmp_path / "example.py"
    script.write_text("import clearjoint\n" + blocks[0])
    run = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    # The example saves the model it builds: the shipped lubricated Sec. 6.1 but for its free
    # texts (name, notes, comments) and its end time.
    written = json.loads((tmp_path / "slider_crank_lubricated.json").read_text())
    expected = shipped(models_dir, "slider_crank_planar_clearance_lubricated.json")
    expected["solver"]["end_time"] = written["solver"]["end_time"]

    def without_texts(value):
        if isinstance(value, dict):
            return {k: without_texts(v) for k, v in value.items() if k not in ("notes", "comment")}
        if isinstance(value, list):
            return [without_texts(v) for v in value]
        return value
    written.pop("name")
    expected.pop("name")
    assert without_texts(written) == without_texts(expected)
    assert run.stdout.strip().splitlines()[-1] == "True"
