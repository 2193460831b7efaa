# SPDX-License-Identifier: BSD-3-Clause
"""`pip install .`: the clearjoint Python package, its compiled core built by CMake.

pyproject.toml holds the metadata and the build system (setuptools); this file adds the two things
a declarative file cannot say: the version, read from CMakeLists.txt, and a build_ext command that
runs CMake. scikit-build-core would do the latter, but Debian 12 does not package it (it has only
the classic scikit-build 0.16, python3-skbuild), and the CMake call below is all it would do.

Offline, with Debian's python3-setuptools and python3-wheel, in a virtual environment that sees
Debian's NumPy (docs/python.md):

    /usr/bin/python3 -m venv --system-site-packages V
    V/bin/pip install --no-index --no-build-isolation .

The extension is linked against static, position-independent copies of the clearjoint libraries
(cmake/ClearjointPositionIndependent.cmake), so the installed package does not depend on a
`cmake --install` of the C++ libraries. The CMake build folder is build-pip/temp.*/cmake, beside
the README's CMake build folder build/, not inside it (where removing either would remove both,
and the two builds' options would be hard to tell apart), kept between runs: a second `pip install .` or `pip wheel .` recompiles only
what changed. CMAKE_BUILD_PARALLEL_LEVEL sets the number of compile jobs (default: every core).

The package's `clearjoint` command (pyproject.toml's [project.scripts], clearjoint/__main__.py)
runs plot, view and study, and hands the other subcommands to the C++ program `clearjoint` when
one is installed: the program is not built here.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, find_namespace_packages, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = pathlib.Path(__file__).resolve().parent
# setuptools' build folder (relative to the sources), which holds the CMake build: beside the
# README's build/, not inside it.
PIP_BUILD_FOLDER = "build-pip"


def project_version() -> str:
    """The one version of the project: project(clearjoint VERSION x.y.z) in CMakeLists.txt."""
    match = re.search(r"project\(clearjoint VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if match is None:
        raise RuntimeError("CMakeLists.txt: no project(clearjoint VERSION ...) line")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self) -> None:
        super().__init__("clearjoint._core", sources=[])


class CMakeBuild(build_ext):
    """Configure the repository with CMake for this interpreter, build the module, copy it in."""

    def build_extension(self, ext: Extension) -> None:
        destination = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                        "-DCMAKE_BUILD_TYPE=Release",
                        f"-DPython3_EXECUTABLE={sys.executable}",
                        "-DCLEARJOINT_BUILD_PYTHON=ON",
                        "-DCLEARJOINT_BUILD_TESTS=OFF",
                        "-DCLEARJOINT_BUILD_BENCHMARKS=OFF",
                        "-DCLEARJOINT_BUILD_APPS=OFF",
                        # Nor what the module does not link: the other bindings, the engines.
                        "-DCLEARJOINT_BUILD_MATLAB=OFF",
                        "-DCLEARJOINT_BUILD_FORTRAN=OFF",
                        "-DCLEARJOINT_WITH_SIMBODY=OFF",
                        "-DCLEARJOINT_WITH_MUJOCO=OFF",
                        "-DBUILD_SHARED_LIBS=OFF",
                        "-DCMAKE_POSITION_INDEPENDENT_CODE=ON"], check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "clearjoint_python_core",
                        "--parallel", jobs], check=True)
        built = build_dir / "bindings" / "python" / "clearjoint" / destination.name
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, destination)


class BuildPy(build_py):
    """The Python files, and the study schema, which lives in docs/schema/, beside the study
    runner (as apps/python/study.cmake puts it)."""

    def run(self) -> None:
        super().run()
        study = pathlib.Path(self.build_lib) / "clearjoint" / "study"
        study.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(ROOT / "docs" / "schema" / "study-v1.schema.json", study / "study-v1.schema.json")


# The package is assembled, as bindings/python/CMakeLists.txt does, from the binding
# (bindings/python/clearjoint) and the applications built on it, each a subpackage whose sources
# live in the applications' wing (apps/python/<name>: clearjoint.study, .plot, .view).
APPLICATIONS = ("study", "plot", "view")


def package_names() -> list:
    """Every package and subpackage, namespace ones too: the viewer's web/ folders hold data only
    (setuptools' advice)."""
    names = find_namespace_packages(where="bindings/python", include=["clearjoint", "clearjoint.*"],
                                    exclude=["*.__pycache__"])
    for application in APPLICATIONS:
        names += ["clearjoint." + name for name in
                  find_namespace_packages(where="apps/python", include=[application, application + ".*"],
                                          exclude=["*.__pycache__"])]
    return names


# Name, description and dependencies: pyproject.toml. The packages are said here, not in its
# [tool.setuptools] table, which Debian 12's setuptools 66 still calls a beta.
setup(
    version=project_version(),
    packages=package_names(),
    # A subpackage's subfolders (view.web, view.web.vendor) follow their parent's entry.
    package_dir={"": "bindings/python",
                 **{"clearjoint." + application: "apps/python/" + application for application in APPLICATIONS}},
    package_data={"clearjoint": ["py.typed", "__init__.pyi"],
                  "clearjoint.view.web": ["*.html", "*.js", "*.css"],
                  "clearjoint.view.web.vendor": ["*.js", "*.txt"]},
    zip_safe=False,
    ext_modules=[CMakeExtension()],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildPy},
    # Beside, not inside, the CMake build tree the README uses (build/).
    options={"build": {"build_base": PIP_BUILD_FOLDER}},
)
