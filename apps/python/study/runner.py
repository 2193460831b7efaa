# SPDX-License-Identifier: BSD-3-Clause
"""Running a study on Dask distributed: expand, skip what the store holds, submit the rest, store
each result as it arrives (in this process only: see store.py), then write the summary tables."""
import importlib.util
import logging
import os
import sys
import time
from dataclasses import dataclass, field

from .execute import execute_run, library_build, package_code
from .expand import expand_study, outputs_sha256, sha256_text
from .store import Store, StoreError
from .study_file import StudyError
from .summary import summarise


@dataclass
class RunReport:
    """What one call of run_study did."""
    total: int = 0
    reused: int = 0
    computed: list = field(default_factory=list)      # run ids stored by this call, in order
    failed: dict = field(default_factory=dict)        # run id -> error text
    set_aside: dict = field(default_factory=dict)     # run id -> (why, where its file went)
    seconds: float = 0.0
    workers: int = 0


def _library_version():
    import clearjoint
    return clearjoint.__version__


def store_error(study, error):
    """A store that cannot be used, as the study file's field at fault."""
    return StudyError("%s: store = %r: %s" % (study.path, study.spec["store"], error))


def reuse_key(run, outputs_hash):
    """What decides a stored run's values, as the run file's attributes: a stored run is reused
    only when all of them are equal: the model and the outputs, the library's build identity (its
    version and the SHA-256 of its binaries) and the Python package that ran and reduced it."""
    return {"model_sha256": run.model_sha256, "outputs_sha256": outputs_hash,
            "library_version": _library_version(), "library_build": library_build(),
            "package_sha256": package_code()}


# The memory a local cluster's worker may use before Dask pauses it (80 %) and restarts it
# (95 %), unless the study file or --memory-limit says otherwise: "auto", the machine's memory
# shared out by core, so that one run that grows without bound fails alone instead of bringing
# in the kernel's OOM killer.
DEFAULT_MEMORY_LIMIT = "auto"


def worker_memory_limit(study, option=None):
    """The memory limit of a local cluster's workers in bytes (0: none): --memory-limit, else the
    study's worker_memory_limit, else DEFAULT_MEMORY_LIMIT; in Dask's notation ("auto", "4GiB",
    a share of the machine's memory up to 1, 0 for none)."""
    from distributed.worker_memory import parse_memory_limit

    if option is not None:
        where, value = "--memory-limit", option
    else:
        where, value = "%s: worker_memory_limit" % study.path, study.spec.get("worker_memory_limit",
                                                                               DEFAULT_MEMORY_LIMIT)
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = None
    if number is not None and not 0 <= number < float("inf"):
        raise StudyError("%s = %r: must be 0 (no limit), a share of the memory up to 1, or a size" % (where, value))
    try:
        limit = parse_memory_limit(number if number is not None else value, 1, logger=logging.getLogger(__name__))
    except (ValueError, TypeError) as error:
        raise StudyError("%s = %r: not a memory size (%s); give \"auto\", a size like \"4GiB\", a share of the "
                         "machine's memory up to 1, or 0 for no limit" % (where, value, error))
    return limit or 0


def connect(scheduler=None, workers=None, dashboard_address=":8787", memory_limit=0):
    """A Dask client: to the scheduler at `scheduler` (tcp://host:8786), or to a new LocalCluster
    of `workers` single-threaded worker processes (default: one per core), each limited to
    memory_limit bytes (0: no limit; worker_memory_limit gives the study's). Returns (client,
    cluster or None)."""
    from distributed import Client, LocalCluster

    if scheduler:
        try:
            return Client(scheduler, timeout="30s"), None
        except OSError as error:
            raise StudyError("--scheduler %s: cannot connect (%s)" % (scheduler, error))
    count = workers or os.cpu_count() or 1
    # One thread per worker: each run is one core's work, and processes keep a crashing run from
    # taking the others with it. The memory limit counts the worker's own memory, not the
    # machine's, so other work on a shared machine does not get workers restarted.
    cluster = LocalCluster(n_workers=count, threads_per_worker=1, processes=True, memory_limit=memory_limit,
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
              client=None, memory_limit=None):
    """Runs every run of the study that the store does not hold (all of them with force) on the
    given client, or on a client of `scheduler`, or on a new local cluster of `workers` (memory
    limit: worker_memory_limit(study, memory_limit)); returns a RunReport. Runs that fail (a bad
    model, a solver error, a task Dask gave up) are reported in it, the others are stored
    regardless. A stored run counts when its file matches its checksum and was written under this
    process's reuse_key (workers should run the same build and package); a file that does not
    match is set aside and run again. Raises StudyError when the store cannot be used or another
    client holds it."""
    start = time.monotonic()
    points, runs, membership = expand_study(study)
    limit = worker_memory_limit(study, memory_limit) if client is None and not scheduler else 0
    store = Store(study.store_path)
    outputs_hash = outputs_sha256(study)
    study_sha256 = sha256_text(study.text)
    try:
        store.open_for_writing({"name": study.name, "study_file": os.path.abspath(study.path),
                                "study_sha256": study_sha256, "outputs_sha256": outputs_hash,
                                "points": len(points), "runs": len(runs), "study": study.spec})
    except StoreError as error:
        raise store_error(study, error)
    try:
        report = RunReport(total=len(runs))
        _set_aside_corrupt_runs(store, runs, report, stream)
        todo = [r for r in runs if force or not store.is_current(r.run_id, reuse_key(r, outputs_hash))]
        report.reused = len(runs) - len(todo)
        print("study %s: %d points, %d runs; %d stored, %d to run; store %s" % (
            study.name, len(points), len(runs), report.reused, len(todo), store.path), file=stream)
        if todo:
            values = {p.point_id: p.values for p in points}
            own = client is None
            cluster = None
            if own:
                client, cluster = connect(scheduler, workers, memory_limit=limit)
            try:
                _submit_and_store(client, study, store, todo, values, outputs_hash, report, progress, stream)
            finally:
                if own:
                    client.close()
                    if cluster is not None:
                        cluster.close()
        summarise(study, store, points, membership)
    except StoreError as error:  # the file system refused a run file or a summary
        raise store_error(study, error)
    finally:
        store.close()
    report.seconds = time.monotonic() - start
    return report


def _set_aside_corrupt_runs(store, runs, report, stream):
    """Moves every stored run file of the study whose bytes do not match its checksum to the
    quarantine, naming it: it is run again. A file without a checksum (an older store's) is
    left in place and run again too, since it cannot be trusted either."""
    stored = store.stored_ids()
    for run in runs:
        if run.run_id not in stored:
            continue
        why = store.verify(run.run_id) if store.has_checksum(run.run_id) else None
        if why is None:
            continue
        where = store.set_aside(run.run_id)
        report.set_aside[run.run_id] = (why, where)
        print("run %s: %s; set aside as %s, running it again" % (run.run_id, why, where), file=stream)


def _submit_and_store(client, study, store, todo, values, outputs_hash, report, progress, stream):
    """Submits one task per run and stores each result when it arrives, in arrival order."""
    from distributed import as_completed
    from tqdm import tqdm

    report.workers = len(client.scheduler_info().get("workers", {}))
    print("%s, %d workers; %s" % (client.scheduler.address, report.workers, dashboard_text(client)), file=stream)
    # One map call: the tasks go to the scheduler as one graph, not one message each.
    payloads = [{"run_id": run.run_id, "model": run.model, "outputs": study.spec["outputs"], "engine": run.engine}
                for run in todo]
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
