# SPDX-License-Identifier: BSD-3-Clause
"""The paper's reproduction in its own wing (reproduction/): the studies it runs resolve their
models, schema and stores from there, and the only figures committed are those a page shows (the
command draws every figure into results/section6/figures and copies those into docs/figures)."""
import json
import os
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
REPRODUCTION = ROOT / "reproduction"
sys.path.insert(0, str(REPRODUCTION))

import reproduce_section6  # noqa: E402 (from the wing above)


def pages_text():
    pages = [ROOT / "README.md"] + sorted((ROOT / "docs").rglob("*.md"))
    return "".join(page.read_text(encoding="utf-8") for page in pages)


def test_the_committed_section_6_figures_are_exactly_those_the_docs_show():
    committed = sorted(os.listdir(reproduce_section6.DOCS_FIGURES))
    assert committed == reproduce_section6.figures_the_docs_show()


def test_every_committed_figure_is_shown_by_a_page():
    text = pages_text()
    unshown = [str(figure.relative_to(ROOT)) for figure in sorted((ROOT / "docs" / "figures").rglob("*.png"))
               if str(figure.relative_to(ROOT / "docs")) not in text]
    assert unshown == []


def test_every_study_of_the_reproduction_finds_its_schema_and_models_and_stores_under_results():
    studies = sorted((REPRODUCTION / "studies").glob("*.json"))
    assert [study.name for study in studies] == sorted(reproduce_section6.STUDY_FILES)
    for study in studies:
        fields = json.loads(study.read_text())
        models = [fields["model"]] + [design["model"] for design in fields.get("designs", []) if "model" in design]
        for relative in [fields["$schema"]] + models:
            assert (study.parent / relative).resolve().is_file(), (study.name, relative)
        store = (study.parent / fields["store"]).resolve()
        assert store.parent == ROOT / "results", (study.name, fields["store"])


def test_the_developer_scripts_hold_no_section_6_script():
    assert [path.name for path in (ROOT / "scripts").iterdir() if "section6" in path.name] == []
