# SPDX-License-Identifier: BSD-3-Clause
"""The `clearjoint` command a pip install puts on PATH (clearjoint/__main__.py, declared in
pyproject.toml): plot, view and study run from the package; the C++ program's subcommands go to
the program when there is one and are refused with a clear line when there is none. The
installed command itself is checked by tests/package (python_smoke.py)."""
import os
import pathlib
import subprocess
import sys
import tomllib

import clearjoint

ROOT = pathlib.Path(__file__).resolve().parents[2]


def command(*args, path=None, **env):
    environment = dict(os.environ, PATH=path if path is not None else "/usr/bin:/bin", **env)
    if "CLEARJOINT_PROGRAM" not in env:
        environment.pop("CLEARJOINT_PROGRAM", None)
    return subprocess.run([sys.executable, "-m", "clearjoint", *args], capture_output=True, text=True,
                          env=environment, timeout=120)


def test_pyproject_installs_a_clearjoint_command_running_the_packages_main():
    with open(ROOT / "pyproject.toml", "rb") as f:
        scripts = tomllib.load(f)["project"]["scripts"]
    module, _, function = scripts["clearjoint"].partition(":")
    assert (module, function) == ("clearjoint.__main__", "main")


def test_setup_py_builds_beside_the_readmes_build_folder_not_inside_it():
    text = (ROOT / "setup.py").read_text()
    folder = next(line.split("=")[1].strip().strip('"') for line in text.splitlines()
                  if line.startswith("PIP_BUILD_FOLDER ="))
    assert pathlib.PurePosixPath(folder).parts[0] != "build", folder
    assert '"build_base": PIP_BUILD_FOLDER' in text


def test_the_command_runs_study_plot_and_view_from_the_package():
    for sub in ("study", "plot", "view"):
        done = command(sub, "--help")
        assert done.returncode == 0 and "usage: clearjoint %s" % sub in done.stdout, done
    done = command("--version")
    assert done.returncode == 0 and clearjoint.__version__ in done.stdout, done


def test_a_subcommand_of_the_cpp_program_without_the_program_is_one_line_saying_how_to_get_it(tmp_path):
    done = command("simulate", "model.json", path=str(tmp_path))
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done
    assert "simulate is a command of the C++ program `clearjoint`, which pip does not install" in done.stderr


def test_a_subcommand_of_the_cpp_program_is_handed_to_the_program_on_path_not_to_a_script(tmp_path):
    scripts, programs = tmp_path / "scripts", tmp_path / "programs"
    scripts.mkdir()
    programs.mkdir()
    (scripts / "clearjoint").write_text("#!/bin/sh\necho script\n")  # a console script like pip's
    (scripts / "clearjoint").chmod(0o755)
    # A stand-in for the C++ program: a copy of a binary that prints its arguments.
    printf = programs / "clearjoint"
    printf.write_bytes(pathlib.Path("/bin/echo").read_bytes())
    printf.chmod(0o755)
    done = command("detect", "--pose", "1", path="%s:%s" % (scripts, programs))
    assert done.returncode == 0 and done.stdout == "detect --pose 1\n", done


def test_an_unknown_subcommand_is_named_with_the_list_of_commands():
    done = command("simulat")
    assert done.returncode == 2 and "unknown command 'simulat'" in done.stderr and "study" in done.stderr, done
