# SPDX-License-Identifier: BSD-3-Clause
"""The MEX results' contact and crossing fields (bindings/matlab/mex_results.c): their names and
the lines that set them, from the field lists and the C names of c_structs.py.

A MATLAB field is named as the C member it is read from. The MEX order is the one the Octave help
lists (cj_detect.m), not the field list's (each error bound follows its value): ORDER names it,
and a field the list has beyond ORDER (one added later) follows in the list's order. Values by
kind: an enum as its key (cj_*_string), a double, bound or integer as a double, a bool as a
logical, a vector as a 1 x 3 row, a list as a struct array (LIST_BUILDERS), a certificate as a
struct.
"""

import textwrap

from c_copies import _c_names
from c_structs import LAYOUTS

MEX_FILE = "bindings/matlab/mex_results.c"

# The fields of each item in the MEX order; the variable that points to the item.
ORDER = {
    "Contact": ("c", ["type", "base", "depth", "depth_error", "point_journal", "point_journal_error",
                      "point_bearing", "point_bearing_error", "normal", "crossings", "certificate"]),
    "RimCrossing": ("x", ["angle", "angle_error", "point", "point_error", "multiplicity"]),
}
# The function of mex_results.c that makes the struct array of a list's items.
LIST_BUILDERS = {"RimCrossing": "crossings"}


def _value(field, member, var, c_enums):
    kind, value = field["kind"], field["value"]
    if kind == "list":
        return f"{LIST_BUILDERS[value]}({var})"
    if value == "Certificate":
        return f"certificate(&{member})"
    if value == "vector3":
        return f"row3({member})"
    if value == "bool":
        return f"mxCreateLogicalScalar({member} != 0)"
    if value in c_enums:
        return f"mxCreateString({c_enums[value]}_string({member}))"
    if kind == "bound" or value in ("float", "int"):
        return f"mxCreateDoubleScalar({member})"
    raise SystemExit(f"mex_results.py: no MATLAB value for the field {field['key']} ({value})")


def mex_lines(results, c_enums):
    """{region name: lines} of mex_results.c for the items ORDER names."""
    described = {result["type"]: result for result in results}
    layouts = {result_type: layout for result_type, _, layout in LAYOUTS}
    regions = {}
    for result_type, (var, order) in ORDER.items():
        if result_type not in described:
            continue
        names, _ = _c_names(layouts[result_type])
        fields = {f["key"]: f for f in described[result_type]["fields"]}
        lost = [key for key in order if key not in fields]
        if lost:
            raise SystemExit(f"mex_results.py: the field list of {result_type} no longer has {', '.join(lost)}; "
                             "removing a MATLAB field changes the MEX results: edit ORDER and the help (cj_detect.m)")
        keys = order + [f["key"] for f in described[result_type]["fields"] if f["key"] not in order]
        c_names = [names.get(key, key) for key in keys]
        regions[f"{result_type} names"] = textwrap.wrap(", ".join(f'"{name}"' for name in c_names), 96,
                                                        initial_indent="    ", subsequent_indent="    ")
        regions[f"{result_type} values"] = [
            f"    mxSetFieldByNumber(out, k, {i}, {_value(fields[key], f'{var}->{name}', var, c_enums)});"
            for i, (key, name) in enumerate(zip(keys, c_names))]
    return regions
