# SPDX-License-Identifier: BSD-3-Clause
"""A pin-in-hole joint's run (docs/dynamics.md, "The pin-in-hole geometry") plotted, read back and
viewed: its scenario column holds PinInHoleScenario codes, so its names and colours come from that
table, chosen by the joint's geometry in the run folder's model.json."""
import json
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import to_hex  # noqa: E402

import clearjoint  # noqa: E402
from clearjoint import plot  # noqa: E402
from clearjoint.plot import scenario_colours  # noqa: E402
from clearjoint.view import frames  # noqa: E402
from clearjoint.view.frames import viewer_data  # noqa: E402
from run_fixtures import short_model, write_run  # noqa: E402

MODEL = "slider_crank_spatial_pin_in_hole_misaligned.json"
JOINT_TABLE = "force_ground-crank_pin"
# 40 ms: free flight, then one edge, one stop and edges with stops (codes 0, 1, 5, 8).
END_TIME = 0.04


def pin_in_hole_labels():
    return {int(s): label for s, label in
            ((code, plot.scenario_name(code, "pin_in_hole")) for code in clearjoint.PinInHoleScenario)}


@pytest.fixture(scope="module")
def runs(tmp_path_factory, models_dir, cli):
    base = tmp_path_factory.mktemp("pin_in_hole")
    model = short_model(models_dir, MODEL, end_time=END_TIME)
    model_path = base / "model.json"
    model_path.write_text(json.dumps(model))
    # run.h5 carries no model of its own: `simulate` writes model.json beside it as for CSV files.
    subprocess.run([str(cli), "simulate", str(model_path), "--out", str(base / "hdf5"), "--format", "hdf5"],
                   check=True, stdout=subprocess.DEVNULL)
    return {"csv": write_run(cli, model, base / "csv"),
            "hdf5": base / "hdf5",
            "no_model": write_run(cli, model, base / "no_model"),
            "model": model}


def legend_texts(figure):
    return [text.get_text() for ax in figure.axes if ax.get_legend() is not None
            for text in ax.get_legend().get_texts()]


def test_the_pin_in_hole_table_labels_its_codes_with_the_librarys_names():
    assert plot.scenario_name(clearjoint.PinInHoleScenario.one_edge, "pin_in_hole") == \
        "one hole edge against the pin"
    assert plot.scenario_name(clearjoint.PinInHoleScenario.one_edge) == "(a) single radial"
    assert [row["code"] for row in plot.scenario_table("pin_in_hole")] == \
        [int(s) for s in clearjoint.PinInHoleScenario]


def test_a_pin_in_hole_runs_figure_names_its_scenarios_from_the_pin_in_hole_table(runs):
    figure = plot.joint_figure(runs["csv"])
    names = legend_texts(figure)
    labels = pin_in_hole_labels()
    assert {"one hole edge against the pin", "one stop against its link face",
            "edge and stop contacts together"} <= set(names)
    assert not any(name.startswith("(") for name in names), names  # no Fig. 2 case "(a) ..."
    scenario = plot.joint_series(plot.read_run(runs["csv"]), JOINT_TABLE).scenario
    assert {labels[code] for code in set(scenario.tolist())} <= set(names)
    plt.close(figure)


def test_a_pin_in_hole_runs_curves_take_the_pin_in_hole_colours(runs):
    figure = plot.joint_figure(runs["csv"], panels=("force",))
    collection = next(c for c in figure.axes[0].collections if isinstance(c, LineCollection))
    colours = {to_hex(c) for c in collection.get_colors()}
    table = scenario_colours.PIN_IN_HOLE_SCENARIO_COLOURS
    assert table[clearjoint.PinInHoleScenario.one_stop] in colours
    assert colours <= set(table.values())
    plt.close(figure)


@pytest.mark.parametrize("kind", ["csv", "hdf5"])
def test_a_pin_in_hole_run_read_back_knows_its_geometry_and_scenario_names(runs, kind):
    result = clearjoint.read_run(runs[kind])
    run = plot.read_run(result)
    (joint,) = run.clearance_joints
    assert joint.geometry == "pin_in_hole"
    model_joint = runs["model"]["forces"][0]
    assert joint.bearing_radius == model_joint["hole"]["radius"]
    assert joint.journal_radius == model_joint["pin"]["radius"]
    series = plot.joint_series(run, JOINT_TABLE)
    assert series.geometry == "pin_in_hole"
    codes = set(np.asarray(result.tables[JOINT_TABLE]["scenario"]).tolist())
    assert {plot.scenario_name(code, series.geometry) for code in codes} >= {
        "none", "one hole edge against the pin", "one stop against its link face"}


def test_the_viewer_sends_a_pin_in_hole_joint_its_table_and_its_sizes(runs):
    data = viewer_data(plot.read_run(runs["csv"]))
    (joint,) = data.manifest["joints"]
    assert joint["geometry"] == "pin_in_hole"
    assert [s["label"] for s in joint["scenarios"]] == list(pin_in_hole_labels().values())
    assert joint["bearing_radius"] == 0.01 and joint["journal_radius"] == 0.0099
    assert joint["bearing_length"] == 0.02
    assert joint["axial_clearance"] == pytest.approx(1e-4)  # stops at +-10.1 mm, faces at +-10 mm
    # Contacts were found on the recorded poses by the pin-in-hole detection.
    offset = joint["offset"] + 13
    assert np.isfinite(data.frames[:, offset:offset + 6 * 6]).any()
    # The paper's table stays the run-wide default.
    assert data.manifest["scenarios"][1]["label"] == "(a) single radial"


def single_call_contacts(run, rows):
    """The frames' contact slots of the pin-in-hole joint, recomputed by one detect_pin_in_hole
    call per recorded pose: C_i and the normal in the hole's frame (u, v, a), NaN in unused slots."""
    joint = run.clearance_joints[0]
    dims = clearjoint.PinInHoleDimensions(hole_radius=joint.bearing_radius, hole_length=joint.bearing_length,
                                          pin_radius=joint.journal_radius, stops=list(joint.stops))
    hole_to_body = frames.bearing_frame_B(joint.bearing_axis)
    out = np.full((len(rows), frames.MAX_CONTACTS, frames.CONTACT_FLOATS), np.nan)
    pose = {}
    for side, body in (("hole", joint.bearing_body), ("pin", joint.journal_body)):
        if body == "ground":
            pose[side] = (np.zeros((len(rows), 3)), np.tile(np.eye(3), (len(rows), 1, 1)))
        else:
            table = run.table("body_" + body)
            e = np.column_stack([table[c][rows] for c in ("e0", "e1", "e2", "e3")])
            pose[side] = (np.column_stack([table[c][rows] for c in ("x", "y", "z")]), frames.rotation_matrices(e))
    for n in range(len(rows)):
        r_i, rot_i, r_j, rot_j = pose["hole"][0][n], pose["hole"][1][n], pose["pin"][0][n], pose["pin"][1][n]
        hole_center = r_i + rot_i @ joint.bearing_point
        found = clearjoint.detect_pin_in_hole(dims, hole_center, rot_i @ joint.bearing_axis,
                                              r_j + rot_j @ joint.journal_point, rot_j @ joint.journal_axis,
                                              parallel_angle_tolerance=joint.parallel_angle_tolerance)
        world_to_hole = hole_to_body.T @ rot_i.T
        for slot, contact in enumerate(found.contacts):
            out[n, slot, 0:3] = world_to_hole @ (np.asarray(contact.point_bearing) - hole_center)
            out[n, slot, 3:6] = world_to_hole @ np.asarray(contact.normal)
    return out


def test_the_viewer_detects_a_pin_in_hole_joints_poses_in_one_batch_with_the_single_calls_answers(runs, monkeypatch):
    run = plot.read_run(runs["csv"])
    calls = []
    batch_call = clearjoint.detect_pin_in_hole

    def counted(*args, **kwargs):
        calls.append(np.shape(args[3]))
        return batch_call(*args, **kwargs)

    monkeypatch.setattr(clearjoint, "detect_pin_in_hole", counted)
    data = viewer_data(run)
    monkeypatch.undo()
    rows = np.arange(0, data.manifest["row_count"], data.manifest["decimation_step"])
    assert calls == [(len(rows), 3)], "one batch call over every frame's pose"
    (joint,) = data.manifest["joints"]
    offset = joint["offset"] + frames.JOINT_HEAD_FLOATS
    shown = data.frames[:, offset:offset + frames.MAX_CONTACTS * frames.CONTACT_FLOATS].astype(float)
    expected = single_call_contacts(run, rows).reshape(shown.shape)
    # The same contacts in the same slots; the numbers those of the single calls as the page's
    # Float32 frames hold them (the frame change may round the last double bit differently).
    np.testing.assert_array_equal(np.isnan(shown), np.isnan(expected))
    assert np.isfinite(shown).any()
    np.testing.assert_allclose(shown, expected.astype(np.float32), rtol=4e-7, atol=1e-12)


def test_a_run_folder_without_its_model_keeps_the_papers_table(runs):
    # A folder written before model.json was kept beside the tables.
    (runs["no_model"] / "model.json").unlink()
    run = plot.read_run(runs["no_model"])
    series = plot.joint_series(run, JOINT_TABLE)
    assert series.geometry == "journal_bearing"
    figure = plot.joint_figure(run)
    assert "(a) single radial" in legend_texts(figure)
    plt.close(figure)


def test_clearjoint_plot_writes_the_pin_in_hole_names_into_the_figure(runs, tmp_path, cli):
    done = subprocess.run([str(cli), "plot", str(runs["hdf5"]), "--out", str(tmp_path),
                           "--panels", "orbit", "--format", "svg"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    svg = (tmp_path / "joint_ground-crank_pin.svg").read_text()
    # Matplotlib keeps each text as a comment beside its glyph paths.
    assert "one hole edge against the pin" in svg and "contact scenario (pin in hole)" in svg
    assert "single radial" not in svg
