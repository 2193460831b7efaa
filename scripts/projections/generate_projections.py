#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the projections of the library's enum tables and result field lists into the files that
a consumer reads without a build: the C header's enums and result structs' members, the Fortran
module's constants and BIND(C) types' components, the Python stubs' enums and result classes, the
JSON schemas' enum lists.

The descriptions come from describe_projections (a program built from the C++ tables, which prints
them as JSON). Each projection replaces the lines between a "BEGIN GENERATED <name>" and an
"END GENERATED <name>" marker (a schema: the "enum" lists named below). Adding a value to an enum
or a field to a result is one edit in C++; then

    cmake --build build --target projections

rewrites the files, and the test projections.up_to_date (this script with --check) fails while a
checked-in copy differs from what the tables give.

What this script itself says, and the tables cannot: the C name and constant prefix of each enum
the C API declares, which schema lists which enum, and the Python attributes of result classes
that are not fields (a certificate's reason_text, an arc's middle); c_structs.py says the C layout
the ABI freezes.
"""
import argparse
import difflib
import json
import pathlib
import subprocess
import sys
import textwrap

from c_copies import MEMBERS_FILE, member_tables
from c_structs import struct_projections
from equivalence_lines import CONTACT_LINE_FILE, FORTRAN_CONTACT_LINE_FILE, writer_lines
from mex_results import MEX_FILE, mex_lines
import schema_results

# The enums of the C API, in the header's order: C++ type, C type, constant prefix, comment.
C_ENUMS = [
    ("ContactScenario", "cj_scenario", "CJ_SCENARIO_",
     "The contact scenarios of the paper's Fig. 2, plus free flight and \"beyond the model\" "
     "(C++: ContactScenario)."),
    ("Certainty", "cj_certainty", "CJ_CERTAINTY_", "Trust in an answer, strongest first (C++: Certainty)."),
    ("CertificateReason", "cj_reason", "CJ_REASON_",
     "Why an answer is `uncertain`, or for an `exact` one why the floating-point tiers did not "
     "decide it; CJ_REASON_NONE for certified answers (C++: CertificateReason). `reason_text` and "
     "cj_reason_string() give the sentence."),
    ("ContactType", "cj_contact_type", "CJ_CONTACT_", "What a contact is against (C++: ContactType)."),
    ("ContactBase", "cj_base", "CJ_BASE_", "Where a contact is (C++: ContactBase)."),
    ("CirclePlaneTopology", "cj_circle_plane_topology", "CJ_CIRCLE_PLANE_",
     "How a circle meets a plane (C++: CirclePlaneTopology)."),
    ("CircleCylinderTopology", "cj_circle_cylinder_topology", "CJ_CIRCLE_CYLINDER_",
     "How a circle meets a cylinder's lateral surface (C++: CircleCylinderTopology)."),
    ("PinInHoleScenario", "cj_pin_in_hole_scenario", "CJ_PIN_IN_HOLE_",
     "The contact scenarios of the pin-in-hole joint (C++: PinInHoleScenario; "
     "docs/contact-detection.md, \"The pin-in-hole joint\")."),
]

# The "enum" lists of the JSON schemas: file, path to the object holding the list, enum type.
SCHEMA_ENUMS = [
    ("docs/schema/detect-answer.schema.json", ["$defs", "certainty"], "Certainty"),
    ("docs/schema/detect-answer.schema.json", ["$defs", "contact", "properties", "type"], "ContactType"),
    ("docs/schema/detect-answer.schema.json", ["$defs", "contact", "properties", "base"], "ContactBase"),
    ("docs/schema/detect-answer.schema.json", ["$defs", "answer", "properties", "scenario"], "ContactScenario"),
    ("docs/schema/intersect-answer.schema.json", ["$defs", "certainty"], "Certainty"),
    ("docs/schema/intersect-answer.schema.json", ["$defs", "plane_answer", "properties", "topology"],
     "CirclePlaneTopology"),
    ("docs/schema/intersect-answer.schema.json", ["$defs", "cylinder_answer", "properties", "topology"],
     "CircleCylinderTopology"),
    ("docs/schema/model.schema.json", ["$defs", "joint", "properties", "type"], "JointType"),
    ("docs/schema/model.schema.json",
     ["$defs", "force", "oneOf", 2, "properties", "normal_force", "properties", "model"], "NormalForceModel"),
    ("docs/schema/model.schema.json",
     ["$defs", "force", "oneOf", 2, "properties", "lubrication", "properties", "cavitation"], "CavitationModel"),
    ("docs/schema/model.schema.json",
     ["$defs", "force", "oneOf", 2, "properties", "lubrication", "properties", "method"], "BearingMethod"),
]

# Attributes of Python's result classes that are not fields of the C++ result (bound by hand in
# bindings/python/src): name and type.
PY_EXTRAS = {
    "Certificate": [("reason_text", "str")],
    "RimArc": [("middle", "float"), ("sweep", "float")],
    "JointContacts": [("contact_count", "int")],
    "PinInHoleContacts": [("contact_count", "int")],
    "CircleCylinderIntersection": [("root_count", "int")],
}
PY_TYPES = {"float": "float", "int": "int", "bool": "bool", "vector3": "npt.NDArray[np.float64]",
            "plane_side": "int"}

C_HEADER = "bindings/c/include/clearjoint/clearjoint.h"
FORTRAN_MODULE = "bindings/fortran/clearjoint.f90"
PY_STUB = "bindings/python/clearjoint/__init__.pyi"
DETECT_HELP = "apps/clearjoint/detect_command.cpp"
REGENERATE = "cmake --build build --target projections"


def c_enums(tables):
    lines = []
    for type_name, c_name, prefix, comment in C_ENUMS:
        entries = tables[type_name]["entries"]
        lines += ["/** " + line[3:] if i == 0 else " * " + line[3:]
                  for i, line in enumerate(textwrap.wrap(comment, 97, initial_indent="   ",
                                                         subsequent_indent="   "))]
        lines[-1] += " */"
        lines.append(f"typedef enum {c_name} {{")
        for i, entry in enumerate(entries):
            separator = "," if i + 1 < len(entries) else ""
            constant = f"  {prefix}{entry['name'].upper()} = {entry['code']}{separator}"
            label = entry["label"]
            if label and len(constant) + len(label) + 7 <= 100:
                constant += f" /**< {label} */"
            elif label:  # too long for the constant's line: a comment of its own above it
                wrapped = textwrap.wrap(label, 92)
                lines += ["  /** " + wrapped[0]] + ["   * " + text for text in wrapped[1:]]
                lines[-1] += " */"
            lines.append(constant)
        lines.append(f"}} {c_name};")
        lines.append("")
    return lines[:-1]


def fortran_constants(tables):
    lines = []
    for type_name, c_name, prefix, _ in C_ENUMS:
        lines.append(f"  ! {c_name} (C++: {type_name})")
        items = [f"{prefix}{e['name'].upper()} = {e['code']}" for e in tables[type_name]["entries"]]
        line = "  integer(c_int32_t), parameter, public :: "
        for i, item in enumerate(items):
            text = item + (", " if i + 1 < len(items) else "")
            if len(line) + len(text.rstrip()) > 99:
                lines.append(line.rstrip() + " &")
                line = "    "
            line += text
        lines.append(line.rstrip())
    return lines


def py_type(field):
    value = PY_TYPES.get(field["value"], field["value"])
    if field["kind"] == "list":
        return f"List[{value}]"
    if field["kind"] == "optional":
        return f"Optional[{value}]"
    return value


def py_enums(tables):
    lines = []
    for table in tables.values():
        if table["module"] != "geometry":  # the enums the package shows (bindings/python/src/enum_codes.cpp)
            continue
        lines.append(f"class {table['type']}(enum.IntEnum):")
        lines += [f"    {e['name']} = {e['code']}" for e in table["entries"]]
        lines.append("")
    return lines[:-1]


def py_results(results):
    lines = []
    for result in results:
        lines.append(f"class {result['type']}:")
        attributes = [(f["key"], py_type(f)) for f in result["fields"]] + PY_EXTRAS.get(result["type"], [])
        for name, type_text in attributes:
            lines += ["    @property", f"    def {name}(self) -> {type_text}: ..."]
        lines += ["    def as_dict(self) -> Dict[str, Any]: ...", ""]
    return lines[:-1]


def replace_region(text, name, lines, path):
    source = text.split("\n")
    begin = [i for i, line in enumerate(source) if f"BEGIN GENERATED {name}" in line]
    end = [i for i, line in enumerate(source) if f"END GENERATED {name}" in line]
    if len(begin) != 1 or len(end) != 1 or end[0] < begin[0]:
        raise SystemExit(f"{path}: needs one 'BEGIN GENERATED {name}' line and one 'END GENERATED {name}' "
                         "line after it")
    return "\n".join(source[:begin[0] + 1] + lines + source[end[0]:])


def schema_text(text, path, targets, tables, results):
    schema = json.loads(text)
    schema_results.apply(schema, path, results, tables)
    for _, keys, type_name in targets:
        node = schema
        for key in keys:
            node = node[key]
        if "enum" not in node:
            raise SystemExit(f"{path}: {'/'.join(map(str, keys))} has no enum list")
        node["enum"] = [e["key"] for e in tables[type_name]["entries"]]
    return json.dumps(schema, indent=2) + "\n"


def projections(root, description):
    tables = {table["type"]: table for table in description["enums"]}
    files = {}

    def region(path, name, lines):
        text = files.get(path, (root / path).read_text())
        files[path] = replace_region(text, name, lines, path)

    region(C_HEADER, "enums", c_enums(tables))
    region(FORTRAN_MODULE, "enums", fortran_constants(tables))
    enum_names = {type_name: c_name for type_name, c_name, _, _ in C_ENUMS}
    for c_name, (c_lines, fortran_lines) in struct_projections(description["results"], enum_names).items():
        region(C_HEADER, f"{c_name} members", c_lines)
        region(FORTRAN_MODULE, f"{c_name} components", fortran_lines)
    region(MEMBERS_FILE, "c members", member_tables(description["results"]))
    for name, lines in writer_lines(description["results"]).items():
        region(CONTACT_LINE_FILE, name, lines)
    for name, lines in writer_lines(description["results"], fortran=True).items():
        region(FORTRAN_CONTACT_LINE_FILE, name, lines)
    for name, lines in mex_lines(description["results"], enum_names).items():
        region(MEX_FILE, name, lines)
    region(PY_STUB, "enums", py_enums(tables))
    region(PY_STUB, "results", py_results(description["results"]))
    for path in sorted({path for path, _, _ in SCHEMA_ENUMS}):
        targets = [t for t in SCHEMA_ENUMS if t[0] == path and t[2] in tables]
        files[path] = schema_text((root / path).read_text(), path, targets, tables, description["results"])
    if "JointContacts" in {result["type"] for result in description["results"]}:
        answer = json.loads(files["docs/schema/detect-answer.schema.json"])
        region(DETECT_HELP, "answer keys", schema_results.detect_help_lines(answer))
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--describe", required=True, help="the describe_projections program")
    parser.add_argument("--root", default=str(pathlib.Path(__file__).resolve().parents[2]))
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true", help="fail if a checked-in file differs")
    mode.add_argument("--write", action="store_true", help="rewrite the files")
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    description = json.loads(subprocess.run([args.describe], check=True, capture_output=True, text=True).stdout)
    stale = []
    for path, text in projections(root, description).items():
        old = (root / path).read_text()
        if old == text:
            continue
        if args.write:
            (root / path).write_text(text)
            print(f"wrote {path}")
        else:
            stale.append(path)
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), text.splitlines(True),
                                                       f"{path} (checked in)", f"{path} (from the tables)"))
    if stale:
        print(f"\nstale: {', '.join(stale)}: the enum tables or result field lists changed; run\n"
              f"    {REGENERATE}\nand commit the result.")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
