# SPDX-License-Identifier: BSD-3-Clause
"""Study files: schema and reference errors name the field and value; designs expand to the
expected points; ensemble members and parameters write the expected model values."""
import json
import os

import numpy as np
import pytest

from clearjoint.study import StudyError, expand_study, load_study
from clearjoint.study.expand import member_offsets
from study_fixtures import write_study


def edited(tmp_path, models_dir, edit):
    path = write_study(tmp_path, models_dir)
    with open(path) as f:
        spec = json.load(f)
    edit(spec)
    with open(path, "w") as f:
        json.dump(spec, f)
    return path


def journal(model):
    return model["forces"][0]["journal"]


def test_a_grid_with_members_expands_to_points_times_members(tmp_path, models_dir):
    study = load_study(write_study(tmp_path, models_dir, radial=(0.05, 0.1, 0.3), members=3))
    points, runs, membership = expand_study(study)
    assert len(points) == 3 and len(runs) == 9 and len(membership) == 9
    assert [p.point_id for p in points] == ["axial_clearance_mm=0.1,radial_clearance_mm=0.05",
                                            "axial_clearance_mm=0.1,radial_clearance_mm=0.1",
                                            "axial_clearance_mm=0.1,radial_clearance_mm=0.3"]


def test_parameters_write_offset_plus_scale_times_value(tmp_path, models_dir):
    study = load_study(write_study(tmp_path, models_dir, radial=(0.3,), members=1))
    (_, [run], _) = expand_study(study)
    assert journal(run.model)["radius"] == 0.01 + -0.001 * 0.3
    assert journal(run.model)["length"] == 0.02 + -0.002 * 0.1
    assert run.model["solver"]["end_time"] == study.spec["set"]["/solver/end_time"]


def test_member_zero_is_the_point_unchanged_and_others_scale_the_crank_speed(tmp_path, models_dir):
    study = load_study(write_study(tmp_path, models_dir, radial=(0.1,), members=3))
    _, runs, membership = expand_study(study)
    by_member = {r.member: r.model for r in runs}
    assert member_offsets(3) == [-1, 0, 1] and member_offsets(9)[0] == -4 and member_offsets(1) == [0]
    base = study.base_models[""]
    wy = [h for h in base["initial_conditions"]["hold_velocities"] if h["component"] == "wy"][0]["value"]
    for k, model in by_member.items():
        held = [h for h in model["initial_conditions"]["hold_velocities"] if h["component"] == "wy"][0]
        assert held["value"] == wy * (1.0 + k * 1e-9)
        assert model["bodies"][0]["angular_velocity"][1] == base["bodies"][0]["angular_velocity"][1] * (1.0 + k * 1e-9)
    assert by_member[0]["initial_conditions"] == base["initial_conditions"]


def test_a_point_named_by_two_designs_is_one_point_with_the_larger_member_count(tmp_path, models_dir):
    def add_design(spec):
        spec["designs"].append({"name": "single", "grid": {"radial_clearance_mm": [0.1, 0.5]},
                                "fixed": {"axial_clearance_mm": 0.1}})
    study = load_study(edited(tmp_path, models_dir, add_design))
    points, runs, _ = expand_study(study)
    shared = [p for p in points if p.point_id.endswith("radial_clearance_mm=0.1")][0]
    assert shared.designs == ("radial", "single") and shared.members == 3
    assert len(points) == 4 and len(runs) == 3 * 3 + 1


def test_seeded_random_draws_are_reproducible_and_inside_their_distribution(tmp_path, models_dir):
    def random_design(spec):
        spec["designs"] = [{"name": "draws", "random": {"draws": 50, "seed": 11, "distributions": {
            "radial_clearance_mm": {"uniform": [0.05, 0.5]}, "axial_clearance_mm": {"loguniform": [0.01, 1.0]}}}}]
    path = edited(tmp_path, models_dir, random_design)
    first, second = expand_study(load_study(path))[0], expand_study(load_study(path))[0]
    assert [p.values for p in first] == [p.values for p in second]
    radial = np.array([p.value("radial_clearance_mm") for p in first])
    axial = np.array([p.value("axial_clearance_mm") for p in first])
    assert radial.min() >= 0.05 and radial.max() < 0.5 and axial.min() >= 0.01 and axial.max() < 1.0
    assert len(set(radial)) == 50


def test_zip_pairs_values_element_by_element(tmp_path, models_dir):
    def diagonal(spec):
        spec["designs"] = [{"name": "diagonal", "zip": {"radial_clearance_mm": [0.05, 0.5],
                                                        "axial_clearance_mm": [0.05, 0.5]}}]
    points, _, _ = expand_study(load_study(edited(tmp_path, models_dir, diagonal)))
    assert [(p.value("radial_clearance_mm"), p.value("axial_clearance_mm")) for p in points] == [(0.05, 0.05), (0.5, 0.5)]


@pytest.mark.parametrize("edit, message", [
    (lambda s: s.update(study_format=2), "study_format"),
    (lambda s: s["designs"][0]["grid"].update(radial_clearance_mm=["wide"]), "designs[0].grid.radial_clearance_mm[0]: 'wide'"),
    (lambda s: s["designs"][0]["grid"].update(diameter=[1.0]), "grid.diameter: no such parameter"),
    (lambda s: s["designs"][0].update(zip={"axial_clearance_mm": [0.1]}), "give one of grid, zip, random"),
    (lambda s: s.pop("ensemble"), "members = 3 needs the study's ensemble"),
    (lambda s: s["outputs"]["reductions"][0].pop("column"), "quantity 'peak_abs' needs 'column'"),
    (lambda s: s["outputs"]["reductions"].append(dict(s["outputs"]["reductions"][0])), "the name 'peak' is used twice"),
    (lambda s: s["parameters"]["radial_clearance_mm"]["set"][0].update(path="/forces/0/journal/radios"),
     "/forces/0/journal/radios: no member 'radios'"),
    (lambda s: s.update(model="no_such_model.json"), "model = 'no_such_model.json': cannot read"),
    (lambda s: s.update(plots=[{"file": "a.png", "designs": ["radial"], "statistics": ["peek"]}]),
     "plots[0].statistics: no reduction called 'peek'"),
    (lambda s: s["outputs"]["reductions"][1].update(after="100%"),
     "outputs.reductions[1] ('p99'): after = '100%': a share of the run must be below 100%"),
    (lambda s: s["outputs"]["reductions"][1].update(after="half"),
     "outputs.reductions[1].after: 'half' is neither a time in seconds nor a share of the run such as \"50%\""),
])
def test_a_bad_study_file_is_an_error_naming_the_field(tmp_path, models_dir, edit, message):
    with pytest.raises(StudyError, match=None) as error:
        study = load_study(edited(tmp_path, models_dir, edit))
        expand_study(study)
    assert message in str(error.value)


def test_a_missing_or_malformed_study_file_is_an_error_naming_the_file(tmp_path):
    with pytest.raises(StudyError, match="cannot read the study file"):
        load_study(str(tmp_path / "absent.json"))
    (tmp_path / "bad.json").write_text("{not json")
    with pytest.raises(StudyError, match="bad.json: not JSON"):
        load_study(str(tmp_path / "bad.json"))


def non_finite(text):
    """Writes a study file whose grid holds a bare NaN, Infinity or -Infinity (Python's json
    reads them; JSON has none)."""
    def edit(tmp_path, models_dir):
        path = write_study(tmp_path, models_dir)
        with open(path) as f:
            content = f.read()
        with open(path, "w") as f:
            f.write(content.replace("0.3", text, 1))
        return path
    return edit


def a_billion_draws(spec):
    design = spec["designs"][0]
    del design["grid"]
    design["random"] = {"draws": 10 ** 9, "seed": 1, "distributions": {"radial_clearance_mm": {"uniform": [0.05, 0.5]}}}


def edited_by(edit):
    return lambda tmp_path, models_dir: edited(tmp_path, models_dir, edit)


@pytest.mark.parametrize("make, message", [
    (non_finite("NaN"), "designs[0].grid.radial_clearance_mm[2]: NaN is not a JSON number"),
    (non_finite("Infinity"), "designs[0].grid.radial_clearance_mm[2]: Infinity is not a JSON number"),
    (edited_by(lambda s: s["designs"][0].update(members=1e9)), "3 points x 1000000000 members = 3000000000 runs"),
    (edited_by(a_billion_draws), "more than the 100000 a study may hold"),
    (edited_by(lambda s: s["outputs"]["time_series"].update(resolution=1e-300)),
     "outputs.time_series.resolution = 1e-300 s"),
    (edited_by(lambda s: s["outputs"]["reductions"][1].update(after=0.5)),
     "outputs.reductions[1] ('p99'): after = 0.5 s is not before the end of the run"),
])
def test_a_study_that_cannot_run_is_one_line_naming_the_field_and_status_2_before_any_run(tmp_path, models_dir,
                                                                                          capsys, make, message):
    from clearjoint.study.__main__ import main
    path = make(tmp_path, models_dir)
    assert main(["run", path, "--workers", "1", "--no-progress", "--no-plot"]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1 and "Traceback" not in err, err
    assert not os.path.exists(tmp_path / "store_small")


def test_a_share_of_the_run_as_after_follows_an_end_time_that_a_time_in_seconds_would_pass(tmp_path, models_dir):
    # p99's after is 0.005 s: a study shortened to 4 ms cannot run; as "33%" of a 15-ms run it
    # is the same window, and a 4-ms run keeps its last 67 %.
    def shortened(share):
        return lambda s: (s["set"].update({"/solver/end_time": 0.004}),
                          s["outputs"]["reductions"][1].update(after=share) if share else None)
    with pytest.raises(StudyError, match="after = 0.005 s is not before the end of the run"):
        expand_study(load_study(edited(tmp_path, models_dir, shortened(None))))
    _, runs, _ = expand_study(load_study(edited(tmp_path, models_dir, shortened("33%"))))
    assert runs and all(r.model["solver"]["end_time"] == 0.004 for r in runs)


def test_a_model_file_with_nan_is_an_error_naming_the_file_and_field(tmp_path, models_dir):
    model = tmp_path / "model.json"
    with open(os.path.join(str(models_dir), "slider_crank_spatial_clearance.json")) as f:
        model.write_text(f.read().replace('"end_time": 1.0', '"end_time": NaN'))
    with pytest.raises(StudyError, match=r"model.json: solver.end_time: NaN is not a JSON number"):
        load_study(edited(tmp_path, models_dir, lambda s: s.update(model="model.json")))


def test_counts_written_as_whole_floats_are_integers(tmp_path, models_dir):
    study = load_study(edited(tmp_path, models_dir, lambda s: s["designs"][0].update(members=3.0)))
    assert len(expand_study(study)[1]) == 9


def test_the_documented_schema_validation_accepts_the_shipped_studies_and_names_a_bad_field(models_dir, monkeypatch,
                                                                                            capsys):
    """docs/studies.md shows how to validate a file in Python; its block runs as written."""
    root = models_dir.parent
    text = (root / "docs" / "studies.md").read_text()
    block = text.split("<!-- schema validation example")[1].split("```python\n")[1].split("```")[0]
    monkeypatch.chdir(root)
    namespace = {}
    exec(block, namespace)
    assert capsys.readouterr().out == ""
    shipped = sorted((root / "reproduction" / "studies").glob("*.json"))
    assert shipped, "no study files in reproduction/studies"
    for study in shipped:
        assert list(namespace["study"].iter_errors(json.loads(study.read_text()))) == [], study
    answer = namespace["validator"]("urn:clearjoint:schema:v1:detect-answer")  # refers to error-line by urn
    assert list(answer.iter_errors({"v": 1, "id": None, "error": "line 1: not JSON"})) == []
    assert list(answer.iter_errors({"v": 1, "id": None, "error": 3})) != []
    assert [e.message for e in namespace["study"].iter_errors({"study_format": 2})] != []


# -- files that must not be read whole -------------------------------------------------------------

def unreadable_file(tmp_path, models_dir, kind):
    """A path that is not a study or model file to read: (path, what the error must say)."""
    from clearjoint._bounded_files import MAX_DESCRIPTION_BYTES
    if kind == "device":
        return "/dev/zero", "'/dev/zero' is not a regular file"
    path = tmp_path / ("named." + kind)
    if kind == "fifo":
        os.mkfifo(path)  # nobody writes into it: an open for reading would wait forever
        return str(path), "%r is not a regular file" % str(path)
    if kind == "link":
        os.symlink(write_study(tmp_path, models_dir), path)
        return str(path), "%r is a symbolic link" % str(path)
    with open(path, "wb") as f:  # sparse: a hole of the limit and one byte
        f.truncate(MAX_DESCRIPTION_BYTES + 1)
    return str(path), "%r holds %d bytes, more than the %d bytes accepted" % (
        str(path), MAX_DESCRIPTION_BYTES + 1, MAX_DESCRIPTION_BYTES)


def study_program(cli, *args):
    """`clearjoint study ...` as a user types it, with a timeout that fails a hang."""
    import subprocess
    return subprocess.run([str(cli), "study", *args], capture_output=True, text=True, timeout=60)


@pytest.mark.parametrize("kind", ["device", "fifo", "link", "oversized"])
def test_a_study_file_that_is_a_device_a_fifo_a_link_or_too_large_is_refused_naming_it_and_the_limit(
        tmp_path, models_dir, cli, kind):
    path, message = unreadable_file(tmp_path, models_dir, kind)
    for command in ("summary", "run", "plot"):
        done = study_program(cli, command, path)
        assert done.returncode == 2, (command, done.stderr)
        assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, done.stderr
        assert "the study file " + message in done.stderr, done.stderr


@pytest.mark.parametrize("kind", ["device", "fifo", "link", "oversized"])
def test_a_model_file_that_is_a_device_a_fifo_a_link_or_too_large_is_refused_naming_the_field(
        tmp_path, models_dir, cli, kind):
    model, message = unreadable_file(tmp_path, models_dir, kind)
    path = edited(tmp_path, models_dir, lambda s: s.update(model=model))
    done = study_program(cli, "summary", path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, done.stderr
    assert "model = %r: the model file " % model + message in done.stderr, done.stderr


def test_model_paths_are_relative_to_the_study_file_not_the_current_folder(tmp_path, models_dir, monkeypatch):
    import shutil
    (tmp_path / "studies").mkdir()
    (tmp_path / "models").mkdir()
    shutil.copy(models_dir / "slider_crank_spatial_clearance.json", tmp_path / "models" / "crank.json")
    path = edited(tmp_path / "studies", models_dir, lambda s: s.update(model="../models/crank.json"))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    study = load_study(os.path.relpath(path, elsewhere))
    with open(models_dir / "slider_crank_spatial_clearance.json") as f:
        assert study.base_models[""] == json.load(f)
    assert study.store_path == str(tmp_path / "studies" / "store_small")


# The formulation as a parameter (docs/studies.md, "Sweeping a setting that is not a number").
FORMULATION = {"set": [{"path": "/solver/method", "choices": ["dormand_prince", "moreau_jean"]}]}


def formulation_study(spec):
    spec["set"]["/solver/method"] = "dormand_prince"
    spec["parameters"]["formulation"] = json.loads(json.dumps(FORMULATION))
    spec["designs"] = [{"name": "formulations", "grid": {"formulation": [0, 1]},
                        "fixed": {"radial_clearance_mm": 0.1, "axial_clearance_mm": 0.1}, "x": "formulation"}]
    spec.pop("ensemble")


def test_a_parameter_with_choices_sweeps_the_formulation_and_both_run(tmp_path, models_dir):
    from clearjoint.study.execute import execute_run
    study = load_study(edited(tmp_path, models_dir, formulation_study))
    points, runs, _ = expand_study(study)
    assert [p.point_id for p in points] == ["axial_clearance_mm=0.1,formulation=0.0,radial_clearance_mm=0.1",
                                            "axial_clearance_mm=0.1,formulation=1.0,radial_clearance_mm=0.1"]
    assert [r.model["solver"]["method"] for r in runs] == ["dormand_prince", "moreau_jean"]
    assert runs[0].run_id != runs[1].run_id
    results = [execute_run({"run_id": r.run_id, "model": r.model, "outputs": study.spec["outputs"]}) for r in runs]
    for result in results:
        assert all(np.isfinite(v) for v in result["reductions"].values())
    # Two formulations, two motions: the slider's peak acceleration is not the same number.
    assert results[0]["reductions"]["peak"] != results[1]["reductions"]["peak"]


@pytest.mark.parametrize("edit, message", [
    (lambda s: s["designs"][0]["grid"].update(formulation=[0, 2]),
     "grid.formulation = 2: must be a whole number from 0 to 1, the index of one of its choices "
     "(\"dormand_prince\", \"moreau_jean\")"),
    (lambda s: s["designs"][0]["grid"].update(formulation=[0.5]), "grid.formulation = 0.5: must be a whole number"),
    (lambda s: s["designs"][0].update(grid={"radial_clearance_mm": [0.1]},
                                      fixed={"formulation": -1, "axial_clearance_mm": 0.1}),
     "fixed.formulation = -1: must be a whole number"),
    (lambda s: s["parameters"]["formulation"]["set"][0].update(scale=2.0),
     "parameters.formulation.set[0]: choices cannot be combined with scale or offset"),
    (lambda s: s["designs"][0].update(random={"draws": 2, "seed": 1,
                                              "distributions": {"formulation": {"uniform": [0, 1]}}})
     or s["designs"][0].pop("grid"),
     "random.formulation: a parameter with choices takes listed values"),
])
def test_a_bad_choice_is_an_error_naming_the_field_and_the_choices(tmp_path, models_dir, edit, message):
    def both(spec):
        formulation_study(spec)
        edit(spec)
    with pytest.raises(StudyError) as error:
        expand_study(load_study(edited(tmp_path, models_dir, both)))
    assert message in str(error.value)
