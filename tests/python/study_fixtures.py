# SPDX-License-Identifier: BSD-3-Clause
"""Small studies for the study-runner tests: the spatial slider-crank of Sec. 6.2 over a few
milliseconds (the first impacts happen within 10 ms), so that a run takes a fraction of a second."""
import json
import os
import subprocess
import sys

# Simulated time of a test run [s]: long enough for the journal to reach the wall (a few ms) so
# that the reductions see impacts, short enough for a run to take well under a second.
TEST_END_TIME = 0.015

CLEARANCE_PARAMETERS = {
    "radial_clearance_mm": {"unit": "mm", "set": [
        {"path": "/forces/0/journal/radius", "offset": 0.01, "scale": -0.001}]},
    "axial_clearance_mm": {"unit": "mm", "set": [
        {"path": "/forces/0/journal/length", "offset": 0.02, "scale": -0.002}]},
}

ENSEMBLE = {"relative_step": 1e-9,
            "scale": ["/initial_conditions/hold_velocities/*/value", "/bodies/0/angular_velocity"]}

OUTPUTS = {
    "reductions": [
        {"name": "peak", "label": "peak |a|", "unit": "m/s^2", "quantity": "peak_abs",
         "table": "body_slider", "column": "ax"},
        {"name": "p99", "quantity": "percentile_abs", "percentile": 99, "table": "body_slider",
         "column": "ax", "after": 0.005},
        {"name": "energy_loss", "unit": "J", "quantity": "energy_loss"},
        {"name": "impacts", "quantity": "impacts", "table": "force_ground-crank_clearance"},
        {"name": "max_depth", "unit": "m", "quantity": "max_depth", "table": "force_ground-crank_clearance"},
    ],
    "time_series": {"resolution": 1e-3, "tables": {"body_slider": ["x", "ax"]}},
}


def write_study(directory, models_dir, radial=(0.05, 0.1, 0.3), members=3, name="small", end_time=TEST_END_TIME):
    """A study of len(radial) points x members runs; returns the study file's path."""
    spec = {
        "study_format": 1,
        "name": name,
        "model": os.path.join(str(models_dir), "slider_crank_spatial_clearance.json"),
        "set": {"/solver/end_time": end_time, "/output/force_elements": ["ground-crank clearance"]},
        "parameters": CLEARANCE_PARAMETERS,
        "designs": [{"name": "radial", "label": "c_r varied", "grid": {"radial_clearance_mm": list(radial)},
                     "fixed": {"axial_clearance_mm": 0.1}, "members": members, "x": "radial_clearance_mm"}],
        "ensemble": ENSEMBLE,
        "outputs": OUTPUTS,
        "store": "store_" + name,
    }
    path = os.path.join(str(directory), name + ".json")
    with open(path, "w") as f:
        json.dump(spec, f, indent=1)
    return path


def edit_study(path, edit):
    """Applies edit(spec) to the study file at path; returns the path."""
    with open(path) as f:
        spec = json.load(f)
    edit(spec)
    with open(path, "w") as f:
        json.dump(spec, f, indent=1)
    return path


def fake_result(reductions=None, series=None):
    """What execute_run returns, without a simulation: for tests of the store alone."""
    return {"reductions": reductions or {"x": 1.0}, "time_series": series or {},
            "library_version": "v", "library_build": "b", "package_sha256": "r",
            "host": "h", "pid": 0, "wall_seconds": 0.0, "simulate_seconds": 0.0}


def edit_run_file(store, run_id, edit):
    """Applies edit(h5py file) to a stored run and records the file's new checksum, as if it had
    been written so: the store then takes it for its own."""
    import h5py
    from clearjoint.study.store import file_sha256
    with h5py.File(store.run_path(run_id), "a") as f:
        edit(f)
    with open(store.checksum_path(run_id), "w") as f:
        f.write("%s  %s.h5\n" % (file_sha256(store.run_path(run_id)), run_id))


def study_command(*args):
    """The study runner as a separate process (the way a user starts it)."""
    return [sys.executable, "-m", "clearjoint.study", *args]


def run_without_faults(study):
    """Every run of the study computed in this process, without Dask: {run id: result}."""
    from clearjoint.study import expand_study
    from clearjoint.study.execute import execute_run
    _, runs, _ = expand_study(study)
    return {r.run_id: execute_run({"run_id": r.run_id, "model": r.model, "outputs": study.spec["outputs"],
                                   "engine": r.engine})
            for r in runs}


def assert_store_matches(store, reference):
    """The store holds exactly the reference's runs, each with identical reductions and series."""
    assert store.stored_ids() == set(reference)
    for run_id, expected in reference.items():
        stored = store.read(run_id)
        assert stored["reductions"] == expected["reductions"], run_id
        assert set(stored["time_series"]) == set(expected["time_series"]), run_id
        for table, columns in expected["time_series"].items():
            for column, values in columns.items():
                assert stored["time_series"][table][column].tobytes() == values.tobytes(), (run_id, table, column)


def wait_for(predicate, timeout, what, process=None):
    """Polls predicate() until true; fails naming `what` after timeout seconds (or when the
    watched process ends first)."""
    import time
    deadline = time.monotonic() + timeout
    while not predicate():
        if process is not None and process.poll() is not None:
            raise AssertionError("%s: the process ended (status %s) first" % (what, process.returncode))
        if time.monotonic() > deadline:
            raise AssertionError("%s: not within %g s" % (what, timeout))
        time.sleep(0.02)


def kill_process_tree(process):
    if process.poll() is None:
        process.kill()
    process.wait(timeout=30)


def popen(command, **kwargs):
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kwargs)
