# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.simulate: run a multibody model in process and get its time series as NumPy arrays."""
from __future__ import annotations

import errno
import json
import math
import os
import sys
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np

from . import _core
from ._run_files import RunFileError, read_folder_tables, read_json_bounded, typed_table

Model = Union[str, "os.PathLike[str]", Mapping[str, Any]]
Progress = Union[bool, None, Callable[[float], None]]


@dataclass(frozen=True)
class SimulationResult:
    """The time series of one run, the same numbers ``clearjoint simulate`` writes as CSV files.

    ``tables`` maps a table name to its columns, in file order, each a float64 array of shape
    ``(rows,)`` (one row per report time, ``solver.report_step`` apart from ``solver.start_time``
    to ``solver.end_time``). Names and columns are those of the CSV files without ``.csv``
    (docs/dynamics.md, dynamics/include/clearjoint/dynamics/simulation.hpp):

    - ``"body_<name>"``: time, x, y, z [m], e0..e3 (Euler parameters), vx, vy, vz [m/s],
      wx, wy, wz [rad/s], ax, ay, az [m/s^2], alphax, alphay, alphaz [rad/s^2]; world frame;
    - ``"energy"``: time, kinetic, potential, total [J], position_violation (max abs Phi),
      velocity_violation (max abs of Phi_q v + Phi_t), euler_norm_drift (max abs(abs(p) - 1));
    - ``"reactions"``: time, then ``<joint>.fx .. <joint>.mz`` per joint [N, N m]: the reaction
      of eq. (37) on body j, moment about the joint point, world frame;
    - ``"force_<element>"``: time and the columns a force element records (a clearance joint's
      scenario, depths, forces ...); NaN where the CSV file says ``nan``.

    ``read_run`` gives the same tables as pandas DataFrames (when pandas is installed) with the
    code columns typed as detection batches type them (``scenario`` int8, ...).

    ``summary`` has the run's statistics: steps, derivative_calls, smallest_step, largest_step,
    restarts, failed_attempts, initial_condition_iterations, initial_position_residual,
    initial_velocity_residual, initial_energy, max_energy_change, max_position_violation,
    max_velocity_violation, max_euler_norm_drift, element_statistics (list of str).

    ``result["energy"]["total"]`` is shorthand for ``result.tables["energy"]["total"]``. The
    object holds only dicts, lists and arrays, so it pickles (for process pools and Dask).
    """

    tables: Dict[str, Dict[str, np.ndarray]] = field(default_factory=dict)
    summary: Dict[str, Any] = field(default_factory=dict)
    folder: Optional[str] = None

    def __getitem__(self, table: str) -> Dict[str, np.ndarray]:
        return self.tables[table]

    def __repr__(self) -> str:
        # Column names and one column's length: the same for a dict of arrays and a DataFrame.
        shapes = ", ".join(f"{name}: {len(list(columns))} columns x {len(columns[next(iter(columns))])} rows"
                           for name, columns in self.tables.items())
        return f"SimulationResult({shapes})"


class _TextBar:
    """A one-line bar on standard error, used for ``progress=True`` when tqdm is not installed."""

    def __init__(self) -> None:
        self._percent = -1

    def __call__(self, fraction: float) -> None:
        percent = int(fraction * 100)
        if percent != self._percent:
            self._percent = percent
            filled = percent * 40 // 100
            sys.stderr.write(f"\r[{'#' * filled}{' ' * (40 - filled)}] {percent:3d}%")
            sys.stderr.flush()

    def close(self) -> None:
        if self._percent >= 0:
            sys.stderr.write("\n")


class _TqdmBar:
    """tqdm counting per cent of simulated time."""

    def __init__(self, tqdm_class: Any) -> None:
        self._bar = tqdm_class(total=100, unit="%", desc="simulate")
        self._percent = 0

    def __call__(self, fraction: float) -> None:
        percent = int(fraction * 100)
        if percent > self._percent:
            self._bar.update(percent - self._percent)
            self._percent = percent

    def close(self) -> None:
        self._bar.close()


def _progress_bar(progress: Progress) -> Any:
    if progress is None or progress is False:
        return None
    if progress is True:
        try:
            from tqdm import tqdm
        except ImportError:
            return _TextBar()
        return _TqdmBar(tqdm)
    if callable(progress):
        return progress
    raise TypeError(f"progress = {progress!r}: must be True, False, None or a callable(fraction)")


def _json_value(value: Any) -> Any:
    """NumPy scalars and arrays in a model dict, as JSON numbers and lists (parameter studies
    build models from arrays)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"model: a value of type {type(value).__name__} is not a JSON value")


#: Deepest nesting of a model dict, as for model files (clearjoint/json_input/bounded_json.hpp).
_MAX_NESTING_DEPTH = 64


def _check_json_values(value: Any, path: str, depth: int = 0) -> None:
    """Refuse what JSON cannot carry, naming the field: NaN and infinities (json.dumps writes them
    as bare words, which the model reader then reports as a parse error at a column), and
    nesting deeper than the model reader accepts."""
    if depth > _MAX_NESTING_DEPTH:
        raise ValueError(f"{path}: nesting deeper than {_MAX_NESTING_DEPTH} levels of lists and dicts (the limit)")
    if isinstance(value, Mapping):
        for key, item in value.items():
            if not isinstance(key, str):
                raise TypeError(f"{path}: key {key!r} is a {type(key).__name__}; model keys are strings")
            _check_json_values(item, f"{path}.{key}" if path else key, depth + 1)
    elif isinstance(value, (list, tuple)):
        for index, item in enumerate(value):
            _check_json_values(item, f"{path}[{index}]", depth + 1)
    elif isinstance(value, np.ndarray):
        if value.dtype.kind in "fc" and not np.all(np.isfinite(value)):
            raise ValueError(f"{path} = {value.tolist()!r}: every value must be finite")
    elif isinstance(value, (float, np.floating)) and not math.isfinite(value):
        raise ValueError(f"{path} = {value!r}: must be finite")


def _model_path(model: Union[str, "os.PathLike[str]"]) -> str:
    """The path as a str, refusing what the C++ reader would misread: a NUL ends a C string
    ('ball.json\\0/etc/passwd' would run ball.json). A missing file is FileNotFoundError, as
    open() says it."""
    path = _check_path_text(model, "model")
    if not os.path.exists(path):
        raise FileNotFoundError(errno.ENOENT, "model file not found", path)
    if os.path.isdir(path):
        raise IsADirectoryError(errno.EISDIR, "the model is a folder, not a model file", path)
    return path


def _model_text(model: Model) -> Tuple[str, str]:
    """(JSON text, source name) of a model path or dict, checked as simulate() checks them."""
    if isinstance(model, Mapping):
        _check_json_values(model, "")
        return json.dumps(model, default=_json_value, allow_nan=False), "<dict>"
    if isinstance(model, (str, os.PathLike)):
        path = _model_path(model)
        with open(path, "rb") as f:
            return f.read().decode("utf-8", errors="surrogateescape"), path
    raise TypeError(f"model = {type(model).__name__}: must be a path or a dict in the model-file format")


# output.decimation's range, as the model reader and the C++ run check it (dynamics::kMaxDecimation):
# checked here so that a Python integer beyond a C++ long is named, not refused by pybind11.
_MAX_DECIMATION = 10**9


def _check_options(allow_large: Any, report_step: Any, decimation: Any, out: Any, format: Any,
                   force: Any) -> None:
    for name, value in (("allow_large", allow_large), ("force", force)):
        if not isinstance(value, bool):
            raise TypeError(f"{name} = {value!r}: must be True or False")
    if report_step is not None and (isinstance(report_step, bool) or not isinstance(report_step, (int, float, np.integer, np.floating))):
        raise TypeError(f"report_step = {report_step!r}: must be a number of seconds or None")
    if decimation is not None and (isinstance(decimation, bool) or not isinstance(decimation, (int, np.integer))):
        raise TypeError(f"decimation = {decimation!r}: must be a whole number or None")
    if decimation is not None and not 1 <= decimation <= _MAX_DECIMATION:
        raise ValueError(f"decimation = {decimation!r}: must be in [1, 1e9]")
    if report_step is not None:
        try:
            float(report_step)
        except OverflowError:
            raise ValueError(f"report_step = {report_step!r}: too large for a double") from None
    if not isinstance(format, str):
        raise TypeError(f"format = {format!r}: must be a str, csv or hdf5")
    if out is None and (format != "csv" or force):
        raise ValueError("format and force apply to a run written to a folder: give out=")
    if out is not None:
        _check_path_text(out, "out")


def _check_path_text(value: Any, name: str) -> str:
    """`value` as a str path, refusing a NUL character: the C++ side would end the path there, so
    'runs/a\\0/../../x' would name another folder than the one the checks saw."""
    if not isinstance(value, (str, bytes, os.PathLike)):
        raise TypeError(f"{name} = {value!r}: must be a path (str or os.PathLike)")
    path = os.fspath(value)
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if "\0" in path:
        raise ValueError(f"{name} = {path!r}: a path cannot contain a NUL character")
    return path


def _override_items(overrides: Any) -> List[Tuple[str, str]]:
    """simulate(overrides=...) as [(path, JSON text of the value)] in the order given, for the
    C++ layer that writes them into the model (dynamics/model_overrides.hpp): the paths and
    their errors are the command line's --set."""
    if overrides is None:
        return []
    if not isinstance(overrides, Mapping):
        raise TypeError(f"overrides = {overrides!r}: must be a dict {{path: value}}, e.g. "
                        "{'solver.end_time': 0.01}")
    items = []
    for path, value in overrides.items():
        if not isinstance(path, str):
            raise TypeError(f"overrides: key {path!r} is a {type(path).__name__}; a path is a str such as "
                            "'solver.end_time', 'bodies[1].mass' or '/bodies/1/mass'")
        _check_json_values(value, f"overrides[{path!r}]")
        items.append((path, json.dumps(value, default=_json_value, allow_nan=False)))
    return items


# --fclib-count's range, as the C++ run checks it (nonsmooth::kMaxFclibProblems): checked here so
# that a Python integer beyond a C++ long is named, not refused by pybind11.
_MAX_FCLIB_PROBLEMS = 10**6


def _fclib_choices(write_fclib: Any, fclib_count: Any) -> Dict[str, Any]:
    """simulate(write_fclib=, fclib_count=) checked as the program checks --write-fclib and
    --fclib-count; the folder itself (created if absent, writable) is checked by the C++ run."""
    if fclib_count is not None:
        if isinstance(fclib_count, bool) or not isinstance(fclib_count, (int, np.integer)):
            raise TypeError(f"fclib_count = {fclib_count!r}: must be a whole number or None")
        if not 1 <= fclib_count <= _MAX_FCLIB_PROBLEMS:
            raise ValueError(f"fclib_count = {fclib_count!r}: must be a whole number in [1, {_MAX_FCLIB_PROBLEMS}]")
        if write_fclib is None:
            raise ValueError("fclib_count needs write_fclib=DIR")
    folder = None if write_fclib is None else _check_path_text(write_fclib, "write_fclib")
    return dict(write_fclib=folder, fclib_count=None if fclib_count is None else int(fclib_count))


def _check_engine(engine: Any) -> str:
    """The engine's name; the C++ layer refuses one this build cannot run, naming those it can."""
    if not isinstance(engine, str):
        raise TypeError(f"engine = {engine!r}: must be a str, one of {', '.join(_core.engines())}")
    return engine


def simulate(model: Model, *, progress: Progress = False, allow_large: bool = False,
             report_step: Optional[float] = None, decimation: Optional[int] = None,
             out: Union[None, str, "os.PathLike[str]"] = None, format: str = "csv",
             force: bool = False, engine: str = "clearjoint",
             overrides: Optional[Mapping[str, Any]] = None,
             write_fclib: Union[None, str, "os.PathLike[str]"] = None,
             fclib_count: Optional[int] = None) -> SimulationResult:
    """Run a multibody model in process and return its time series as NumPy arrays.

    Parameters
    ----------
    model:
        A path to a model file (str or os.PathLike), or a dict in the same JSON model-file format
        (docs/dynamics.md; models/ has examples), e.g. ``json.load(open(path))`` with some values
        changed; NumPy numbers and arrays in it are read as numbers and lists.
    progress:
        False (default) or None: silent. True: a progress bar over simulated time, tqdm's when
        tqdm is installed, else a one-line bar on standard error. A callable: called as
        ``progress(fraction)`` with the fraction of simulated time done, in [0, 1], at every
        report time and, between them, every 0.1 s of wall time.
    allow_large:
        False (default): refuse a run beyond the size guard of ``clearjoint simulate``
        (docs/command-line.md, "Size guard": more than 1000 s simulated, 1e7 report times or an
        estimated 4 GB of tables) with ValueError naming the setting; True runs it anyway, as
        ``--allow-large`` does.
    report_step, decimation:
        In place of the model's ``solver.report_step`` and ``output.decimation`` (rows at every
        decimation-th report time and the last), as ``--report-step`` and ``--decimation``.
    out, format, force:
        With ``out``, the run is written into that folder exactly as ``clearjoint simulate
        --out`` writes it (``format`` "csv" or "hdf5", ``force`` to replace an earlier result;
        docs/command-line.md, "Output folder"), and the result holds only the summary and the
        folder; ``read_run(out)`` reads it back.
    engine:
        The integrating engine, as ``clearjoint simulate --engine``: "clearjoint" (default) or
        "simbody" (when the package was built with the Simbody adapter; ``clearjoint._core.engines()``
        lists this build's), with the same tables and columns (docs/engines.md). Another name is
        a ValueError naming the engines there are.
    overrides:
        ``{path: value}``: values of the model set in place of the model's, as ``clearjoint
        simulate --set PATH=VALUE`` sets them (docs/command-line.md, "Setting model values"):
        ``path`` dotted as error messages name fields (``"solver.end_time"``,
        ``"bodies[1].mass"``) or a JSON pointer (``"/bodies/1/mass"``), ``value`` any JSON value
        (numbers, NumPy numbers and arrays, str, bool, lists, dicts). The model is validated
        with them written in, as a file holding those values; a path that does not exist, a
        value of the wrong type and one field given twice are ValueErrors naming it. The run's
        model.json holds the model as run, its summary the overrides (``summary["overrides"]``).
    write_fclib, fclib_count:
        With ``write_fclib`` a folder, a ``solver.method = "moreau_jean"`` run also writes the
        frictional contact problems of its first ``fclib_count`` steps with a contact (default
        100, at most 1e6) as FCLIB files ``step_<k>.hdf5`` there, as ``clearjoint simulate
        --write-fclib DIR --fclib-count N`` does (docs/nonsmooth.md, "FCLIB problems"). The
        folder is created if absent; one that cannot be written, a compliant model and
        ``fclib_count`` without ``write_fclib`` are ValueErrors naming the keyword.

    Returns
    -------
    SimulationResult
        ``tables[name][column]``: float64 arrays of shape (rows,), bit for bit the values of the
        CSV files ``clearjoint simulate MODEL --out DIR`` writes; ``summary``: run statistics
        (the keys of summary.json); ``folder``: the output folder, or None.

    Raises
    ------
    ValueError
        A bad model; the message names the field, e.g.
        ``"<dict>: bodies[1].mass = -1: must be positive"`` or ``"bodies[0].mass = nan: must be
        finite"``; a run beyond the size guard; a path with a NUL character.
    FileNotFoundError
        The model file does not exist.
    clearjoint.SolverError
        The equations could not be solved from some time on (a RuntimeError).
    KeyboardInterrupt
        Ctrl-C: the run stops within about 0.1 s; nothing is returned.

    The integration runs without the GIL; other Python threads keep running.
    """
    _check_options(allow_large, report_step, decimation, out, format, force)
    run_choices = dict(overrides=_override_items(overrides), engine=_check_engine(engine),
                       **_fclib_choices(write_fclib, fclib_count))
    bar = _progress_bar(progress)
    try:
        options = dict(allow_large=allow_large,
                       report_step=None if report_step is None else float(report_step),
                       decimation=None if decimation is None else int(decimation), **run_choices)
        if out is not None:
            text, source = _model_text(model)
            folder = _check_path_text(out, "out")
            summary = _core.simulate_into_folder(text, source, folder, format, force, bar, **options)
            return SimulationResult(tables={}, summary=summary, folder=folder)
        if isinstance(model, Mapping):
            text, source = _model_text(model)
            tables, summary = _core.simulate_text(text, source, bar, **options)
        elif isinstance(model, (str, os.PathLike)):
            tables, summary = _core.simulate_file(_model_path(model), bar, **options)
        else:
            raise TypeError(f"model = {type(model).__name__}: must be a path or a dict in the "
                            "model-file format")
    finally:
        if bar is not None and hasattr(bar, "close"):
            bar.close()
    columns = {name: dict(zip(header, values)) for name, (header, values) in tables.items()}
    return SimulationResult(tables=columns, summary=summary)


def read_run(folder: Union[str, "os.PathLike[str]"]) -> SimulationResult:
    """A run folder read back: the tables and summary of ``clearjoint simulate`` (either engine,
    CSV files or run.h5) or of ``clearjoint-mujoco`` (the same body, energy and force tables, a
    shorter summary).

    ``tables[name]`` is a pandas DataFrame when pandas can be imported, else a dict of NumPy
    arrays, as ``DetectionBatch.poses()`` gives its tables. Columns are those of the files, in
    file order; the numbers are float64, bit for bit what ``simulate`` returns in memory, except
    the code columns, which have the dtypes of detection batches: ``scenario``, ``certainty``,
    ``contact_count`` and ``film.regime`` int8, ``aligned`` bool (a code column holding a NaN
    stays float64). ``clearjoint.plot.read_run`` reads folders with this same reader and adds the
    model (docs/viewing-runs.md).

    Files are read with the limits of docs/command-line.md ("Reading a run back"): regular files
    only, no symbolic links, tables of at most 2 GiB; run.h5 only when its bytes match the
    checksum beside it (run.h5.sha256). Anything else raises ValueError naming the file."""
    folder = os.fspath(folder)
    if not os.path.isdir(folder):
        raise FileNotFoundError(errno.ENOENT, "run folder not found", folder)
    summary_path = os.path.join(folder, "summary.json")
    summary: Dict[str, Any] = {}
    if os.path.lexists(summary_path):
        loaded = read_json_bounded(summary_path, "summary")
        if not isinstance(loaded, dict):
            raise RunFileError(f"summary {summary_path!r}: not a JSON object")
        summary = loaded
    tables = {name: typed_table(columns) for name, columns in read_folder_tables(folder).items()}
    return SimulationResult(tables=tables, summary=summary, folder=folder)
