# SPDX-License-Identifier: BSD-3-Clause
"""The task a Dask worker runs: simulate one model in process and reduce it.

It imports clearjoint on the worker, so a worker needs the package on its path (docs/studies.md).
"""
import functools
import hashlib
import os
import socket
import time


@functools.lru_cache(maxsize=None)
def library_build():
    """SHA-256 of the clearjoint binaries this process runs: the extension module and the
    clearjoint shared libraries it has mapped (/proc/self/maps; the module alone where there is no
    /proc). The version string stays the same between releases while the code changes, and the
    motion is chaotic, so a stored run is reused only for the same binaries."""
    import clearjoint._core as core
    paths = {os.path.realpath(core.__file__)}
    try:
        with open("/proc/self/maps") as maps:
            for line in maps:
                path = line.split()[-1] if len(line.split()) >= 6 else ""
                if "libclearjoint" in os.path.basename(path) and os.path.exists(path):
                    paths.add(os.path.realpath(path))
    except OSError:
        pass
    digest = hashlib.sha256()
    for path in sorted(paths, key=os.path.basename):
        digest.update(os.path.basename(path).encode())
        with open(path, "rb") as f:
            digest.update(hashlib.sha256(f.read()).digest())
    return digest.hexdigest()


# The Python source that turns a simulation into the stored values: this module (the tables) and
# reduce.py (the reductions and kept samples). A change to either changes a stored run.
REDUCING_SOURCES = ("execute.py", "reduce.py")


@functools.lru_cache(maxsize=None)
def reduction_code():
    """SHA-256 of the reducing Python source this process runs (REDUCING_SOURCES), so that a
    stored run is reused only when the same code reduced it."""
    here = os.path.dirname(os.path.abspath(__file__))
    digest = hashlib.sha256()
    for name in REDUCING_SOURCES:
        digest.update(name.encode())
        with open(os.path.join(here, name), "rb") as f:
            digest.update(hashlib.sha256(f.read()).digest())
    return digest.hexdigest()


def tables_of(result):
    """The simulation's tables as {name: {column: array}}, names without ".csv"."""
    tables = getattr(result, "tables", result)
    out = {}
    for name, t in dict(tables).items():
        name = name[:-4] if name.endswith(".csv") else name
        if hasattr(t, "dtype") and t.dtype.names:  # a structured array
            out[name] = {c: t[c] for c in t.dtype.names}
        else:
            out[name] = dict(t)
    return out


def execute_run(payload):
    """payload: run_id, model (dict), outputs (the study's outputs). Returns the reduced run and
    where and how long it ran. Raises what simulate raises for a bad model (the client reports
    it with the run)."""
    import clearjoint
    from .reduce import reduce_run

    start = time.perf_counter()
    result = clearjoint.simulate(payload["model"])
    simulated = time.perf_counter()
    reductions, series = reduce_run(tables_of(result), payload["outputs"])
    return {"run_id": payload["run_id"],
            "reductions": reductions,
            "time_series": series,
            "simulate_seconds": simulated - start,
            "wall_seconds": time.perf_counter() - start,
            "library_version": clearjoint.__version__,
            "library_build": library_build(),
            "reduction_sha256": reduction_code(),
            "host": socket.gethostname(),
            "pid": os.getpid()}
