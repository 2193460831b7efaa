# SPDX-License-Identifier: BSD-3-Clause
"""The C and Fortran writers of a contact's part of the equivalence test's lines
(tests/bindings/equivalence/contact_line.h, used by answers_c.c and pin_in_hole_answers_c.c;
contact_line.inc, included by answers_fortran.f90 and pin_in_hole_answers_fortran.f90), from the
field lists and the C names of c_structs.py (the Fortran types' components are named as the C
members).

The line's order is the test's format (tests/bindings/equivalence/README.md), which the C++,
Fortran and Octave writers share, not the field list's: ORDER names it. A field the list has
beyond ORDER (one added later) follows, in the list's order, as equivalence_line.hpp's
later_fields writes it: a double or bound as H(x), a vector as three, an integer, bool or enum code
in decimal.
"""

from c_copies import _c_names
from c_structs import LAYOUTS

CONTACT_LINE_FILE = "tests/bindings/equivalence/contact_line.h"
FORTRAN_CONTACT_LINE_FILE = "tests/bindings/equivalence/contact_line.inc"

# The fields of each item in the format's order; the variable that points to the item.
ORDER = {
    "Contact": ("c", ["type", "base", "depth", "point_journal", "point_bearing", "normal", "depth_error",
                      "point_journal_error", "point_bearing_error", "crossings", "certificate"]),
    "RimCrossing": ("x", ["angle", "angle_error", "point", "point_error", "multiplicity"]),
}
# The writer of a list's items.
ITEM_WRITERS = {"RimCrossing": "add_crossing"}
FORTRAN_ITEM_WRITERS = {"RimCrossing": "crossing_text"}


def _field_lines(field, var, c_name, counts):
    member = f"{var}->{c_name}"
    if field["kind"] == "list":
        count = f"{var}->{counts[field['key']]}"
        return [f'add(line, " %d", {count});',
                f"for (m = 0; m < {count}; ++m) {ITEM_WRITERS[field['value']]}(line, &{member}[m]);"]
    if field["value"] == "Certificate":
        return [f'add(line, " %d %d", {member}.level, {member}.reason);',
                f'if (with_text) add(line, " \\"%s\\"", {member}.reason_text);']
    if field["value"] == "vector3":
        return [f"add_vector(line, {member});"]
    if field["kind"] == "bound" or field["value"] == "float":
        return [f"add_hex(line, {member});"]
    return [f'add(line, " %d", {member});']  # an integer, a bool (1 or 0) or an enum's code


def _fortran_lines(field, var, c_name, counts):
    member = f"{var}%{c_name}"
    if field["kind"] == "list":
        count = f"{var}%{counts[field['key']]}"
        return [f"line = line//' '//decimal({count})", f"do m = 1, {count}",
                f"  line = line//{FORTRAN_ITEM_WRITERS[field['value']]}({member}(m))", "end do"]
    if field["value"] == "Certificate":
        return [f"line = line//' '//decimal({member}%level)//' '//decimal({member}%reason)",
                f"if (with_text) line = line//' \"'//cj_string({member}%reason_text)//'\"'"]
    if field["value"] == "vector3":
        return [f"line = line//hex3({member})"]
    if field["kind"] == "bound" or field["value"] == "float":
        return [f"line = line//hex({member})"]
    return [f"line = line//' '//decimal({member})"]  # an integer, a bool (1 or 0) or an enum's code


def writer_lines(results, fortran=False):
    """{region name: lines} of contact_line.h (of contact_line.inc if `fortran`) for the items ORDER names."""
    described = {result["type"]: result for result in results}
    layouts = {result_type: layout for result_type, _, layout in LAYOUTS}
    regions = {}
    for result_type, (var, order) in ORDER.items():
        if result_type not in described:
            continue
        names, counts = _c_names(layouts[result_type])
        fields = {f["key"]: f for f in described[result_type]["fields"]}
        lost = [key for key in order if key not in fields]
        if lost:
            raise SystemExit(f"equivalence_lines.py: the field list of {result_type} no longer has "
                             f"{', '.join(lost)}; change the equivalence format (README.md) and ORDER")
        keys = order + [f["key"] for f in described[result_type]["fields"] if f["key"] not in order]
        lines = []
        for key in keys:
            if fortran:
                lines += [f"    {text}" for text in _fortran_lines(fields[key], var, names.get(key, key), counts)]
            else:
                lines += [f"  {text}" for text in _field_lines(fields[key], var, names.get(key, key), counts)]
        regions[f"{result_type} fields"] = lines
    return regions
