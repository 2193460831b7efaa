# SPDX-License-Identifier: BSD-3-Clause
"""The C member of each field of the results that clearjoint.h mirrors, as C++ member pointers in
the order of the field lists (bindings/c/src/c_members.hpp), from the layouts of c_structs.py.

conversions.hpp copies a C++ result into its C struct by pairing each entry of the result's field
list (ResultFields<R>::fields) with the entry of the same place here, and choosing the copy by the
field's kind and types (a bound is a double, an enum its code, a vector three doubles, a list its
items and its count), so a field added to a list is copied with no edit of the bindings.
"""

from c_structs import LAYOUTS

# Lists of these items are written over [0, count) only: the C header says the entries after the
# count are left as they were (cj_result's contacts), and a contact is ~280 bytes. Every other
# list is copied whole, its unused entries holding the kernel's defaults.
WRITTEN_IN_USE_ONLY = {"Contact"}

MEMBERS_FILE = "bindings/c/src/c_members.hpp"


def _c_names(layout):
    """{field key: C member name} and {list key: C count name} of a layout."""
    names = {entry[1]: entry[2] or entry[1] for entry in layout if entry[0] == "field"}
    counts = {entry[2]: entry[1] for entry in layout if entry[0] == "count"}
    return names, counts


def _abi_order(layout, keys):
    """The field keys in the C struct's order: the layout's fields, then those it does not name
    (placed in the reserved room in the list's order, as c_structs.py places them)."""
    named = [entry[1] for entry in layout if entry[0] == "field"]
    return [key for key in named if key in keys] + [key for key in keys if key not in named]


def member_tables(results):
    """The lines of a CMembers specialisation for every laid-out result the description has: the C
    members in the struct's order (so that the copy writes the struct front to back), with the
    place of each one's field in the field list."""
    described = {result["type"]: result for result in results}
    lines = []
    for result_type, c_struct, layout in LAYOUTS:
        if result_type not in described:
            continue
        names, counts = _c_names(layout)
        fields = described[result_type]["fields"]
        place = {field["key"]: i for i, field in enumerate(fields)}
        entries = []
        order = _abi_order(layout, [field["key"] for field in fields])
        for key in order:
            field = fields[place[key]]
            c_name = names.get(key, key)  # a field added later is named by its key (c_structs.py)
            if field["kind"] == "list":
                if key not in counts:
                    raise SystemExit(f"c_copies.py: {c_struct} has no count member for the list {key}")
                form = "InUse" if field["value"] in WRITTEN_IN_USE_ONLY else "Whole"
                entries.append(f"{form}{{&{c_struct}::{c_name}, &{c_struct}::{counts[key]}}}")
            else:
                entries.append(f"&{c_struct}::{c_name}")
        lines += ["template <>", f"struct CMembers<geometry::{result_type}> {{", f"  using type = {c_struct};",
                  f"  static constexpr std::size_t fields[] = {{{', '.join(str(place[key]) for key in order)}}};",
                  "  static constexpr std::tuple members{"]
        lines += [f"      {entry}," for entry in entries[:-1]] + [f"      {entries[-1]}}};", "};"]
    return lines
