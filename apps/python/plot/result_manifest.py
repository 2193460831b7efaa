# SPDX-License-Identifier: BSD-3-Clause
"""The files a tool writes into a run folder, added to the run's manifest.

Every run folder holds ``.clearjoint-result``: a header line, then the files clearjoint wrote into
the folder, one relative '/'-separated path a line (dynamics/include/clearjoint/dynamics/
output_folder.hpp). ``clearjoint simulate --force`` replaces a run folder only while it holds
nothing the manifest does not list, so that a user's own files in it are never deleted; what
``clearjoint plot`` writes there (``figures/``) is listed here so that the next ``--force`` run
replaces it with the rest.
"""
from __future__ import annotations

import os
from typing import Iterable

from .._bounded_files import read_text_bounded

MARKER = ".clearjoint-result"
# output_folder.hpp, OutputFolder::kManifestHeader and kMaxManifestBytes.
HEADER = "clearjoint result manifest 1"
MAX_MANIFEST_BYTES = 32 << 20


def register_written(run_folder: "os.PathLike[str] | str", paths: Iterable[str]) -> None:
    """Appends to ``run_folder``'s manifest those of ``paths`` that lie inside it and are not
    listed yet. Does nothing for a folder that is not a clearjoint result (no manifest, or one
    clearjoint did not write): ``--force`` refuses such a folder whatever it lists."""
    folder = os.path.abspath(os.fspath(run_folder))
    manifest = os.path.join(folder, MARKER)
    try:
        text = read_text_bounded(manifest, "the run's manifest", MAX_MANIFEST_BYTES)
    except (OSError, ValueError):
        return
    if not text.startswith(HEADER) or not text.endswith("\n"):
        return
    listed = set(text.split("\n")[1:])
    entries = []
    for path in paths:
        relative = os.path.relpath(os.path.abspath(os.fspath(path)), folder)
        if relative == os.pardir or relative.startswith(os.pardir + os.sep) or "\n" in relative:
            continue  # outside the run folder: not the run's to replace
        entry = relative.replace(os.sep, "/")
        if entry not in listed:
            listed.add(entry)
            entries.append(entry)
    if not entries:
        return
    flags = os.O_WRONLY | os.O_APPEND | getattr(os, "O_NOFOLLOW", 0)
    descriptor = os.open(manifest, flags)
    with os.fdopen(descriptor, "a", encoding="utf-8") as stream:
        stream.write("".join(entry + "\n" for entry in entries))
