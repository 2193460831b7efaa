# SPDX-License-Identifier: BSD-3-Clause
"""Opening the files a user names (tables, study files, summaries) with the limits model files
have: only regular files, not through a symbolic link, and no larger than a stated size.

A table linked to /dev/zero, a FIFO or a 20 GB file would otherwise be read whole (or forever)
before anything could complain; a symbolic link to a system file would have its first line quoted
in an error message. Each refusal is a ValueError that names what the file was for, its path and
the limit, and quotes none of its content.
"""
from __future__ import annotations

import os
import stat
from typing import IO, Union

PathLike = Union[str, "os.PathLike[str]"]

# The largest table `plot`, `view` and `read_run` read: a run's CSV files are limited to 4e9 bytes
# in all (dynamics/run_size.hpp, kMaxOutputBytes); one table of 2 GiB is then read into memory as
# about twice as many bytes of float64 columns, which the 24 GiB machines this project targets
# hold. Larger tables are refused with this limit named instead of exhausting memory.
MAX_TABLE_BYTES = 2 << 30

# The largest study file, summary or reduction file: the same 16 MiB as a model file
# (dynamics/model_file.hpp, kMaxModelFileBytes); these are small hand-written or generated files.
MAX_DESCRIPTION_BYTES = 16 << 20


def _describe(path: PathLike) -> str:
    return repr(os.fspath(path))


def check_regular_file(path: PathLike, what: str, limit: int) -> int:
    """Returns the size of `path` after checking that it is a regular file reached without a
    symbolic link in its last component, and at most `limit` bytes. Raises FileNotFoundError for a
    missing file and ValueError for the rest, naming `what` and the path."""
    name = os.fspath(path)
    try:
        info = os.lstat(name)
    except FileNotFoundError:
        raise FileNotFoundError(f"{what} {_describe(path)} does not exist") from None
    except OSError as error:
        raise ValueError(f"{what} {_describe(path)} cannot be read: {error.strerror}") from None
    if stat.S_ISLNK(info.st_mode):
        raise ValueError(f"{what} {_describe(path)} is a symbolic link; name the file itself "
                         f"(links are not followed, so that no other file is read)")
    if not stat.S_ISREG(info.st_mode):
        raise ValueError(f"{what} {_describe(path)} is not a regular file")
    if info.st_size > limit:
        raise ValueError(f"{what} {_describe(path)} holds {info.st_size} bytes, more than the "
                         f"{limit} bytes accepted")
    return info.st_size


def open_bounded(path: PathLike, what: str, limit: int, mode: str = "r",
                 **kwargs) -> IO:
    """Opens `path` after check_regular_file, with O_NOFOLLOW so that a link swapped in between
    the check and the open is refused too. `mode` is "r" (text, UTF-8 unless `encoding` is given)
    or "rb"."""
    check_regular_file(path, what, limit)
    flags = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
    try:
        descriptor = os.open(os.fspath(path), flags)
    except OSError as error:
        raise ValueError(f"{what} {_describe(path)} cannot be opened: {error.strerror}") from None
    info = os.fstat(descriptor)
    if not stat.S_ISREG(info.st_mode) or info.st_size > limit:
        os.close(descriptor)
        raise ValueError(f"{what} {_describe(path)} changed while it was opened; try again")
    if "b" not in mode:
        kwargs.setdefault("encoding", "utf-8")
    return os.fdopen(descriptor, mode, **kwargs)


def read_text_bounded(path: PathLike, what: str, limit: int = MAX_DESCRIPTION_BYTES) -> str:
    """The whole text of a file of at most `limit` bytes (see open_bounded). Reads at most
    limit + 1 bytes whatever the file claims, so a file that grows while read is refused too."""
    with open_bounded(path, what, limit, "rb") as handle:
        data = handle.read(limit + 1)
    if len(data) > limit:
        raise ValueError(f"{what} {_describe(path)} holds more than the {limit} bytes accepted")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        raise ValueError(f"{what} {_describe(path)} is not UTF-8 text (byte {error.start})") \
            from None
