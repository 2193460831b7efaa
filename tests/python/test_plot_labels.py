# SPDX-License-Identifier: BSD-3-Clause
"""The figures and the viewer name contact slots and scenarios from the library's enum tables
(clearjoint._enums, built from _core's rows), never from lists of their own: a value planted in
the tables reaches them with no other edit."""
import importlib
import pathlib
import re

import numpy as np
import pytest

import clearjoint
from clearjoint import _core, _enums

APPLICATIONS = pathlib.Path(__file__).resolve().parents[2] / "apps" / "python"
PLANTED_SCENARIO = ("planted_scenario", 99, "(z) planted")
PLANTED_SLOT = ("planted_slot", 99, "planted")


@pytest.fixture
def planted_tables(monkeypatch):
    """clearjoint._enums, the contact slots of clearjoint.plot and its scenario table rebuilt from
    tables holding one more scenario and one more slot; restored afterwards."""
    real = _core._enum_tables()

    def with_planted():
        extra = {"ContactScenario": PLANTED_SCENARIO, "ContactSlot": PLANTED_SLOT}
        return [(name, doc, list(members) + ([extra[name]] if name in extra else []))
                for name, doc, members in real]

    monkeypatch.setattr(_core, "_enum_tables", with_planted)
    importlib.reload(_enums)
    joint_series = importlib.reload(importlib.import_module("clearjoint.plot.joint_series"))
    yield joint_series
    monkeypatch.undo()
    importlib.reload(_enums)
    importlib.reload(joint_series)


def test_a_contact_slot_planted_in_the_table_is_read_by_the_joint_series(planted_tables):
    assert planted_tables.CONTACT_SLOTS[-1] == PLANTED_SLOT[0]
    assert set(planted_tables.CONTACT_SLOTS) == {s.name for s in clearjoint._enums.ContactSlot}


def test_an_impact_in_a_planted_slot_alone_is_found(planted_tables):
    from clearjoint.plot.run_folder import Run

    time = np.array([0.0, 1e-3, 2e-3])
    columns = {"time": time, "scenario": np.zeros(3), "axis_angle": np.zeros(3),
               **{f"rim_{rim}_{c}": np.zeros(3) for rim in "ab" for c in ("u", "v", "axial")},
               f"{PLANTED_SLOT[0]}.depth": np.array([np.nan, 1e-6, 1e-6]),
               f"{PLANTED_SLOT[0]}.normal_force": np.array([0.0, 5.0, 7.0])}

    series = planted_tables.joint_series(Run(tables={"force_joint": columns}), "force_joint")
    assert list(series.impact_rows) == [1]
    assert list(series.normal_force) == [0.0, 5.0, 7.0]


def test_a_scenario_planted_in_the_table_is_in_the_viewers_legend(planted_tables):
    from clearjoint.plot.scenario_colours import UNKNOWN_SCENARIO_COLOUR, scenario_table
    legend = {entry["code"]: entry for entry in scenario_table()}
    assert sorted(legend) == sorted(int(s) for s in clearjoint._enums.ContactScenario)
    # A scenario no colour was chosen for shows in the warning colour (test_plot.py requires a
    # colour of its own for each of the library's scenarios).
    assert legend[PLANTED_SCENARIO[1]]["colour"] == UNKNOWN_SCENARIO_COLOUR


def test_the_plot_and_view_sources_spell_no_contact_slot():
    slots = [slot.name for slot in clearjoint._enums.ContactSlot]
    spelt = [(path.name, slot) for path in sorted(APPLICATIONS.glob("*/*.py")) for slot in slots
             if re.search(r"""["']%s[."']""" % re.escape(slot), path.read_text())]
    assert spelt == []
