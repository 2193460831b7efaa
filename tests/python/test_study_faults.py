# SPDX-License-Identifier: BSD-3-Clause
"""Faults: a worker killed mid-study, a client killed mid-study, a run file killed mid-write.

The first two start a real `dask scheduler` and two `dask worker` processes on 127.0.0.1 and the
study runner as its own process, as a user would."""
import json
import os
import signal
import subprocess
import sys
import time

import h5py
import pytest

from clearjoint.study import Store, expand_study, load_study
from study_fixtures import (assert_store_matches, kill_process_tree, popen, run_without_faults, study_command,
                            wait_for, write_study)

# Seconds to wait for a cluster process or a study step on a loaded 2-core machine.
STARTUP_TIMEOUT = 120
STUDY_TIMEOUT = 600
# Simulated time of a fault-test run [s]: long enough (about 0.1-0.5 s of work per run) that the
# study is still going when the test kills a process after the first runs are stored, even on an
# idle machine; each test checks that it was.
FAULT_END_TIME = 0.06


@pytest.fixture
def cluster(tmp_path):
    """A scheduler and two single-threaded workers without nannies (so that killing a worker's
    process kills the worker, with nobody to restart it). Yields (address, {name: process})."""
    scheduler_file = tmp_path / "scheduler.json"
    environment = dict(os.environ)
    dask = [sys.executable, "-m", "distributed.cli.dask_scheduler"]
    processes = {"scheduler": popen(dask + ["--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                            "--scheduler-file", str(scheduler_file)], env=environment)}
    try:
        wait_for(scheduler_file.exists, STARTUP_TIMEOUT, "the scheduler's file", processes["scheduler"])
        time.sleep(0.2)  # the file is written whole, but give the writer a moment to close it
        address = json.loads(scheduler_file.read_text())["address"]
        for name in ("worker-a", "worker-b"):
            processes[name] = popen([sys.executable, "-m", "distributed.cli.dask_worker", address, "--name", name,
                                     "--nthreads", "1", "--no-nanny", "--no-dashboard", "--memory-limit", "0"],
                                    env=environment)
        from distributed import Client
        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=STARTUP_TIMEOUT)
        yield address, processes
    finally:
        for process in reversed(list(processes.values())):
            kill_process_tree(process)


def test_a_worker_killed_mid_study_leaves_every_run_stored_once_and_unchanged(tmp_path, models_dir, cluster):
    address, processes = cluster
    path = write_study(tmp_path, models_dir, radial=(0.05, 0.1, 0.3, 0.5), members=4, name="worker_fault",
                       end_time=FAULT_END_TIME)
    study = load_study(path)
    store = Store(study.store_path)
    runner = popen(study_command("run", path, "--scheduler", address, "--no-progress", "--no-plot"))
    try:
        wait_for(lambda: len(store.write_log()) >= 2, STUDY_TIMEOUT, "two runs stored", runner)
        processes["worker-b"].send_signal(signal.SIGKILL)
        processes["worker-b"].wait(timeout=30)
        stored_at_kill = len(store.write_log())
        output, _ = runner.communicate(timeout=STUDY_TIMEOUT)
    finally:
        kill_process_tree(runner)
    assert runner.returncode == 0, output
    runs = expand_study(study)[1]
    assert stored_at_kill < len(runs), "the worker was killed after the study ended: nothing tested"
    log = store.write_log()
    assert sorted(log) == sorted(r.run_id for r in runs)  # every run written, none twice
    assert_store_matches(store, run_without_faults(study))


def test_a_client_killed_mid_study_resumes_without_redoing_stored_runs(tmp_path, models_dir, cluster):
    address, _ = cluster
    path = write_study(tmp_path, models_dir, radial=(0.05, 0.1, 0.3, 0.5), members=4, name="client_fault",
                       end_time=FAULT_END_TIME)
    study = load_study(path)
    store = Store(study.store_path)
    first = popen(study_command("run", path, "--scheduler", address, "--no-progress", "--no-plot"))
    try:
        wait_for(lambda: len(store.write_log()) >= 3, STUDY_TIMEOUT, "three runs stored", first)
        first.send_signal(signal.SIGKILL)
        first.wait(timeout=30)
    finally:
        kill_process_tree(first)
    runs = expand_study(study)[1]
    before = {run_id: os.stat(store.run_path(run_id)).st_ino for run_id in store.stored_ids()}
    assert 3 <= len(before) < len(runs), "the client was killed after the study ended: nothing tested"
    for run_id in before:  # whatever the moment of the kill, a published run file is whole
        store.read(run_id)

    second = subprocess.run(study_command("run", path, "--scheduler", address, "--no-progress", "--no-plot"),
                            capture_output=True, text=True, timeout=STUDY_TIMEOUT)
    assert second.returncode == 0, second.stderr
    assert "%d stored, %d to run" % (len(before), len(runs) - len(before)) in second.stderr
    assert os.listdir(os.path.join(store.runs, ".partial")) == []
    for run_id, inode in before.items():  # not rewritten
        assert os.stat(store.run_path(run_id)).st_ino == inode
    log = store.write_log()
    assert len(log) == len(set(log)) and set(log) <= {r.run_id for r in runs}
    assert_store_matches(store, run_without_faults(study))


WRITER = """
import sys, numpy as np
from clearjoint.study.store import Store
from clearjoint.study.expand import Run
store = Store(sys.argv[1])
store.open_for_writing({})
run = Run("torn", "p", 0, {}, "m")
big = np.random.default_rng(1).normal(size=10_000_000)  # 80 MB of doubles: seconds to compress
print("writing", flush=True)
store.write(run, (), {"reductions": {"x": 1.0}, "time_series": {"t": {"time": big}}, "library_version": "v", "library_build": "b",
                      "package_sha256": "r", "host": "h", "pid": 0, "wall_seconds": 0.0, "simulate_seconds": 0.0}, "o", "s")
"""


def test_a_client_killed_while_writing_a_run_leaves_no_run_file_and_the_next_start_clears_the_partial(tmp_path):
    store = Store(str(tmp_path / "store"))
    writer = popen([sys.executable, "-c", WRITER, store.path])
    try:
        assert writer.stdout.readline().strip() == "writing"
        wait_for(lambda: os.path.isdir(store.partial) and os.listdir(store.partial), STARTUP_TIMEOUT,
                 "the partial run file", writer)
        writer.send_signal(signal.SIGKILL)
        writer.wait(timeout=30)
    finally:
        kill_process_tree(writer)
    assert store.stored_ids() == set() and store.write_log() == []
    assert os.listdir(store.partial) != []  # the torn file is there, private, never read
    store.open_for_writing({})
    assert os.listdir(store.partial) == []
