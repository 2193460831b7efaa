# SPDX-License-Identifier: BSD-3-Clause
"""Reading the files of a run folder of ``clearjoint simulate`` (docs/command-line.md, "Output
folder"): its CSV tables and its HDF5 file ``run.h5``, for ``clearjoint.read_run`` and for the
figures and the viewer (``clearjoint.plot.read_run``).

Every file is opened through the bounded reader (_bounded_files: regular files only, no symbolic
link, at most MAX_TABLE_BYTES). No message quotes a file's content: a table linked or copied from
elsewhere may hold anything, and an error message is often pasted where others read it.

``run.h5`` is read only after its bytes match the SHA-256 the writer put beside it
(``run.h5.sha256``, sha256sum's format): libhdf5 trusts its input, and one flipped byte in the
file's metadata can crash the reading process instead of raising an error. A run without that
file is refused (say how to add it), for the same reason.
"""
from __future__ import annotations

import hashlib
import os
import re
from typing import Any, Dict, List, Tuple

import numpy as np

from ._bounded_files import MAX_DESCRIPTION_BYTES, MAX_TABLE_BYTES, open_bounded, read_text_bounded

#: The HDF5 file of a run and its checksum (dynamics/run_folder/run_folder.hpp).
HDF5_FILE = "run.h5"
CHECKSUM_FILE = HDF5_FILE + ".sha256"
#: The value of run.h5's attribute ``format`` (dynamics/run_folder/hdf5_tables.hpp, kHdf5RunFormat).
HDF5_FORMAT = "clearjoint-run-1"

# sha256sum's line: 64 hex digits, two spaces (or a space and '*', binary mode), the file name.
_CHECKSUM_LINE = re.compile(r"([0-9a-fA-F]{64}) [ *]" + re.escape(HDF5_FILE) + r"\r?\n?")
# Bytes hashed per read: large enough that Python's loop costs nothing beside SHA-256 itself.
_HASH_CHUNK_BYTES = 1 << 20


class RunFileError(ValueError):
    """A run file that cannot be read: missing, not a regular file, too large, damaged."""


def read_csv_table(path: str) -> Tuple[List[str], np.ndarray]:
    """The header and the values (rows x columns, float64) of a CSV table of a run."""
    name = os.path.basename(path)
    try:
        with open_bounded(path, "table", MAX_TABLE_BYTES) as stream:
            header = stream.readline().rstrip("\r\n").split(",")
            if header == [""]:
                raise RunFileError(f"{path}: empty (a truncated table)")
            try:
                values = np.loadtxt(stream, delimiter=",", ndmin=2, dtype=np.float64)
            except ValueError:
                # NumPy's message quotes the offending text: say where, not what.
                raise RunFileError(f"{path}: a row is not {len(header)} numbers separated by "
                                   "commas (a truncated or damaged table)") from None
    except UnicodeDecodeError as error:
        raise RunFileError(f"{path}: not UTF-8 text near byte {error.start} of a line "
                           "(a damaged table)") from None
    except MemoryError:
        raise RunFileError(f"{path}: not enough memory to read this table "
                           f"({os.path.getsize(path)} bytes)") from None
    except FileNotFoundError as error:
        raise RunFileError(str(error)) from None
    if values.size == 0:
        values = np.zeros((0, len(header)))
    if values.shape[1] != len(header):
        raise RunFileError(f"{path}: {values.shape[1]} columns in the rows, {len(header)} in the "
                           f"header of {name} (a truncated or damaged table)")
    return header, values


def read_json_bounded(path: str, what: str) -> object:
    """A small JSON file of the run (model.json, summary.json), at most MAX_DESCRIPTION_BYTES."""
    import json
    text = read_text_bounded(path, what, MAX_DESCRIPTION_BYTES)
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        # The decoder's message gives the place (line, column), not the text there.
        raise RunFileError(f"{what} {path!r}: not JSON ({error})") from None


def _recorded_checksum(folder: str) -> str:
    path = os.path.join(folder, CHECKSUM_FILE)
    if not os.path.lexists(path):
        raise RunFileError(
            f"{HDF5_FILE} in {folder} has no checksum beside it ({CHECKSUM_FILE}), so it cannot be "
            "checked before reading (a damaged HDF5 file can crash the reader); run the simulation "
            f"again, or, if you trust the file, write one in that folder with "
            f"`sha256sum {HDF5_FILE} > {CHECKSUM_FILE}`")
    match = _CHECKSUM_LINE.fullmatch(read_text_bounded(path, "checksum file", MAX_DESCRIPTION_BYTES))
    if match is None:
        raise RunFileError(f"{CHECKSUM_FILE} in {folder} is not one SHA-256 line for {HDF5_FILE} "
                           "(sha256sum's format); the folder is damaged")
    return match.group(1).lower()


def _damaged(folder: str, why: str) -> RunFileError:
    return RunFileError(f"{HDF5_FILE} in {folder} does not match its checksum: the file is damaged "
                        f"({why}); run the simulation again")


def _unreadable(folder: str, why: str) -> RunFileError:
    return RunFileError(f"{HDF5_FILE} in {folder} cannot be read as a run: the file is damaged or "
                        f"was not written by clearjoint simulate ({why})")


def read_hdf5_tables(folder: str) -> Dict[str, Dict[str, np.ndarray]]:
    """The tables of ``FOLDER/run.h5``, table -> column -> float64 array, after checking its bytes
    against ``FOLDER/run.h5.sha256``. Every failure is a RunFileError naming the folder."""
    expected = _recorded_checksum(folder)
    path = os.path.join(folder, HDF5_FILE)
    # The bytes hashed are the bytes h5py reads: one descriptor, opened once, for both.
    with open_bounded(path, HDF5_FILE, MAX_TABLE_BYTES, "rb") as handle:
        digest = hashlib.sha256()
        for chunk in iter(lambda: handle.read(_HASH_CHUNK_BYTES), b""):
            digest.update(chunk)
        actual = digest.hexdigest()
        if actual != expected:
            raise _damaged(folder, f"SHA-256 {actual[:12]}..., recorded {expected[:12]}...")
        handle.seek(0)
        try:
            return _tables_of(handle)
        except RunFileError as error:
            raise _unreadable(folder, str(error)) from None
        except MemoryError:
            raise RunFileError(f"{HDF5_FILE} in {folder}: not enough memory to read its tables") from None
        except Exception as error:  # noqa: BLE001 - h5py raises OSError, KeyError, ValueError, ...
            # Its bytes match the checksum, yet HDF5 cannot read them: a file made elsewhere. HDF5's
            # message may name objects of the file: only the kind of failure is given.
            raise _unreadable(folder, f"HDF5 cannot read it: {type(error).__name__}") from None


def _tables_of(handle) -> Dict[str, Dict[str, np.ndarray]]:
    import h5py  # Debian: python3-h5py
    tables: Dict[str, Dict[str, np.ndarray]] = {}
    with h5py.File(handle, "r") as f:
        if f.attrs.get("format") not in (HDF5_FORMAT, HDF5_FORMAT.encode()):
            raise RunFileError(f"its attribute format is not {HDF5_FORMAT}")
        group = f.get("tables")
        if not isinstance(group, h5py.Group):
            raise RunFileError("it has no group tables")
        for name, dataset in group.items():
            if not isinstance(dataset, h5py.Dataset) or dataset.ndim != 2 or dataset.dtype.kind != "f":
                raise RunFileError(f"tables/{name} is not a 2-D dataset of numbers")
            names = [c.decode() if isinstance(c, bytes) else str(c) for c in dataset.attrs.get("columns", [])]
            if len(names) != dataset.shape[1]:
                raise RunFileError(f"tables/{name} has {len(names)} column names for "
                                   f"{dataset.shape[1]} columns")
            values = np.asarray(dataset[:], dtype=np.float64)
            tables[name] = {column: np.ascontiguousarray(values[:, k]) for k, column in enumerate(names)}
    return tables


Tables = Dict[str, Dict[str, np.ndarray]]


def read_folder_tables(folder: str) -> Tables:
    """Every table of a run folder, table -> column -> float64 array: ``run.h5`` when the folder
    has one (checked against its checksum), else its ``*.csv`` files. Any folder of
    ``clearjoint simulate`` (either engine, either format) or of ``clearjoint-mujoco`` (the same
    body, energy and force tables) reads; a folder holding neither is a RunFileError naming it."""
    if os.path.lexists(os.path.join(folder, HDF5_FILE)):
        return read_hdf5_tables(folder)
    tables: Tables = {}
    for entry in sorted(os.listdir(folder)):
        if entry.endswith(".csv"):
            header, values = read_csv_table(os.path.join(folder, entry))
            tables[entry[:-len(".csv")]] = {column: np.ascontiguousarray(values[:, k])
                                            for k, column in enumerate(header)}
    if not tables:
        raise RunFileError(f"{folder}: not a run folder: no run tables (no {HDF5_FILE} and no .csv "
                           "files; clearjoint simulate --out and clearjoint-mujoco --out write them)")
    return tables


#: Columns that hold codes, with the dtype detection batches give the same codes
#: (clearjoint/_detect.py, DetectionBatch): ContactScenario, Certainty and counts as int8, the
#: parallel-axes flag as bool; a lubricated joint's film regime (0 dry, 1 film, 2 blend) as int8.
CODE_COLUMNS = {"scenario": np.int8, "certainty": np.int8, "contact_count": np.int8,
                "aligned": np.bool_, "film.regime": np.int8}


def typed_column(name: str, values: np.ndarray) -> np.ndarray:
    """A table's column with the dtype of CODE_COLUMNS when it is one and every value is a whole
    number in range (a code column of another writer holding NaN stays float64)."""
    dtype = CODE_COLUMNS.get(name)
    if dtype is None or not np.all(np.isfinite(values)) or not np.all(values == np.round(values)):
        return values
    if dtype is np.bool_:
        return values != 0.0 if np.all((values == 0.0) | (values == 1.0)) else values
    limits = np.iinfo(dtype)
    if values.size and (values.min() < limits.min or values.max() > limits.max):
        return values
    return values.astype(dtype)


def typed_table(columns: Dict[str, np.ndarray]) -> Any:
    """A run table as ``clearjoint.read_run`` returns it: a pandas DataFrame when pandas can be
    imported (as DetectionBatch.poses()), else the dict of arrays; code columns typed."""
    typed = {name: typed_column(name, values) for name, values in columns.items()}
    try:
        import pandas
    except ImportError:
        return typed
    return pandas.DataFrame(typed, copy=False)
