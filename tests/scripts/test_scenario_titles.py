# SPDX-License-Identifier: BSD-3-Clause
"""The scenario pictures of the docs (scripts/plot_scenarios.py) and the reproduction's scenario
counts (reproduction/section6_figures.py) name each scenario by the library's label, read from
its enum table, never in words of their own: a scenario planted in the table gets its title from
it, and no scenario label is written out in either script."""
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))

import plot_scenarios  # noqa: E402 (from scripts/)

# The program printing the enum tables, given by ctest (tests/CMakeLists.txt).
DESCRIBE = os.environ.get("CLEARJOINT_DESCRIBE_TABLES")
# A scenario's label as the tables write them: its Fig. 2 letter in parentheses, "(a) ...".
SPELT_LABEL = re.compile(r"""["']\([a-z]\)""")


@pytest.fixture(scope="module")
def tables():
    if not DESCRIBE:
        pytest.fail("CLEARJOINT_DESCRIBE_TABLES is not set: run through ctest")
    return json.loads(subprocess.run([DESCRIBE], capture_output=True, text=True, check=True).stdout)


def scenario_table(tables):
    return next(t for t in tables["enums"] if t["type"] == "ContactScenario")


def test_every_pictured_scenario_is_titled_with_its_label_from_the_table(tables):
    titles = plot_scenarios.scenario_titles(tables)
    assert titles == {e["key"]: e["label"] for e in scenario_table(tables)["entries"]}
    pictured = [json.loads(line)["id"] for line in (ROOT / "examples" / "scenarios.jsonl").read_text().splitlines()
                if line.strip()]
    assert pictured and set(pictured) <= set(titles)


def test_every_pictured_pin_in_hole_scenario_is_titled_from_the_pin_in_hole_table(tables):
    table = next(t for t in tables["enums"] if t["type"] == "PinInHoleScenario")
    titles = plot_scenarios.scenario_titles(tables, plot_scenarios.SCENARIO_TABLES["pin_in_hole"])
    assert titles == {e["key"]: e["label"] for e in table["entries"]}
    lines = [json.loads(line) for line in (ROOT / "examples" / "pin_in_hole_scenarios.jsonl").read_text().splitlines()
             if line.strip()]
    # One picture per scenario of the table, each line's id "pin-<key>".
    assert sorted(line["id"] for line in lines) == sorted(f"pin-{key}" for key in titles)
    assert all(line["joint"] == "pin_in_hole" for line in lines)


def test_a_scenario_planted_in_the_table_is_titled_from_it(tables):
    scenario_table(tables)["entries"].append({"code": 99, "key": "z", "label": "(z) planted", "name": "planted"})
    assert plot_scenarios.scenario_titles(tables)["z"] == "(z) planted"


@pytest.mark.parametrize("script", ["scripts/plot_scenarios.py", "reproduction/section6_figures.py"])
def test_the_script_writes_out_no_scenario_label(script):
    assert SPELT_LABEL.findall((ROOT / script).read_text()) == []
