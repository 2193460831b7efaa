# SPDX-License-Identifier: BSD-3-Clause
"""The study store: one HDF5 file per run, published by rename.

    STORE/study.json          the study file as last run, and its expansion's hashes
    STORE/runs/<run id>.h5    one run: reduced outputs, kept time series, parameters, model
    STORE/runs/.partial/      files being written (removed when a study starts)
    STORE/writes.log          one JSON line per run written, appended after the rename
    STORE/.lock               held (flock) by the client that runs the study
    STORE/summary/            runs.csv, points.csv, trends.csv, summary.json (rewritten whole)

Why this shape. HDF5 (h5py) has no concurrent writers and no journal: a process killed while it
writes into an HDF5 file can leave the whole file unreadable, not just the last group. Zarr
(python3-zarr 2.13 in Debian 12) writes chunk by chunk, atomically per chunk file, but a run of
several arrays would still be visible half-written. So only the client writes, one run at a time
as results arrive, into a private file under runs/.partial/; the file is closed, fsync'ed and then
renamed to runs/<run id>.h5, and the directory fsync'ed. rename(2) is atomic: a run is either
absent or complete, whatever kills the client and when. The directory listing is the index; the
summary tables are derived from it and rewritten whole (write then rename) at the end of a study.
A run is reused when its file exists and was written for the same model, the same outputs and
the same library (version and binaries, execute.library_build); otherwise it is run again and
the file replaced. One client runs a
study at a time: it holds an flock on STORE/.lock, which the kernel releases however it ends.
"""
import fcntl
import json
import os
import time

import h5py
import numpy as np

FORMAT = 1  # bump when the layout of a run file changes


class StoreBusy(RuntimeError):
    """Another process holds the store's lock."""


def _fsync_directory(path):
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _write_json_atomically(path, value):
    partial = path + ".partial-%d" % os.getpid()
    with open(partial, "w") as f:
        json.dump(value, f, indent=1, sort_keys=True)
        f.write("\n")
        f.flush()
        os.fsync(f.fileno())
    os.replace(partial, path)


class Store:
    def __init__(self, path):
        self.path = path
        self.runs = os.path.join(path, "runs")
        self.partial = os.path.join(self.runs, ".partial")
        self.summary = os.path.join(path, "summary")
        self.log = os.path.join(path, "writes.log")
        self._lock = None

    def run_path(self, run_id):
        return os.path.join(self.runs, run_id + ".h5")

    def open_for_writing(self, study_record):
        """Takes the store's lock, creates the directories, removes what a killed client left
        half-written, and records the study. Raises StoreBusy when another client holds it."""
        for directory in (self.path, self.runs, self.partial, self.summary):
            os.makedirs(directory, exist_ok=True)
        if self._lock is None:
            fd = os.open(os.path.join(self.path, ".lock"), os.O_RDWR | os.O_CREAT, 0o644)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                os.close(fd)
                raise StoreBusy("%s: another client is running a study into this store" % self.path)
            self._lock = fd
        for leftover in os.listdir(self.partial):
            os.remove(os.path.join(self.partial, leftover))
        _write_json_atomically(os.path.join(self.path, "study.json"), study_record)

    def stored_ids(self):
        if not os.path.isdir(self.runs):
            return set()
        return {name[:-3] for name in os.listdir(self.runs) if name.endswith(".h5")}

    def is_current(self, run_id, model_sha256, outputs_sha256, library_version, library_build):
        """The run's file exists, reads, and was written for this model, outputs and library."""
        try:
            with h5py.File(self.run_path(run_id), "r") as f:
                a = f.attrs
                return (int(a["format"]) == FORMAT and a["model_sha256"] == model_sha256
                        and a["outputs_sha256"] == outputs_sha256 and a["library_version"] == library_version
                        and a["library_build"] == library_build)
        except (OSError, KeyError):
            return False

    def write(self, run, values, result, outputs_sha256, study_name):
        """Publishes one run: private file, fsync, rename, fsync the directory, then a log line."""
        partial = os.path.join(self.partial, "%s.%d.h5" % (run.run_id, os.getpid()))
        with h5py.File(partial, "w") as f:
            a = f.attrs
            a["format"] = FORMAT
            a["study"] = study_name
            a["run_id"] = run.run_id
            a["point_id"] = run.point_id
            a["member"] = run.member
            a["parameters"] = json.dumps(dict(values), sort_keys=True)
            a["model_sha256"] = run.model_sha256
            a["outputs_sha256"] = outputs_sha256
            a["model"] = json.dumps(run.model, sort_keys=True)
            for key in ("library_version", "library_build", "host", "pid", "wall_seconds", "simulate_seconds"):
                a[key] = result[key]
            reductions = f.create_group("reductions")
            for name, value in result["reductions"].items():
                reductions[name] = value
            series = f.create_group("time_series")
            for table, columns in result["time_series"].items():
                group = series.create_group(table)
                for name, data in columns.items():
                    group.create_dataset(name, data=np.asarray(data), compression="gzip", shuffle=True)
            f.flush()
        with open(partial, "rb") as f:
            os.fsync(f.fileno())
        os.replace(partial, self.run_path(run.run_id))
        _fsync_directory(self.runs)
        line = json.dumps({"run_id": run.run_id, "time": time.time(), "client_pid": os.getpid()}) + "\n"
        # One write(2) of a short line in append mode: a kill cannot tear it in the middle.
        fd = os.open(self.log, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        try:
            os.write(fd, line.encode())
        finally:
            os.close(fd)

    def read(self, run_id, series=True):
        """One stored run: attributes, reductions and (unless series=False) the time series."""
        with h5py.File(self.run_path(run_id), "r") as f:
            attrs = {k: (v.item() if hasattr(v, "item") else v) for k, v in f.attrs.items()}
            attrs["parameters"] = json.loads(attrs["parameters"])
            reductions = {k: float(v[()]) for k, v in f["reductions"].items()}
            data = {}
            if series:
                data = {t: {c: g[c][()] for c in g} for t, g in f["time_series"].items()}
        return {"attrs": attrs, "reductions": reductions, "time_series": data}

    def write_log(self):
        """The run ids of writes.log in order (a torn last line, which cannot happen with one
        write(2) per line, would be skipped)."""
        if not os.path.exists(self.log):
            return []
        ids = []
        with open(self.log) as f:
            for line in f:
                try:
                    ids.append(json.loads(line)["run_id"])
                except (ValueError, KeyError):
                    continue
        return ids

    def close(self):
        """Releases the lock (the kernel does it too when the process ends)."""
        if self._lock is not None:
            os.close(self._lock)
            self._lock = None

    def write_summary_file(self, name, text_or_value):
        path = os.path.join(self.summary, name)
        if isinstance(text_or_value, str):
            partial = path + ".partial-%d" % os.getpid()
            with open(partial, "w") as f:
                f.write(text_or_value)
            os.replace(partial, path)
        else:
            _write_json_atomically(path, text_or_value)
        return path
