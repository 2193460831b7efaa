# SPDX-License-Identifier: BSD-3-Clause
"""The package as a whole: docs/python.md's code runs as written, every public name is documented
and typed in the stub, and the version is the library's."""
import ast
import os
import pathlib
import re
import subprocess
import sys

import clearjoint

ROOT = pathlib.Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "python.md"
STUB = pathlib.Path(clearjoint.__file__).with_name("__init__.pyi")


def python_blocks(text):
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_the_guides_code_runs_as_written_and_draws_its_figure(tmp_path):
    # Run every block in order, as a reader would, from a directory laid out like the repository
    # (models/, docs/figures/) so that the figure is written there and not into the source tree.
    (tmp_path / "docs" / "figures").mkdir(parents=True)
    (tmp_path / "models").symlink_to(ROOT / "models")
    script = tmp_path / "guide.py"
    script.write_text("\n".join(python_blocks(GUIDE.read_text())))
    run = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True,
                         text=True, env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    assert (tmp_path / "docs" / "figures" / "python-scenario-map.png").stat().st_size > 10_000
    # Twelve scenarios: all but (c) and (d), which need other clearances than Table 2's.
    assert run.stdout.strip().splitlines()[-1] == (
        "271803 poses, scenarios found: none, (a) single radial, (b) single axial, "
        "(e) radial and axial at the same base, (f) radial and axial at opposite bases, "
        "(g) two radial, one axial, (h) one radial, two axial, (i) all four, (j) line, (k) face, "
        "(l) line and face, beyond model")


def test_the_guides_figure_is_in_the_repository():
    assert (ROOT / "docs" / "figures" / "python-scenario-map.png").is_file()


def test_every_public_name_has_a_docstring():
    for name in clearjoint.__all__:
        if name.startswith("__") or name == "MAX_CONTACTS":
            continue
        doc = getattr(clearjoint, name).__doc__
        assert doc and len(doc.strip()) > 20, name


def test_every_public_name_is_in_the_type_stub():
    tree = ast.parse(STUB.read_text())
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            stubbed.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            stubbed.add(node.target.id)
    assert set(clearjoint.__all__) <= stubbed, set(clearjoint.__all__) - stubbed


def test_the_type_stubs_enums_have_the_members_and_codes_of_the_package():
    tree = ast.parse(STUB.read_text())
    stubbed = {node.name: {item.targets[0].id: item.value.value for item in node.body
                           if isinstance(item, ast.Assign)}
               for node in tree.body if isinstance(node, ast.ClassDef)
               and any(getattr(base, "attr", None) == "IntEnum" for base in node.bases)}
    assert stubbed, "no IntEnum in the stub"
    for name, members in stubbed.items():
        assert members == {m.name: int(m) for m in getattr(clearjoint, name)}, name


def test_every_public_method_of_a_class_is_in_the_type_stub():
    tree = ast.parse(STUB.read_text())
    methods = {node.name: {item.name for item in node.body if isinstance(item, ast.FunctionDef)}
               for node in tree.body if isinstance(node, ast.ClassDef)}
    for name in ("DetectionBatch", "JointContacts", "Contact", "CirclePlaneIntersection"):
        cls = getattr(clearjoint, name)
        public = {m for m in vars(cls) if not m.startswith("_") and callable(getattr(cls, m))}
        inherited = methods.get("ArrayResult", set()) if name == "DetectionBatch" else set()
        assert public <= methods[name] | inherited, (name, public - methods[name] - inherited)


def test_every_property_of_the_stubs_result_classes_is_an_attribute_of_the_class():
    # The stub's result classes are generated from the C++ field lists (scripts/projections), so a
    # field added to a result is a property here; the class must have it, which the bindings that
    # loop over the field lists give (bindings/python/src/result_attributes.hpp) and a binding
    # written by hand forgets.
    tree = ast.parse(STUB.read_text())
    checked = 0
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        properties = [item.name for item in node.body if isinstance(item, ast.FunctionDef)
                      and any(getattr(d, "id", None) == "property" for d in item.decorator_list)]
        cls = getattr(clearjoint, node.name, None)
        for name in properties:
            assert cls is not None and isinstance(getattr(cls, name, None), property), \
                f"{node.name}.{name} is in the stub but not an attribute of clearjoint.{node.name}"
            checked += 1
    # 51 properties when this test was written, 41 of them the fields and extras of the seven
    # results: a stub that lost its result classes would check nothing.
    assert checked >= 41, checked


def test_the_version_is_the_projects():
    cmake = (ROOT / "CMakeLists.txt").read_text()
    assert clearjoint.__version__ == re.search(r"project\(clearjoint VERSION ([0-9.]+)", cmake).group(1)
