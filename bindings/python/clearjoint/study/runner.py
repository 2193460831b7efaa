# SPDX-License-Identifier: BSD-3-Clause
"""Running a study on Dask distributed: expand, skip what the store holds, submit the rest, store
each result as it arrives (in this process only: see store.py), then write the summary tables."""
import importlib.util
import logging
import os
import sys
import time
from dataclasses import dataclass, field

from .execute import execute_run, library_build
from .expand import expand_study, outputs_sha256, sha256_text
from .store import Store, StoreBusy
from .study_file import StudyError
from .summary import summarise


@dataclass
class RunReport:
    """What one call of run_study did."""
    total: int = 0
    reused: int = 0
    computed: list = field(default_factory=list)      # run ids stored by this call, in order
    failed: dict = field(default_factory=dict)        # run id -> error text
    seconds: float = 0.0
    workers: int = 0


def _library_version():
    import clearjoint
    return clearjoint.__version__


def connect(scheduler=None, workers=None, dashboard_address=":8787"):
    """A Dask client: to the scheduler at `scheduler` (tcp://host:8786), or to a new LocalCluster
    of `workers` single-threaded worker processes (default: one per core). Returns (client,
    cluster or None)."""
    from distributed import Client, LocalCluster

    if scheduler:
        try:
            return Client(scheduler, timeout="30s"), None
        except OSError as error:
            raise StudyError("--scheduler %s: cannot connect (%s)" % (scheduler, error))
    count = workers or os.cpu_count() or 1
    # One thread per worker: each run is one core's work, and processes keep a crashing run from
    # taking the others with it. No memory limit: the runs are small, and a shared machine's
    # memory pressure must not get workers restarted.
    cluster = LocalCluster(n_workers=count, threads_per_worker=1, processes=True, memory_limit=0,
                           dashboard_address=dashboard_address, silence_logs=logging.ERROR)
    return Client(cluster), cluster


def dashboard_text(client):
    """Where to watch the study. The scheduler's web server always has its status pages
    (/info/main/workers.html: workers, tasks, logs); the graphical dashboard (/status) needs Bokeh,
    which Debian 12 does not package."""
    if "dashboard" not in client.scheduler_info().get("services", {}):
        return "no dashboard (the scheduler runs no web server)"
    link = client.dashboard_link
    if importlib.util.find_spec("bokeh"):
        return "dashboard: %s" % link
    return "scheduler status: %s (the graphical dashboard needs Bokeh)" % link.replace(
        "/status", "/info/main/workers.html")


def run_study(study, scheduler=None, workers=None, progress=True, force=False, stream=sys.stderr,
              client=None):
    """Runs every run of the study that the store does not hold (all of them with force) on the
    given client, or on a client of `scheduler`, or on a new local cluster of `workers`; returns a
    RunReport. Runs that fail (a bad model, a solver error, a task Dask gave up) are reported in
    it, the others are stored regardless. A stored run counts when it was written for the same
    model, outputs and library build as this process's (workers should run the same build).
    Raises StudyError when another client holds the store."""
    start = time.monotonic()
    points, runs, membership = expand_study(study)
    store = Store(study.store_path)
    outputs_hash = outputs_sha256(study)
    with open(study.path) as f:
        study_sha256 = sha256_text(f.read())
    try:
        store.open_for_writing({"name": study.name, "study_file": os.path.abspath(study.path),
                                "study_sha256": study_sha256, "outputs_sha256": outputs_hash,
                                "points": len(points), "runs": len(runs), "study": study.spec})
    except StoreBusy as error:
        raise StudyError(str(error))
    try:
        version, build = _library_version(), library_build()
        todo = [r for r in runs
                if force or not store.is_current(r.run_id, r.model_sha256, outputs_hash, version, build)]
        report = RunReport(total=len(runs), reused=len(runs) - len(todo))
        print("study %s: %d points, %d runs; %d stored, %d to run; store %s" % (
            study.name, len(points), len(runs), report.reused, len(todo), store.path), file=stream)
        if todo:
            values = {p.point_id: p.values for p in points}
            own = client is None
            cluster = None
            if own:
                client, cluster = connect(scheduler, workers)
            try:
                _submit_and_store(client, study, store, todo, values, outputs_hash, report, progress, stream)
            finally:
                if own:
                    client.close()
                    if cluster is not None:
                        cluster.close()
        summarise(study, store, points, membership)
    finally:
        store.close()
    report.seconds = time.monotonic() - start
    return report


def _submit_and_store(client, study, store, todo, values, outputs_hash, report, progress, stream):
    """Submits one task per run and stores each result when it arrives, in arrival order."""
    from distributed import as_completed
    from tqdm import tqdm

    report.workers = len(client.scheduler_info().get("workers", {}))
    print("%s, %d workers; %s" % (client.scheduler.address, report.workers, dashboard_text(client)), file=stream)
    # One map call: the tasks go to the scheduler as one graph, not one message each.
    payloads = [{"run_id": run.run_id, "model": run.model, "outputs": study.spec["outputs"]} for run in todo]
    futures = client.map(execute_run, payloads, key=["clearjoint-run-%s" % run.run_id for run in todo])
    by_key = {future.key: run for future, run in zip(futures, todo)}
    bar = tqdm(total=len(todo), unit="run", file=stream, disable=not progress, dynamic_ncols=True)
    try:
        for future in as_completed(futures):
            run = by_key[future.key]
            try:
                result = future.result()
            except Exception as error:  # the run's own error, or Dask's (KilledWorker, cancelled)
                report.failed[run.run_id] = "%s: %s" % (type(error).__name__, error)
            else:
                store.write(run, values[run.point_id], result, outputs_hash, study.name)
                report.computed.append(run.run_id)
            future.release()
            bar.update(1)
    except KeyboardInterrupt:
        client.cancel(futures)
        raise StudyError("study %s: interrupted after storing %d of %d runs; run again to resume" % (
            study.name, len(report.computed), len(todo)))
    finally:
        bar.close()
