# SPDX-License-Identifier: BSD-3-Clause
"""The study store: one HDF5 file per run, published by rename, with its checksum beside it.

    STORE/.clearjoint-study-store  the marker: this folder is a study store
    STORE/study.json               the study file as last run, and its expansion's hashes
    STORE/runs/<run id>.h5         one run: reduced outputs, kept time series, parameters, model
    STORE/runs/<run id>.sha256     the SHA-256 of the run file's bytes (sha256sum's format)
    STORE/runs/.partial/           files being written (removed when a study starts)
    STORE/quarantine/              run files whose bytes no longer match their checksum
    STORE/writes.log               one JSON line per run written, appended after the rename
    STORE/.lock                    held (flock) by the client that runs the study
    STORE/summary/                 runs.csv, points.csv, trends.csv, summary.json (rewritten whole)

Why this shape. HDF5 (h5py) has no concurrent writers and no journal: a process killed while it
writes into an HDF5 file can leave the whole file unreadable, not just the last group. Zarr
(python3-zarr 2.13 in Debian 12) writes chunk by chunk, atomically per chunk file, but a run of
several arrays would still be visible half-written. So only the client writes, one run at a time
as results arrive, into a private file under runs/.partial/; the file is closed, fsync'ed and then
renamed to runs/<run id>.h5, and the directory fsync'ed. rename(2) is atomic: a run is either
absent or complete, whatever kills the client and when. The directory listing is the index; the
summary tables are derived from it and rewritten whole (write then rename) at the end of a study.

A run file is read only after its bytes match its checksum: libhdf5 trusts its input, and one
flipped byte in a header can crash the reading process instead of raising an error. The checksum
is published before the run file (and an older run file removed first), so that whatever the
moment of a kill, a run file present always has its own checksum beside it.

A run is reused when its file exists, matches its checksum, and was written under the same reuse
key (runner.reuse_key: model, outputs, library build and the whole Python package); otherwise it is
run again and the file replaced. One client runs a study at a time: it holds an flock on
STORE/.lock, which the kernel releases however it ends.

A store is a folder the study owns: one that holds the marker (a regular file the runner writes
before anything else), or an empty or new one; a folder holding anything else is refused, however
much it looks like a store (a summary/runs.csv of the user's is not the runner's), so that a
mistyped store cannot scatter a study's files over a folder of the user's or overwrite them. When
the store's folder is group-writable, everything the runner creates in it is group-writable too,
whatever the umask, so that the members of a group can take turns running a study into a shared
store.
"""
import fcntl
import hashlib
import json
import os
import stat
import time

import h5py
import numpy as np

from .._bounded_files import MAX_TABLE_BYTES, open_bounded, read_text_bounded

FORMAT = 3  # bump when the layout or the attributes of a run file change
MARKER = ".clearjoint-study-store"
MARKER_TEXT = "A clearjoint study store (docs/studies.md); the study runner writes into this folder.\n"
# Every file the store reads is opened with _bounded_files: a regular file, not through a symbolic
# link, of at most these sizes, so that a run file replaced by a FIFO, a link to /dev/zero or a
# runaway file is named and set aside instead of hanging or exhausting the reader.
# A checksum file is one line of sha256sum's format: 64 hex digits, two spaces and the run file's
# name (a 20-character run id and ".h5"); 4 KiB leaves room for any name.
MAX_CHECKSUM_BYTES = 4096
# A run file holds a run's reductions and its kept time series, gzip-compressed, and `read` loads
# them whole: the limit of a table `read_run` loads, which the kept series are sampled from.
MAX_RUN_FILE_BYTES = MAX_TABLE_BYTES
# writes.log grows by one line of about 80 bytes per run written, and is read line by line: the
# table limit allows some 25 million writes.
MAX_WRITE_LOG_BYTES = MAX_TABLE_BYTES
REUSE_ATTRIBUTES = ("model_sha256", "outputs_sha256", "library_version", "library_build", "package_sha256")


class StoreError(RuntimeError):
    """The store's folder cannot be used: not a folder, not a store, not writable."""


class StoreBusy(StoreError):
    """Another process holds the store's lock."""


class CorruptRun(StoreError):
    """A run file whose bytes do not match its checksum, or that has none."""


def _fsync_directory(path):
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _write_json_atomically(path, value):
    """Strict JSON (no NaN or Infinity, which strict parsers reject), written then renamed."""
    text = json.dumps(value, indent=1, sort_keys=True, allow_nan=False) + "\n"
    partial = path + ".partial-%d" % os.getpid()
    with open(partial, "w") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(partial, path)


def file_sha256(path):
    """The SHA-256 of a run file's bytes; ValueError for anything but a regular file of at most
    MAX_RUN_FILE_BYTES (a FIFO would block, /dev/zero never end)."""
    digest = hashlib.sha256()
    with open_bounded(path, "the run file", MAX_RUN_FILE_BYTES, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


class Store:
    def __init__(self, path):
        self.path = path
        self.runs = os.path.join(path, "runs")
        self.partial = os.path.join(self.runs, ".partial")
        self.quarantine_folder = os.path.join(path, "quarantine")
        self.summary = os.path.join(path, "summary")
        self.log = os.path.join(path, "writes.log")
        self._lock = None
        self._group_writable = False

    def run_path(self, run_id):
        return os.path.join(self.runs, run_id + ".h5")

    def checksum_path(self, run_id):
        return os.path.join(self.runs, run_id + ".sha256")

    # -- the folder -----------------------------------------------------------------------------

    def check_folder(self, must_exist=False):
        """Raises StoreError unless the path is a store, an empty folder, or (unless must_exist)
        absent."""
        if not os.path.lexists(self.path):
            if must_exist:
                raise StoreError("%s does not exist (no study has run into it yet)" % self.path)
            return
        if not os.path.isdir(self.path):
            raise StoreError("%s is a file, not a folder" % self.path)
        try:
            entries = sorted(os.listdir(self.path))
        except OSError as error:
            raise StoreError("cannot read the folder %s (%s)" % (self.path, error.strerror))
        if not entries or self._has_marker():
            return
        raise StoreError("%s is not a study store: it holds %s%s but no marker %s (a regular file the runner "
                         "writes into every store it makes); give a new or empty folder (a store made by a "
                         "version without the marker: create the marker file in it)"
                         % (self.path, ", ".join(entries[:3]), ", ..." if len(entries) > 3 else "", MARKER))

    def _has_marker(self):
        try:
            return stat.S_ISREG(os.lstat(os.path.join(self.path, MARKER)).st_mode)
        except OSError:
            return False

    def _share(self, path):
        """Makes what the runner created group-writable when the store's folder is."""
        if self._group_writable:
            mode = os.stat(path).st_mode
            os.chmod(path, stat.S_IMODE(mode) | stat.S_IRGRP | stat.S_IWGRP
                     | (stat.S_IXGRP if stat.S_ISDIR(mode) else 0))

    def _make_folder(self, path):
        if not os.path.isdir(path):
            os.mkdir(path)
            self._share(path)

    def _create_store_folder(self):
        parent = os.path.dirname(os.path.abspath(self.path))
        os.makedirs(parent, exist_ok=True)
        if not os.path.isdir(self.path):
            os.mkdir(self.path)
            if os.stat(parent).st_mode & stat.S_IWGRP:
                os.chmod(self.path, stat.S_IMODE(os.stat(self.path).st_mode) | stat.S_IRWXG)
        self._group_writable = bool(os.stat(self.path).st_mode & stat.S_IWGRP)

    def _take_lock(self):
        path = os.path.join(self.path, ".lock")
        created = not os.path.exists(path)
        try:
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
        except PermissionError:
            # Another user's lock file that is not group-writable: flock needs no write access.
            fd = os.open(path, os.O_RDONLY)
        if created:
            self._share(path)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise StoreBusy("%s: another client is running a study into this store" % self.path)
        self._lock = fd

    def open_for_writing(self, study_record):
        """Checks that the folder is a store (or new, or empty), takes its lock, creates the
        folders, removes what a killed client left half-written, and records the study. Raises
        StoreBusy when another client holds it, StoreError when the folder cannot be a store."""
        self.check_folder()
        try:
            self._create_store_folder()
            if not os.access(self.path, os.W_OK | os.X_OK):
                raise PermissionError(13, "Permission denied")
            # The marker first: a client killed at any later point leaves a folder that is a store.
            if not self._has_marker():
                marker = os.path.join(self.path, MARKER)
                with open(marker, "w") as f:
                    f.write(MARKER_TEXT)
                self._share(marker)
            if self._lock is None:
                self._take_lock()
            for folder in (self.runs, self.partial, self.summary):
                self._make_folder(folder)
            for leftover in os.listdir(self.partial):
                os.remove(os.path.join(self.partial, leftover))
            study_json = os.path.join(self.path, "study.json")
            _write_json_atomically(study_json, study_record)
            self._share(study_json)
        except OSError as error:
            self.close()
            raise StoreError("cannot write into %s (%s%s)" % (self.path, error.strerror or error, self._owner_text()))

    def open_for_reading(self):
        """Checks that the folder exists and is a store, for the commands that only read it (and
        rewrite its summary)."""
        self.check_folder(must_exist=True)
        self._group_writable = bool(os.stat(self.path).st_mode & stat.S_IWGRP)

    def _owner_text(self):
        try:
            st = os.stat(self.path)
        except OSError:
            return ""
        return "; the folder belongs to user %d, group %d, mode %03o" % (st.st_uid, st.st_gid, stat.S_IMODE(st.st_mode))

    # -- runs -----------------------------------------------------------------------------------

    def stored_ids(self):
        if not os.path.isdir(self.runs):
            return set()
        return {name[:-3] for name in os.listdir(self.runs) if name.endswith(".h5")}

    def has_checksum(self, run_id):
        return os.path.lexists(self.checksum_path(run_id))

    def verify(self, run_id):
        """None when the run file's bytes match its checksum, else why not."""
        try:
            text = read_text_bounded(self.checksum_path(run_id), "its checksum", MAX_CHECKSUM_BYTES)
            expected = text.split()[0]
        except FileNotFoundError:
            return "no checksum beside it (%s)" % os.path.basename(self.checksum_path(run_id))
        except ValueError as error:
            return str(error)
        except IndexError:
            return "its checksum %s is empty" % os.path.basename(self.checksum_path(run_id))
        try:
            actual = file_sha256(self.run_path(run_id))
        except OSError as error:
            return "unreadable (%s)" % (error.strerror or error)
        except ValueError as error:
            return str(error)
        if actual != expected:
            return "its bytes do not match its checksum (SHA-256 %s, recorded %s)" % (actual[:12], expected[:12])
        return None

    def set_aside(self, run_id):
        """Moves a run file (and its checksum) to STORE/quarantine/<run id>.<UTC time>.h5, where
        nothing reads it; returns the new path."""
        self._make_folder(self.quarantine_folder)
        stamp = time.strftime("%Y%m%dT%H%M%SZ", time.gmtime())
        target = os.path.join(self.quarantine_folder, "%s.%s.h5" % (run_id, stamp))
        copy = 0
        while os.path.exists(target):  # set aside twice within a second: keep both
            copy += 1
            target = os.path.join(self.quarantine_folder, "%s.%s-%d.h5" % (run_id, stamp, copy))
        os.replace(self.run_path(run_id), target)
        if os.path.exists(self.checksum_path(run_id)):
            os.replace(self.checksum_path(run_id), target[:-3] + ".sha256")
        _fsync_directory(self.runs)
        return target

    def is_current(self, run_id, key):
        """The run's file matches its checksum and was written under this reuse key
        ({attribute: value}, runner.reuse_key). Verify first: a file that fails is not opened."""
        if self.verify(run_id) is not None:
            return False
        try:
            with h5py.File(self.run_path(run_id), "r") as f:
                a = f.attrs
                return int(a["format"]) == FORMAT and all(a[name] == value for name, value in key.items())
        except (OSError, KeyError):
            return False

    def _publish(self, partial, target):
        with open(partial, "rb") as f:
            os.fsync(f.fileno())
        os.replace(partial, target)
        self._share(target)

    def write(self, run, values, result, outputs_sha256, study_name):
        """Publishes one run: private file, fsync; its checksum, published first; the run file,
        renamed into place; fsync the directory; then a log line. Raises StoreError saying why
        when the file system refuses (a full disk, say)."""
        try:
            self._write(run, values, result, outputs_sha256, study_name)
        except OSError as error:
            raise StoreError("cannot write run %s into %s (%s)" % (run.run_id, self.runs, error.strerror or error))

    def _write(self, run, values, result, outputs_sha256, study_name):
        partial = os.path.join(self.partial, "%s.%d.h5" % (run.run_id, os.getpid()))
        with h5py.File(partial, "w") as f:
            a = f.attrs
            a["format"] = FORMAT
            a["study"] = study_name
            a["run_id"] = run.run_id
            a["point_id"] = run.point_id
            a["member"] = run.member
            a["parameters"] = json.dumps(dict(values), sort_keys=True, allow_nan=False)
            a["model_sha256"] = run.model_sha256
            a["outputs_sha256"] = outputs_sha256
            a["model"] = json.dumps(run.model, sort_keys=True, allow_nan=False)
            a["engine"] = run.engine
            for key in ("library_version", "library_build", "package_sha256", "host", "pid", "wall_seconds",
                        "simulate_seconds"):
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
        checksum = partial[:-3] + ".sha256"
        with open(checksum, "w") as f:
            f.write("%s  %s.h5\n" % (file_sha256(partial), run.run_id))
        if os.path.exists(self.run_path(run.run_id)):  # an older run: never beside the new checksum
            os.remove(self.run_path(run.run_id))
        self._publish(checksum, self.checksum_path(run.run_id))
        self._publish(partial, self.run_path(run.run_id))
        _fsync_directory(self.runs)
        line = json.dumps({"run_id": run.run_id, "time": time.time(), "client_pid": os.getpid()}) + "\n"
        # One write(2) of a short line in append mode: a kill cannot tear it in the middle.
        created = not os.path.exists(self.log)
        fd = os.open(self.log, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o666)
        try:
            os.write(fd, line.encode())
        finally:
            os.close(fd)
        if created:
            self._share(self.log)

    def read(self, run_id, series=True):
        """One stored run: attributes, reductions and (unless series=False) the time series.
        Raises CorruptRun, without opening it, for a file that does not match its checksum."""
        reason = self.verify(run_id)
        if reason is not None:
            raise CorruptRun("%s: %s" % (self.run_path(run_id), reason))
        try:
            with h5py.File(self.run_path(run_id), "r") as f:
                attrs = {k: (v.item() if hasattr(v, "item") else v) for k, v in f.attrs.items()}
                attrs["parameters"] = json.loads(attrs["parameters"])
                reductions = {k: float(v[()]) for k, v in f["reductions"].items()}
                data = {}
                if series:
                    data = {t: {c: g[c][()] for c in g} for t, g in f["time_series"].items()}
        except (OSError, KeyError, ValueError) as error:
            raise CorruptRun("%s: not a run file of this format (%s)" % (self.run_path(run_id), error))
        return {"attrs": attrs, "reductions": reductions, "time_series": data}

    def write_log(self):
        """The run ids of writes.log in order (a torn last line, which cannot happen with one
        write(2) per line, would be skipped)."""
        if not os.path.exists(self.log):
            return []
        ids = []
        with open_bounded(self.log, "the store's writes.log", MAX_WRITE_LOG_BYTES) as f:
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
        """Writes summary/<name> whole (write, then rename); text as given, anything else as
        strict JSON. Raises StoreError saying why when the file system refuses."""
        path = os.path.join(self.summary, name)
        try:
            self._make_folder(self.summary)
            if isinstance(text_or_value, str):
                partial = path + ".partial-%d" % os.getpid()
                with open(partial, "w") as f:
                    f.write(text_or_value)
                os.replace(partial, path)
            else:
                _write_json_atomically(path, text_or_value)
            self._share(path)
        except OSError as error:
            raise StoreError("cannot write %s (%s%s)" % (path, error.strerror or error, self._owner_text()))
        return path
