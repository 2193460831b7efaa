# SPDX-License-Identifier: BSD-3-Clause
"""`pip install .`: the clearjoint Python package, its compiled core built by CMake.

A small setuptools command rather than scikit-build: Debian 12 ships scikit-build 0.16
(python3-skbuild, not installed by default), the classic line that scikit-build-core has replaced,
and either needs the same CMake call as below; this file is that call and nothing else. There is
no pyproject.toml on purpose: with one, pip builds in an isolated environment and downloads
setuptools from PyPI, which a machine with only Debian's packages cannot do. Without it, pip
uses the setuptools already installed (python3-setuptools, or the copy in a virtual environment).

The extension is linked against static, position-independent copies of the clearjoint libraries,
so the installed package does not depend on a `cmake --install` of the C++ libraries. docs/python.md
gives the commands (a virtual environment with --system-site-packages for Debian's NumPy).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = pathlib.Path(__file__).resolve().parent


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
                        "-DBUILD_SHARED_LIBS=OFF",
                        "-DCMAKE_POSITION_INDEPENDENT_CODE=ON"], check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "clearjoint_python_core",
                        "--parallel", jobs], check=True)
        built = build_dir / "bindings" / "python" / "clearjoint" / destination.name
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, destination)


class BuildPy(build_py):
    """The Python files, and the study schema, which lives in docs/schema/, beside the study
    runner (as bindings/python/study.cmake puts it)."""

    def run(self) -> None:
        super().run()
        study = pathlib.Path(self.build_lib) / "clearjoint" / "study"
        study.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(ROOT / "docs" / "schema" / "study-v1.schema.json", study / "study-v1.schema.json")


setup(
    name="clearjoint",
    version=project_version(),
    description="Certified contact detection for spatial revolute joints with clearance",
    license="BSD-3-Clause",
    packages=["clearjoint", "clearjoint.study"],
    package_dir={"clearjoint": "bindings/python/clearjoint"},
    package_data={"clearjoint": ["py.typed", "__init__.pyi"]},
    ext_modules=[CMakeExtension()],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildPy},
    python_requires=">=3.8",
    install_requires=["numpy"],
    zip_safe=False,
    # Beside, not inside, the CMake build tree the README uses (build/).
    options={"build": {"build_base": "build/setuptools"}},
)
