# SPDX-License-Identifier: BSD-3-Clause
"""The C structs of the results (clearjoint.h) and the Fortran BIND(C) types that mirror them
(clearjoint.f90), written from the result field lists.

The field lists give the fields, their order in the outputs and their types; what they cannot give
is the C layout, which the ABI rules of clearjoint.h freeze: no member moves, structs never grow,
and a later field takes the room of `reserved` members the library fills in. So each struct's
layout below names, in ABI order, its members: a field of the list (by key, with the C name where
the C API spells it differently, and the comment the header shows), or a member of the C struct
only (padding, a list's count, a C-only string). A field the list gains and the layout does not
name is placed before the struct's trailing reserved array, which shrinks by the field's size, so
the struct's size and every other member's offset stay as they are; a field that does not fit, or
a field the layout names and the list lost, is an error asking for a new ABI (CJ_ABI_VERSION).
"""

# A layout entry: ("field", key, C name or None for the key, comment or None)
#                 ("member", C declaration, Fortran declaration)
#                 ("count", C name, key of the list it counts, comment or None)
# and last ("reserved", C name, number of doubles): the room later fields take.
LAYOUTS = [
    ("Certificate", "cj_certificate", [
        ("field", "level", None, None),
        ("field", "reason", None, None),
        ("member", "const char* reason_text; /**< static string: cj_reason_string(reason) */",
         "type(c_ptr) :: reason_text  ! static C string: cj_string(reason_text)"),
    ]),
    ("RimCrossing", "cj_crossing", [
        ("field", "angle", None, "rim angle in [0, 2 pi), in the rim's CircleFrame (primitives.hpp)"),
        ("field", "angle_error", "angle_error_bound", None),
        ("field", "point", None, None),
        ("field", "point_error", "point_error_bound", None),
        ("field", "multiplicity", None, "1 crossing, 2 tangency, 3-4 higher-order contact"),
        ("member", "int32_t reserved;", "integer(c_int32_t) :: reserved"),
    ]),
    ("Contact", "cj_contact", [
        ("field", "type", None, None),
        ("field", "base", None, None),
        ("field", "point_journal", "p_WCj", "contact point on the journal"),
        ("field", "point_bearing", "p_WCi", "contact point on the bearing"),
        ("field", "normal", "normal_W", None),
        ("field", "depth", None, None),
        ("field", "depth_error", "depth_error_bound", None),
        ("field", "point_journal_error", "p_WCj_error_bound", None),
        ("field", "point_bearing_error", "p_WCi_error_bound", None),
        ("field", "crossings", None, "Rim crossings bounding the penetration arc (point contacts); none for "
                                     "line and face contacts."),
        ("count", "crossing_count", "crossings", None),
        ("member", "int32_t reserved0;", "integer(c_int32_t) :: reserved0"),
        ("field", "certificate", None, None),
        ("reserved", "reserved", 4),
    ]),
    ("JointContacts", "cj_result", [
        ("field", "scenario", None, None),
        ("field", "aligned", None, "1 when the axes are (treated as) parallel"),
        ("count", "contact_count", "contacts", "0 to CJ_MAX_CONTACTS"),
        ("member", "int32_t reserved0;", "integer(c_int32_t) :: reserved0"),
        ("field", "certificate", None, "The weakest certificate over every decision taken, \"no contact\" "
                                       "answers included."),
        ("field", "contacts", None, None),
        ("reserved", "reserved", 8),
    ]),
    ("PinInHoleContacts", "cj_pin_in_hole_result", [
        ("field", "scenario", None, None),
        ("field", "aligned", None, "1 when the axes are (treated as) parallel"),
        ("count", "contact_count", "contacts", "0 to CJ_MAX_CONTACTS"),
        ("member", "int32_t reserved0;", "integer(c_int32_t) :: reserved0"),
        ("field", "certificate", None, "The weakest certificate over every decision taken, \"no contact\" "
                                       "answers included."),
        ("field", "contacts", None, "Radial (edges, line) before axial (stops, faces), face A before B."),
        ("reserved", "reserved", 8),
    ]),
]

# The C array bound of a list whose capacity the header names.
CAPACITY_NAMES = {6: "CJ_MAX_CONTACTS"}


def _types(field, c_enums):
    """(C type, array suffix, Fortran type, size in doubles or None) of a field; a default comment."""
    kind, value = field["kind"], field["value"]
    structs = {result: c_name for result, c_name, _ in LAYOUTS}
    if kind == "optional":
        raise SystemExit(f"c_structs.py: no C layout for the optional field {field['key']}")
    if kind == "list":
        if value not in structs:
            raise SystemExit(f"c_structs.py: no C struct for the items of {field['key']} ({value})")
        bound = CAPACITY_NAMES.get(field["capacity"], str(field["capacity"]))
        return structs[value], f"[{bound}]", f"type({structs[value]})", f"({bound})", None, None
    if value in ("float",) or kind == "bound":
        return "double", "", "real(c_double)", "", 1, None
    if value == "vector3":
        return "double", "[3]", "real(c_double)", "(3)", 3, None
    if value == "int":
        return "int32_t", "", "integer(c_int32_t)", "", 1, None
    if value == "bool":
        return "int32_t", "", "integer(c_int32_t)", "", 1, "1 or 0"
    if value in c_enums:
        return "int32_t", "", "integer(c_int32_t)", "", 1, c_enums[value]
    if value in structs:
        return structs[value], "", f"type({structs[value]})", "", None, None
    raise SystemExit(f"c_structs.py: no C type for the field {field['key']} ({value})")


def _comment_lines(comment, indent="  "):
    import textwrap
    wrapped = textwrap.wrap(comment, 100 - len(indent) - 7)
    lines = [f"{indent}/** " + wrapped[0]] + [f"{indent} * " + text for text in wrapped[1:]]
    lines[-1] += " */"
    return lines


def members(result, c_enums):
    """The C struct's member lines and the Fortran type's component lines of a described result."""
    fields = {f["key"]: f for f in result["fields"]}
    name = next((c for r, c, _ in LAYOUTS if r == result["type"]), None)
    layout = next(entries for r, _, entries in LAYOUTS if r == result["type"])
    placed = {entry[1] for entry in layout if entry[0] == "field"}
    lost = sorted(placed - fields.keys())
    if lost:
        raise SystemExit(f"{name}: the field list of {result['type']} no longer has {', '.join(lost)}; removing "
                         "a member changes the C ABI (see the ABI rules in clearjoint.h): do it with a new "
                         "CJ_ABI_VERSION and edit LAYOUTS in scripts/projections/c_structs.py")
    later = [f for f in result["fields"] if f["key"] not in placed]
    c_lines, f_lines = [], []

    def field_lines(field, c_name, comment):
        c_type, c_suffix, f_type, f_suffix, _, default = _types(field, c_enums)
        comment = comment or default
        declaration = f"  {c_type} {c_name}{c_suffix};"
        if comment and len(declaration) + len(comment) + 7 <= 100:
            c_lines.append(f"{declaration} /**< {comment} */")
        else:
            c_lines.extend((_comment_lines(comment) if comment else []) + [declaration])
        f_lines.append(f"    {f_type} :: {c_name}{f_suffix}")

    for entry in layout:
        if entry[0] == "field":
            _, key, c_name, comment = entry
            field_lines(fields[key], c_name or key, comment)
        elif entry[0] == "member":
            c_lines.append(f"  {entry[1]}")
            f_lines.append(f"    {entry[2]}")
        elif entry[0] == "count":
            _, c_name, key, comment = entry
            c_lines.append(f"  int32_t {c_name};" + (f" /**< {comment} */" if comment else ""))
            f_lines.append(f"    integer(c_int32_t) :: {c_name}")
        else:  # the trailing reserved room: later fields first
            _, c_name, room = entry
            for field in later:
                size = _types(field, c_enums)[4]
                if size is None or size > room:
                    raise SystemExit(f"{name}: no reserved room left for the new field {field['key']}; growing "
                                     "the struct changes the C ABI (see the ABI rules in clearjoint.h): do it "
                                     "with a new CJ_ABI_VERSION and edit LAYOUTS in "
                                     "scripts/projections/c_structs.py")
                room -= size
                field_lines(field, field["key"], field["doc"] or None)
            later = []
            if room:
                c_lines.append(f"  double {c_name}[{room}];")
                f_lines.append(f"    real(c_double) :: {c_name}({room})")
    if later:
        raise SystemExit(f"{name}: has no reserved room for the new field(s) "
                         f"{', '.join(f['key'] for f in later)}; growing the struct changes the C ABI (see the ABI "
                         "rules in clearjoint.h): do it with a new CJ_ABI_VERSION and edit LAYOUTS in "
                         "scripts/projections/c_structs.py")
    return c_lines, f_lines


def struct_projections(results, c_enums):
    """{C struct name: (C lines, Fortran lines)} for every laid-out result the description has."""
    described = {result["type"]: result for result in results}
    return {c_name: members(described[r], c_enums) for r, c_name, _ in LAYOUTS if r in described}
