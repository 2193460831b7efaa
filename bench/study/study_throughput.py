#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Throughput of the study runner: a 64-run study (the spatial slider-crank of Sec. 6.2 over
END_TIME s, 4 radial x 4 axial clearances x 4 ensemble members) on a LocalCluster of 1 and of 2
workers, against the same 64 runs called directly (clearjoint.simulate and the reductions in one
loop, no Dask, no store), and the scheduler's cost per task (no-op tasks).

    PYTHONPATH=build/bindings/python /usr/bin/python3 bench/study/study_throughput.py \\
        --repetitions 3 --json results/study_throughput.json

The three ways run interleaved, once each per repetition, so that a change in the machine's load
affects all of them alike; clusters are started before the timing (their start is reported on
its own). Each way is timed in wall-clock time and in CPU time: this process's (the client and,
in a LocalCluster, the scheduler and the nannies) plus that of the worker processes of the
cluster in use (psutil; the other cluster's idle workers are left out). On a machine shared with other work, wall-clock times scatter with the load; CPU times
measure the work itself. Overhead per run = (study time with 1 worker - direct time) / 64,
relative to the direct time per run, in either measure.

The scaling estimate for N workers is a model, not a measurement: each worker, on a core of its
own, does a run in c_run + c_task (the direct CPU time per run plus the CPU overhead per run),
the scheduler hands out at most one task per t_sched (the no-op measurement) and the client
stores one run per t_store, so runs/min = 60 min(N / (c_run + c_task), 1 / t_sched, 1 / t_store).
"""
import argparse
import json
import os
import statistics
import sys
import tempfile
import time

import psutil  # a dependency of distributed

END_TIME = 0.05        # simulated seconds per run (default): about 0.06 s of CPU per run
CLEARANCES_MM = (0.05, 0.1, 0.3, 0.5)
MEMBERS = 4
NOOP_TASKS = 2000


def write_study(directory, model, end_time=END_TIME):
    spec = {
        "study_format": 1, "name": "throughput",
        "model": model,
        "set": {"/solver/end_time": end_time},
        "parameters": {
            "radial_clearance_mm": {"set": [{"path": "/forces/0/journal/radius", "offset": 0.01, "scale": -0.001}]},
            "axial_clearance_mm": {"set": [{"path": "/forces/0/journal/length", "offset": 0.02, "scale": -0.002}]}},
        "designs": [{"name": "grid", "grid": {"radial_clearance_mm": list(CLEARANCES_MM),
                                              "axial_clearance_mm": list(CLEARANCES_MM)}, "members": MEMBERS}],
        "ensemble": {"relative_step": 1e-9,
                     "scale": ["/initial_conditions/hold_velocities/*/value", "/bodies/0/angular_velocity"]},
        "outputs": {"reductions": [
            {"name": "peak", "quantity": "peak_abs", "table": "body_slider", "column": "ax"},
            {"name": "energy_loss", "quantity": "energy_loss"}],
            "time_series": {"resolution": 1e-3, "tables": {"body_slider": ["x", "ax"]}}},
        "store": "store",
    }
    path = os.path.join(directory, "throughput.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    return path


def cpu_seconds(client=None):
    """CPU time (user + system) of this process and of the worker processes of `client`."""
    processes = [psutil.Process()]
    if client is not None:
        processes += [psutil.Process(pid) for pid in client.run(os.getpid).values()]
    return sum(sum(p.cpu_times()[:2]) for p in processes)


def direct(study, runs):
    from clearjoint.study.execute import execute_run
    start, cpu = time.perf_counter(), cpu_seconds()
    for run in runs:
        execute_run({"run_id": run.run_id, "model": run.model, "outputs": study.spec["outputs"]})
    return time.perf_counter() - start, cpu_seconds() - cpu


def through_study(study, client):
    from clearjoint.study import run_study
    import shutil
    shutil.rmtree(study.store_path, ignore_errors=True)
    cpu = cpu_seconds(client)
    start = time.perf_counter()
    with open(os.devnull, "w") as quiet:
        report = run_study(study, client=client, progress=False, stream=quiet)
    elapsed = time.perf_counter() - start
    used = cpu_seconds(client) - cpu
    assert not report.failed and len(report.computed) == len(set(report.computed)), report.failed
    return elapsed, used


def noop(x):
    return x


def scheduler_cost(client):
    """Seconds per task for no-op tasks on this cluster: the scheduler's and the transport's
    share of a run, without the run."""
    start = time.perf_counter()
    futures = client.map(noop, range(NOOP_TASKS), pure=False)
    client.gather(futures)
    return (time.perf_counter() - start) / NOOP_TASKS


def store_cost(study, runs):
    """Seconds per stored run on the client (write, fsync, rename) for this study's outputs."""
    from clearjoint.study import Store
    from clearjoint.study.execute import execute_run
    result = execute_run({"run_id": runs[0].run_id, "model": runs[0].model, "outputs": study.spec["outputs"]})
    with tempfile.TemporaryDirectory() as directory:
        store = Store(directory)
        store.open_for_writing({})
        start = time.perf_counter()
        for run in runs:
            store.write(run, (), result, "o", "throughput")
        return (time.perf_counter() - start) / len(runs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--model", default=os.path.join(os.path.dirname(__file__), "..", "..", "reproduction", "models",
                                                         "slider_crank_spatial_clearance_study.json"),
                        help="the model the study varies (default: the base model of the Sec. 6.2 studies)")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--end-time", type=float, default=END_TIME, help="simulated seconds per run")
    parser.add_argument("--json", help="write the measurements here")
    args = parser.parse_args()
    from clearjoint.study import expand_study, load_study
    from clearjoint.study.runner import connect

    with tempfile.TemporaryDirectory() as directory:
        study = load_study(write_study(directory, os.path.abspath(args.model), args.end_time))
        runs = expand_study(study)[1]
        assert len(runs) == 64
        clients, starts = {}, {}
        for workers in (1, 2):
            begin = time.perf_counter()
            clients[workers] = connect(workers=workers, dashboard_address=None)
            clients[workers][0].wait_for_workers(workers)
            starts[workers] = time.perf_counter() - begin
        times = {"direct": [], "1 worker": [], "2 workers": []}
        cpu = {"direct": [], "1 worker": [], "2 workers": []}
        try:
            direct(study, runs[:2])  # warm-up: first import and page-in
            for repetition in range(args.repetitions):
                for way, measure in (("direct", lambda: direct(study, runs)),
                                     ("1 worker", lambda: through_study(study, clients[1][0])),
                                     ("2 workers", lambda: through_study(study, clients[2][0]))):
                    wall, used = measure()
                    times[way].append(wall)
                    cpu[way].append(used)
                print("repetition %d: %s" % (repetition + 1, ", ".join(
                    "%s %.2f s (CPU %.2f s)" % (k, v[-1], cpu[k][-1]) for k, v in times.items())), file=sys.stderr)
            t_sched = scheduler_cost(clients[1][0])
        finally:
            for client, cluster in clients.values():
                client.close()
                cluster.close()
        t_store = store_cost(study, runs)

    n = len(runs)
    median = {k: statistics.median(v) for k, v in times.items()}
    median_cpu = {k: statistics.median(v) for k, v in cpu.items()}
    t_run = median["direct"] / n
    t_task = (median["1 worker"] - median["direct"]) / n
    cpu_run = median_cpu["direct"] / n
    cpu_task = (median_cpu["1 worker"] - median_cpu["direct"]) / n
    result = {
        "runs": n, "end_time_s": args.end_time, "repetitions": args.repetitions, "times_s": times,
        "cpu_s": cpu, "median_cpu_s": median_cpu, "direct_cpu_seconds_per_run": cpu_run,
        "overhead_cpu_seconds_per_run": cpu_task, "overhead_cpu_relative": cpu_task / cpu_run,
        "cluster_start_s": starts, "median_s": median,
        "runs_per_minute": {k: 60 * n / v for k, v in median.items()},
        "direct_seconds_per_run": t_run, "overhead_seconds_per_run": t_task,
        "overhead_relative": t_task / t_run, "scheduler_seconds_per_noop_task": t_sched,
        "store_seconds_per_run": t_store,
        "speedup_2_workers": median["1 worker"] / median["2 workers"],
    }
    # The estimate takes the CPU measure of a run and its overhead: a worker's own core does both.
    per_worker = cpu_run + max(cpu_task, 0.0)
    estimate = {}
    for workers in (1, 2, 4, 8, 16, 32, 64, 128, 256, 512):
        estimate[workers] = 60 * min(workers / per_worker, 1 / t_sched, 1 / t_store)
    result["estimated_runs_per_minute"] = estimate
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
    print("| way | runs/min (median of %d) | wall for 64 runs [s] (each repetition) | CPU for 64 runs [s] (each) |"
          % args.repetitions)
    print("| --- | ---: | ---: | ---: |")
    for k in times:
        print("| %s | %.0f | %.2f (%s) | %.2f (%s) |" % (
            k, result["runs_per_minute"][k], median[k], ", ".join("%.2f" % t for t in times[k]),
            median_cpu[k], ", ".join("%.2f" % t for t in cpu[k])))
    print("\nper run: direct %.3f s wall, %.3f s CPU; overhead through the study runner %.4f s wall (%.1f %%), "
          "%.4f s CPU (%.1f %%); no-op task %.2f ms; store write %.2f ms; cluster start %.1f s (1 worker), "
          "%.1f s (2 workers); 2 workers / 1 worker: %.2fx" % (
              t_run, cpu_run, t_task, 100 * t_task / t_run, cpu_task, 100 * cpu_task / cpu_run, 1e3 * t_sched,
              1e3 * t_store, starts[1], starts[2], result["speedup_2_workers"]))
    print("\n| workers | estimated runs/min | limited by |")
    print("| ---: | ---: | --- |")
    for workers, rate in estimate.items():
        limits = {"workers": 60 * workers / per_worker, "scheduler": 60 / t_sched, "client store": 60 / t_store}
        print("| %d | %.0f | %s |" % (workers, rate, min(limits, key=limits.get)))


if __name__ == "__main__":
    main()
