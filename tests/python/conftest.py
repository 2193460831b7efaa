# SPDX-License-Identifier: BSD-3-Clause
"""Paths the tests share, from the environment ctest sets (tests/python/CMakeLists.txt)."""
import os
import pathlib

import pytest


def _directory(variable: str) -> pathlib.Path:
    value = os.environ.get(variable)
    if not value:
        raise RuntimeError(f"{variable} is not set: run the Python tests through ctest")
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def models_dir() -> pathlib.Path:
    return _directory("CLEARJOINT_MODELS_DIR")


@pytest.fixture(scope="session")
def cli() -> pathlib.Path:
    """The clearjoint command-line program of the same build."""
    return _directory("CLEARJOINT_CLI")
