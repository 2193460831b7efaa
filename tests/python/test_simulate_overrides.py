# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.simulate(overrides=..., engine=...): model values set without copying the model,
with the grammar and the errors of `clearjoint simulate --set` (dynamics/model_overrides.hpp)."""
import json
import re
import subprocess

import numpy as np
import pytest

import clearjoint
from clearjoint import _core

# A short run of the paper's spatial slider-crank with its clearance joint, and two values of the
# joint changed: the same edits made by hand to the file and given as overrides.
OVERRIDES = {
    "solver.end_time": 0.02,
    "/solver/report_step": 1e-3,
    "forces[0].friction.coefficient": 0.05,
    "forces[0].normal_force.restitution": np.float64(0.6),
}


def edited_by_hand(model):
    model["solver"]["end_time"] = 0.02
    model["solver"]["report_step"] = 1e-3
    model["forces"][0]["friction"]["coefficient"] = 0.05
    model["forces"][0]["normal_force"]["restitution"] = 0.6
    return model


@pytest.fixture
def model_path(models_dir):
    return models_dir / "slider_crank_spatial_clearance.json"


@pytest.fixture
def hand_edited(model_path, tmp_path):
    with open(model_path) as f:
        model = edited_by_hand(json.load(f))
    path = tmp_path / "edited.json"
    path.write_text(json.dumps(model))
    return path


def same_bits(a, b):
    """Equal bit patterns, NaN matching NaN (a contact slot not in use)."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    both_nan = np.isnan(a) & np.isnan(b)
    return a.shape == b.shape and bool(np.all((a.view(np.int64) == b.view(np.int64)) | both_nan))


def assert_same_tables(a, b):
    assert sorted(a.tables) == sorted(b.tables)
    for name, columns in a.tables.items():
        assert list(columns) == list(b.tables[name]), name
        for column, values in columns.items():
            assert same_bits(values, b.tables[name][column]), f"{name}.{column}"


def test_overrides_of_a_model_file_give_the_arrays_of_the_file_edited_by_hand_bit_for_bit(model_path, hand_edited):
    result = clearjoint.simulate(model_path, overrides=OVERRIDES)
    assert_same_tables(result, clearjoint.simulate(hand_edited))
    assert result["energy"]["time"][-1] == 0.02
    assert len(result["energy"]["time"]) == 21
    assert result.summary["overrides"] == {"solver.end_time": 0.02, "/solver/report_step": 1e-3,
                                           "forces[0].friction.coefficient": 0.05,
                                           "forces[0].normal_force.restitution": 0.6}


def test_overrides_of_a_model_dict_give_the_same_arrays(model_path, hand_edited):
    with open(model_path) as f:
        model = json.load(f)
    assert_same_tables(clearjoint.simulate(model, overrides=OVERRIDES), clearjoint.simulate(hand_edited))
    assert model["solver"]["end_time"] == 1.0, "the caller's dict must be left as it was"


def test_a_run_folder_holds_the_model_as_run_and_the_overrides(model_path, hand_edited, tmp_path):
    result = clearjoint.simulate(model_path, overrides=OVERRIDES, out=tmp_path / "run")
    with open(tmp_path / "run" / "model.json") as f, open(hand_edited) as g:
        assert json.load(f) == json.load(g)
    with open(tmp_path / "run" / "summary.json") as f:
        summary = json.load(f)
    assert list(summary["overrides"]) == list(OVERRIDES)
    assert summary["overrides"] == result.summary["overrides"]
    assert_same_tables(clearjoint.read_run(tmp_path / "run"), clearjoint.simulate(hand_edited))


def test_the_command_line_and_python_give_the_same_run_for_the_same_overrides(model_path, cli, tmp_path):
    out = tmp_path / "cli"
    subprocess.run([str(cli), "simulate", str(model_path), "--out", str(out), "--end-time", "0.02",
                    "--set", "/solver/report_step=1e-3", "--set", "forces[0].friction.coefficient=0.05",
                    "--set", "forces[0].normal_force.restitution=0.6"], check=True, capture_output=True)
    assert_same_tables(clearjoint.read_run(out), clearjoint.simulate(model_path, overrides=OVERRIDES))


@pytest.mark.parametrize("overrides, message", [
    ({"solver.end_tme": 1.0}, "solver.end_tme: unknown field (expected start_time, end_time,"),
    ({"bodies[5].mass": 1.0}, "overrides['bodies[5].mass']: bodies has 3 elements, [0] to [2]: there is no [5]"),
    ({"bodies.1.mass": 1.0}, "overrides['bodies.1.mass']: bodies is an array: write its elements as bodies[1]"),
    ({"bodies[1].mass": "heavy"}, 'bodies[1].mass = "heavy": must be a number'),
    ({"gravity": [0.0, -9.81]}, "gravity = [0.0,-9.81]: must be an array of 3 numbers"),
    ({"solver.end_time": 0.02, "/solver/end_time": 0.03},
     "overrides['/solver/end_time']: sets solver.end_time, which overrides['solver.end_time'] sets too"),
    ({"solver.end_time": float("nan")}, "overrides['solver.end_time'] = nan: must be finite"),
])
def test_a_bad_override_is_a_value_error_naming_it(model_path, overrides, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        clearjoint.simulate(model_path, overrides=overrides)


def test_overrides_that_are_not_a_dict_of_paths_are_a_type_error(model_path):
    with pytest.raises(TypeError, match=re.escape("overrides = [('solver.end_time', 1)]: must be a dict")):
        clearjoint.simulate(model_path, overrides=[("solver.end_time", 1)])
    with pytest.raises(TypeError, match="overrides: key 3 is a int; a path is a str"):
        clearjoint.simulate(model_path, overrides={3: 1.0})


def test_an_unknown_engine_is_a_value_error_naming_the_engines_of_this_build(model_path):
    engines = ", ".join(_core.engines())
    with pytest.raises(ValueError, match=re.escape(f"engine = 'bogus': unknown engine; the engines of this "
                                                   f"build are {engines}")):
        clearjoint.simulate(model_path, engine="bogus")
    with pytest.raises(TypeError, match=re.escape("engine = 3: must be a str, one of clearjoint")):
        clearjoint.simulate(model_path, engine=3)


def test_an_unknown_engine_gets_the_command_lines_refusal_under_the_keywords_name(model_path, cli, tmp_path):
    # One check of an engine's name (engines/choice) for both front-ends: the same words after the
    # field, which each names in its own terms (--engine, engine).
    done = subprocess.run([str(cli), "simulate", str(model_path), "--out", str(tmp_path / "out"),
                           "--engine", "bogus"], capture_output=True, text=True)
    assert done.returncode == 2
    prefix = "clearjoint simulate: --engine"
    assert done.stderr.startswith(prefix), done.stderr
    with pytest.raises(ValueError) as refusal:
        clearjoint.simulate(model_path, engine="bogus")
    assert str(refusal.value) == "engine" + done.stderr[len(prefix):].rstrip("\n")


def test_a_bad_format_gets_the_command_lines_refusal_under_the_keywords_name(model_path, cli, tmp_path):
    # One check of a run's format (dynamics' run_format) for both front-ends.
    done = subprocess.run([str(cli), "simulate", str(model_path), "--out", str(tmp_path / "cli"),
                           "--format", "bogus"], capture_output=True, text=True)
    assert done.returncode == 2
    prefix = "clearjoint simulate: --format"
    first_line = done.stderr.splitlines()[0]
    assert first_line.startswith(prefix), done.stderr
    with pytest.raises(ValueError) as refusal:
        clearjoint.simulate(model_path, out=tmp_path / "python", format="bogus")
    assert str(refusal.value) == "format" + first_line[len(prefix):]


@pytest.mark.skipif("simbody" in _core.engines(), reason="this package is built with Simbody")
def test_engine_simbody_without_simbody_says_the_package_was_built_without_it(model_path):
    with pytest.raises(ValueError, match="engine = 'simbody': this clearjoint was built without Simbody"):
        clearjoint.simulate(model_path, engine="simbody")


@pytest.mark.skipif("simbody" not in _core.engines(), reason="this package is built without Simbody")
def test_engine_simbody_gives_the_run_of_the_command_lines_engine_simbody_bit_for_bit(models_dir, cli, tmp_path):
    # The planar aligned slider-crank, which the Simbody route supports (tests/apps/
    # simulate_engine_test.sh), over 20 ms.
    model = models_dir / "slider_crank_planar_clearance_aligned.json"
    short = {"solver.end_time": 0.02, "solver.report_step": 1e-3}
    out = tmp_path / "cli"
    subprocess.run([str(cli), "simulate", str(model), "--out", str(out), "--engine", "simbody",
                    "--end-time", "0.02", "--report-step", "1e-3"], check=True, capture_output=True)
    result = clearjoint.simulate(model, engine="simbody", overrides=short)
    assert_same_tables(result, clearjoint.read_run(out))
    # Not clearjoint's own run under another name: the two engines' slider positions differ in
    # their last bits at least (docs/engines.md: they agree to 1e-6 m, not bit for bit).
    own = clearjoint.simulate(model, overrides=short)
    assert not same_bits(result["body_slider"]["x"], own["body_slider"]["x"])
