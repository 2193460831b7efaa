# SPDX-License-Identifier: BSD-3-Clause
"""Reductions skip NaN samples (no value there) and fail, naming the column, when nothing is left
or the value is not finite; the summary is strict JSON, with null for a value that is absent."""
import json
import math

import numpy as np
import pytest

from clearjoint.study import Store, expand_study, load_study, summarise
from clearjoint.study.reduce import ReductionError, reduce_one, reduce_run
from study_fixtures import edit_study, fake_result, write_study

NAN = float("nan")


def contact_table():
    """A clearance joint's table: slot a in contact at the middle samples only, slot b never."""
    return {"force_joint": {"time": np.array([0.0, 1.0, 2.0, 3.0]),
                            "radial_a.depth": np.array([NAN, 2e-6, -3e-6, NAN]),
                            "radial_b.depth": np.full(4, NAN)},
            "energy": {"time": np.array([0.0, 1.0, 2.0, 3.0]), "total": np.array([1.0, 0.9, NAN, 0.5])}}


def reduction(column, quantity="peak_abs", **extra):
    return dict(name="r", quantity=quantity, table="force_joint", column=column, **extra)


@pytest.mark.parametrize("quantity, extra, expected", [
    ("peak_abs", {}, 3e-6),
    ("percentile_abs", {"percentile": 0}, 2e-6),
    ("rms", {}, math.sqrt((4e-12 + 9e-12) / 2)),
    ("peak_abs", {"after": 1.5}, 3e-6),
])
def test_nan_samples_are_skipped(quantity, extra, expected):
    assert reduce_one(contact_table(), reduction("radial_a.depth", quantity, **extra)) == pytest.approx(expected)


@pytest.mark.parametrize("spec", [reduction("radial_b.depth"), reduction("radial_a.depth", after=2.5),
                                  reduction("radial_b.depth", "rms")])
def test_a_window_of_nan_only_is_an_error_naming_the_column(spec):
    with pytest.raises(ReductionError, match="column %r of table 'force_joint' is NaN at every sample" % spec["column"]):
        reduce_one(contact_table(), spec)


def speed_table(end_time):
    """A body's table of 11 samples from 0 to end_time, the value growing with the sample."""
    return {"body": {"time": np.linspace(0.0, end_time, 11), "v": np.arange(11.0)}}


@pytest.mark.parametrize("end_time", [1.0, 0.2])
def test_an_after_given_as_a_share_of_the_run_keeps_the_same_samples_whatever_the_end_time(end_time):
    spec = {"name": "r", "quantity": "rms", "table": "body", "column": "v", "after": "50%"}
    # Samples 6..10 are after half the run, at any end time.
    assert reduce_one(speed_table(end_time), spec) == pytest.approx(math.sqrt(np.mean(np.arange(6.0, 11.0) ** 2)))
    in_seconds = dict(spec, after=0.5)
    assert reduce_one(speed_table(1.0), in_seconds) == reduce_one(speed_table(1.0), spec)


def test_an_after_given_as_a_share_counts_from_the_start_time():
    tables = {"body": {"time": np.linspace(1.0, 2.0, 11), "v": np.arange(11.0)}}
    spec = {"name": "r", "quantity": "peak_abs", "table": "body", "column": "v", "after": "85%"}
    assert reduce_one(tables, dict(spec, quantity="rms")) == pytest.approx(math.sqrt((81.0 + 100.0) / 2))
    with pytest.raises(ReductionError, match=r"reduction 'r': no sample after t = 2 s \(100% of the run\)"):
        reduce_one(tables, dict(spec, after="100%"))


def test_a_reduction_that_is_not_finite_is_an_error_naming_it():
    tables = contact_table()
    tables["energy"]["total"][-1] = NAN  # the energy at the last sample is missing
    with pytest.raises(ReductionError, match="reduction 'loss': the value is nan"):
        reduce_run(tables, {"reductions": [{"name": "loss", "quantity": "energy_loss"}]})


def test_the_summary_is_strict_json_with_null_for_a_stored_value_that_is_not_finite(tmp_path, models_dir):
    # Runs stored as an earlier version stored them, with NaN; read back as absent.
    path = edit_study(write_study(tmp_path, models_dir, radial=(0.05, 0.1), members=1),
                      lambda s: s["outputs"].update(reductions=[{"name": "peak", "quantity": "peak_abs",
                                                                 "table": "body_slider", "column": "ax"}]))
    study = load_study(path)
    points, runs, membership = expand_study(study)
    store = Store(study.store_path)
    store.open_for_writing({})
    for run, value in zip(runs, (NAN, 2.0)):
        store.write(run, (), fake_result({"peak": value}), "o", study.name)
    summary = summarise(study, store, points, membership)
    store.close()

    def refuse(constant):
        raise AssertionError("summary.json holds %s" % constant)
    with open(store.summary + "/summary.json") as f:
        parsed = json.load(f, parse_constant=refuse)
    assert [row.get("peak") for row in parsed["runs"]] == [None, 2.0]
    assert summary["points"][points[1].point_id]["peak"]["values"] == [2.0]
    assert "peak" not in summary["points"][points[0].point_id]
    with open(store.summary + "/runs.csv") as f:
        assert "nan" not in f.read().lower()
