# SPDX-License-Identifier: BSD-3-Clause
"""docs/tutorial.md runs as written: its Python files and its commands, in order, in a scratch
folder, each command printing what the page shows, and the comparison figure drawn with its
panels and legend.

Blocks read from the page: a ```python block whose first line is ``# NAME.py: ...`` is written to
NAME.py; a ```console block holds commands (``$ `` lines, continued after a trailing backslash)
each followed by its output as shown. ``clearjoint`` is the program of this build (its folder put
first on PATH) and ``/usr/bin/python3`` this interpreter; the package is the build tree's
(PYTHONPATH, set by ctest). The commands run as the page gives them, --end-time included: the
tutorial's runs are short enough for the test (a few seconds each).

Shown output against the run's (standard output and standard error together, as a terminal shows
them): a line ``…`` stands for any number of lines left out, a ``…`` inside a line for any text;
the words must be the same and each number within OUTPUT_RELATIVE_TOLERANCE of the run's.
"""
import math
import os
import pathlib
import re
import subprocess
import sys

import pytest

import clearjoint
from clearjoint import plot

ROOT = pathlib.Path(__file__).resolve().parents[2]
TUTORIAL = ROOT / "docs" / "tutorial.md"

#: The page shows numbers as one build printed them. Another compiler, or a change of the
#: integrator's arithmetic that leaves the mechanism's behaviour alone, moves the step and
#: evaluation counts by a few parts in a thousand (the dry four-bar's counts move by 0.3 % when
#: its tolerance moves by 0.1 %); a number off by more than this means the page no longer says
#: what the program does, and its runs are to be redone.
OUTPUT_RELATIVE_TOLERANCE = 0.05

ELISION = "…"
NUMBER = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"
PYTHON_FILE = re.compile(r"# (\w+\.py): ")

# What the figure must hold: the runs compared and its panels' y labels, top to bottom.
RUNS = {"dry": "dry", "lubricated": "lubricated", "dry, Simbody": "dry-simbody",
        "lubricated, Simbody": "lubricated-simbody"}
PANELS = ["v / c_r [-]", "joint force |F| [N]", "film force [N]", "h_min [µm]",
          "eccentricity ratio ε [-]", "peak pressure [MPa]", "total energy [J]"]


def tutorial_steps(text):
    """[("file", name, code) | ("command", command, [expected lines])] in the page's order."""
    steps = []
    for kind, body in re.findall(r"```(python|console)\n(.*?)```", text, flags=re.S):
        if kind == "python":
            first = body.splitlines()[0]
            named = PYTHON_FILE.match(first)
            assert named, f"a python block of the tutorial does not start with '# NAME.py: ': {first!r}"
            steps.append(("file", named.group(1), body))
            continue
        lines = body.splitlines()
        k = 0
        while k < len(lines):
            assert lines[k].startswith("$ "), f"console block: {lines[k]!r} is neither a command nor its output"
            command = lines[k][2:]
            while command.endswith("\\"):
                k += 1
                command = command[:-1] + lines[k].strip()
            k += 1
            expected = []
            while k < len(lines) and not lines[k].startswith("$ "):
                expected.append(lines[k])
                k += 1
            steps.append(("command", command, expected))
    return steps


def line_pattern(expected):
    """A regular expression for one shown line: its text as is, numbers and elisions open."""
    parts = []
    for segment in expected.split(ELISION):
        pieces = re.split(f"({NUMBER})", segment)
        parts.append("".join(f"({NUMBER})" if k % 2 else re.escape(piece) for k, piece in enumerate(pieces)))
    return re.compile(".*?".join(parts) + "$")


def numbers_of(expected):
    return [float(n) for segment in expected.split(ELISION) for n in re.findall(NUMBER, segment)]


def mismatch(expected, actual):
    """None when ``actual`` is ``expected`` up to elisions and the number tolerance, else why not."""
    found = line_pattern(expected).match(actual)
    if not found:
        return f"text differs:\n  shown: {expected}\n  run:   {actual}"
    for shown, ran in zip(numbers_of(expected), (float(g) for g in found.groups())):
        if not math.isclose(shown, ran, rel_tol=OUTPUT_RELATIVE_TOLERANCE):
            return f"{shown:g} shown, {ran:g} in the run:\n  shown: {expected}\n  run:   {actual}"
    return None


def check_output(command, expected, actual):
    """The shown lines against the run's, in order; ``…`` lines skip any number of the run's."""
    k = 0
    skipping = False
    for line in expected:
        if line == ELISION:
            skipping = True
            continue
        if skipping:
            start = k
            while k < len(actual) and mismatch(line, actual[k]) is not None:
                k += 1
            if k == len(actual):  # the line with the same words, when there is one, says which number
                near = [p for p in (mismatch(line, a) for a in actual[start:]) if not p.startswith("text")]
                pytest.fail(f"$ {command}\nshown line not in the output: {line}\n"
                            + (near[0] if near else "output:\n" + "\n".join(actual)))
        else:
            assert k < len(actual), f"$ {command}\nshown line missing at the end: {line}\noutput:\n" + "\n".join(actual)
            problem = mismatch(line, actual[k])
            assert problem is None, f"$ {command}\n{problem}"
        k += 1
        skipping = False
    if not skipping:
        assert k == len(actual), f"$ {command}\nlines the page does not show:\n" + "\n".join(actual[k:])


def test_the_output_check_reads_numbers_elisions_and_tolerance():
    assert mismatch("simulated 0 s to 0.25 s: 11569 steps, …", "simulated 0 s to 0.25 s: 11600 steps, x") is None
    assert "shown" in mismatch("simulated 0 s to 0.25 s: 11569 steps", "simulated 0 s to 0.25 s: 13000 steps")
    assert "text differs" in mismatch("36 impacts recorded", "36 impact recorded")
    check_output("c", ["a 1", ELISION, "d 4"], ["a 1", "b 2", "c 3", "d 4"])
    with pytest.raises(AssertionError, match="does not show"):
        check_output("c", ["a 1"], ["a 1", "b 2"])


@pytest.fixture(scope="module")
def tutorial_run(tmp_path_factory, cli):
    """The page's steps run in order in a scratch folder; the folder."""
    folder = tmp_path_factory.mktemp("tutorial")
    environment = dict(os.environ, PATH=f"{pathlib.Path(cli).parent}{os.pathsep}{os.environ['PATH']}")
    steps = tutorial_steps(TUTORIAL.read_text())
    assert [s[1] for s in steps if s[0] == "file"] == ["four_bar.py", "lubricated_simbody.py",
                                                       "compare_runs.py", "thin_oil.py"]
    for kind, name, content in steps:
        if kind == "file":
            (folder / name).write_text(content)
            continue
        command = re.sub(r"^/usr/bin/python3 ", f"{sys.executable} ", name)
        run = subprocess.run(["bash", "-c", command], cwd=folder, env=environment, text=True,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        assert run.returncode == 0, f"$ {name}\nexit status {run.returncode}:\n{run.stdout}"
        check_output(name, content, run.stdout.splitlines())
    return folder


def test_the_tutorials_commands_print_what_the_page_shows(tutorial_run):
    for name in ["four_bar_dry.json", "four_bar_lubricated.json", "four_bar.png", "four_bar.pdf"]:
        assert (tutorial_run / name).is_file(), name
    for folder in list(RUNS.values()) + ["thin-oil"]:
        assert (tutorial_run / folder / "summary.json").is_file(), folder


def test_the_tutorials_figure_has_its_panels_a_legend_entry_per_run_and_curves_in_every_panel(tutorial_run):
    png = (tutorial_run / "four_bar.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 50_000
    comparison = plot.compare([tutorial_run / f for f in RUNS.values()], labels=list(RUNS))
    axes = comparison.figure.axes
    assert [a.get_ylabel() for a in axes] == PANELS
    assert [t.get_text() for t in axes[0].get_legend().get_texts()] == list(RUNS)
    for a in axes:
        drawn = [line for line in a.get_lines() if sum(map(math.isfinite, line.get_ydata())) > 10]
        assert drawn, f"panel {a.get_ylabel()!r} has no curve"
    # Both engines' runs of each model on every time panel that applies: 4 curves of |F| and
    # energy, 2 (the lubricated runs) of each film panel.
    counts = [len(a.get_lines()) for a in axes[1:]]
    assert counts == [4, 2, 2, 2, 2, 4]


def test_the_tutorials_models_are_the_builders_and_load_back_equal(tutorial_run):
    for name in ["four_bar_dry.json", "four_bar_lubricated.json"]:
        model = clearjoint.Model.load(tutorial_run / name)
        assert model == clearjoint.Model.from_dict(model.to_dict())
    lubricated = clearjoint.Model.load(tutorial_run / "four_bar_lubricated.json").to_dict()
    assert lubricated["forces"][0]["lubrication"]["viscosity"] == 0.04
    assert "lubrication" not in clearjoint.Model.load(tutorial_run / "four_bar_dry.json").to_dict()["forces"][0]
