# SPDX-License-Identifier: BSD-3-Clause
"""The engine as a study setting: a study's or a design's `engine` reaches clearjoint.simulate,
is part of the point and of the run's key, and is recorded with the stored run; the two engines
agree on the planar clearance slider-crank to the integrator's tolerance."""
import csv
import io
import json
import os

import numpy as np
import pytest

from clearjoint.study import Store, StudyError, expand_study, load_study, run_study
from clearjoint.study.execute import execute_run
from clearjoint.study.expand import canonical_json, outputs_sha256, sha256_text
from study_fixtures import write_study

# Simulated time of the comparison [s]: the first impacts of the planar slider-crank's joint
# happen within it (docs/reports/reproduction.md, Figs. 7-8), and each engine runs it in well
# under a second.
END_TIME = 0.02
# Both engines integrate the same equations with error control at the model's relative tolerance
# (1e-7, the paper's Table 2); their slider positions may differ by a few local errors: ten
# tolerances of the largest position. Measured: 7.6e-9 m on a 0.457 m position (1.7e-8 relative).
AGREEMENT_IN_TOLERANCES = 10.0


def two_engine_study(directory, models_dir):
    spec = {
        "study_format": 1,
        "name": "engines",
        "model": os.path.join(str(models_dir), "slider_crank_planar_clearance_aligned.json"),
        "set": {"/solver/end_time": END_TIME},
        "designs": [{"name": "ours"}, {"name": "simbody", "engine": "simbody"}],
        "outputs": {"reductions": [{"name": "x_peak", "unit": "m", "quantity": "peak_abs",
                                    "table": "body_slider", "column": "x"}],
                    "time_series": {"resolution": None, "tables": {"body_slider": ["x"]}}},
        "store": "store",
    }
    path = os.path.join(str(directory), "engines.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    return path


def test_a_study_in_two_engines_gives_two_runs_with_different_keys_that_agree_to_the_tolerance(tmp_path,
                                                                                              models_dir):
    import clearjoint._core
    if "simbody" not in clearjoint._core.engines():
        pytest.skip("this build has no Simbody adapter")
    study = load_study(two_engine_study(tmp_path, models_dir))
    points, runs, membership = expand_study(study)
    assert [p.point_id for p in points] == ["base", "engine=simbody"]
    assert [r.engine for r in runs] == ["clearjoint", "simbody"]
    assert runs[0].run_id != runs[1].run_id and runs[0].model == runs[1].model
    results = {r.engine: execute_run({"run_id": r.run_id, "model": r.model, "outputs": study.spec["outputs"],
                                      "engine": r.engine}) for r in runs}
    ours, simbody = (results[e]["time_series"]["body_slider"]["x"] for e in ("clearjoint", "simbody"))
    assert ours.shape == simbody.shape
    difference = np.max(np.abs(ours - simbody))
    tolerance = study.base_models[""]["solver"]["relative_tolerance"]
    assert 0 < difference <= AGREEMENT_IN_TOLERANCES * tolerance * np.max(np.abs(ours)), difference
    assert results["clearjoint"]["reductions"]["x_peak"] == pytest.approx(
        results["simbody"]["reductions"]["x_peak"], rel=AGREEMENT_IN_TOLERANCES * tolerance)


def test_the_default_engine_keeps_the_run_keys_of_studies_that_name_none(tmp_path, models_dir):
    os.makedirs(tmp_path / "a")
    os.makedirs(tmp_path / "b")
    plain = load_study(write_study(tmp_path / "a", models_dir, radial=(0.1,), members=1))
    path = write_study(tmp_path / "b", models_dir, radial=(0.1,), members=1)
    with open(path) as f:
        spec = json.load(f)
    spec["engine"] = "clearjoint"
    with open(path, "w") as f:
        json.dump(spec, f)
    named = load_study(path)
    (_, [run], _), (_, [same], _) = expand_study(plain), expand_study(named)
    key = sha256_text(sha256_text(canonical_json(run.model)) + outputs_sha256(plain))[:20]
    assert run.run_id == same.run_id == key and run.point_id == same.point_id


def test_the_runner_runs_each_design_in_its_engine_and_the_store_and_summary_name_it(tmp_path, models_dir):
    import clearjoint._core
    if "simbody" not in clearjoint._core.engines():
        pytest.skip("this build has no Simbody adapter")
    study = load_study(two_engine_study(tmp_path, models_dir))
    report = run_study(study, workers=1, progress=False, stream=io.StringIO())
    assert not report.failed and len(report.computed) == 2
    _, runs, _ = expand_study(study)
    store = Store(study.store_path)
    stored = {r.engine: store.read(r.run_id) for r in runs}
    assert {e: s["attrs"]["engine"] for e, s in stored.items()} == {"clearjoint": "clearjoint", "simbody": "simbody"}
    # Not the same run twice: the Simbody run's positions differ from ours in the last digits.
    assert not np.array_equal(stored["clearjoint"]["time_series"]["body_slider"]["x"],
                              stored["simbody"]["time_series"]["body_slider"]["x"])
    with open(os.path.join(study.store_path, "summary", "runs.csv")) as f:
        assert [(row["point_id"], row["engine"]) for row in csv.DictReader(f)] == [
            ("base", "clearjoint"), ("engine=simbody", "simbody")]


@pytest.mark.parametrize("where", ["study", "design"])
def test_an_unknown_engine_is_an_error_naming_the_field_and_the_value(tmp_path, models_dir, where):
    path = two_engine_study(tmp_path, models_dir)
    with open(path) as f:
        spec = json.load(f)
    (spec if where == "study" else spec["designs"][1])["engine"] = "mujoco"
    with open(path, "w") as f:
        json.dump(spec, f)
    with pytest.raises(StudyError) as error:
        load_study(path)
    field = "engine" if where == "study" else "designs[1].engine"
    assert "%s: 'mujoco' is not one of ['clearjoint', 'simbody']" % field in str(error.value)
