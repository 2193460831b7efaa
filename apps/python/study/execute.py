# SPDX-License-Identifier: BSD-3-Clause
"""The task a Dask worker runs: simulate one model in process and reduce it.

It imports clearjoint on the worker, so a worker needs the package on its path (docs/studies.md).
"""
import functools
import hashlib
import os
import socket
import time

from .study_file import DEFAULT_ENGINE


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


@functools.lru_cache(maxsize=None)
def package_code():
    """SHA-256 of the clearjoint package this process imports: every .py file under the package's
    folder (simulate's wrappers and result tables as much as the study's reductions) and the
    compiled module clearjoint._core, each by its path relative to the package and its bytes, in
    sorted order, so that a copy of the package in another folder gives the same hash and a copy
    with one file changed another. A stored run is reused only when the same package made it."""
    import clearjoint._core as core
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    files = {os.path.relpath(os.path.realpath(core.__file__), os.path.realpath(root)): core.__file__}
    for folder, subfolders, names in os.walk(root):
        subfolders[:] = [name for name in subfolders if name != "__pycache__"]
        for name in names:
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                files[os.path.relpath(path, root)] = path
    digest = hashlib.sha256()
    for relative in sorted(files):
        digest.update(relative.encode())
        with open(files[relative], "rb") as f:
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
    """payload: run_id, model (dict), outputs (the study's outputs), engine (clearjoint.simulate's;
    default "clearjoint"). Returns the reduced run and
    where and how long it ran. Raises what simulate raises for a bad model (the client reports
    it with the run)."""
    import clearjoint
    from .reduce import reduce_run

    start = time.perf_counter()
    result = clearjoint.simulate(payload["model"], engine=payload.get("engine", DEFAULT_ENGINE))
    simulated = time.perf_counter()
    reductions, series = reduce_run(tables_of(result), payload["outputs"])
    return {"run_id": payload["run_id"],
            "reductions": reductions,
            "time_series": series,
            "simulate_seconds": simulated - start,
            "wall_seconds": time.perf_counter() - start,
            "library_version": clearjoint.__version__,
            "library_build": library_build(),
            "package_sha256": package_code(),
            "host": socket.gethostname(),
            "pid": os.getpid()}
