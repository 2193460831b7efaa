#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Fails on an include that crosses the project's layers (docs/architecture.md, "Rooms of the kernel").

    check-include-layers.py [ROOT]

Reads every `#include "..."` in geometry/src, bench/, fuzz/, bindings/* and tests/ under ROOT
(default: this checkout) and prints `file:line: why` for each one that
  - in geometry/src, names a kernel header by its bare name instead of its path from src/
    ("arithmetic/error_bounded.hpp"), or names a room above its own (ROOMS, bottom first), or a
    public header whose room is above its own (PUBLIC_HEADER_ROOMS);
  - in bench/, fuzz/ or a binding, reaches a file of tests/ (shared test helpers are libraries
    under support/);
  - in a binding, reaches another binding's files other than the C API's public headers
    (bindings/c/include), or a file of bench/ (a binding's own benchmarks live in bench/bindings).
Exits 1 when it printed any, 0 otherwise. ctest runs it as the test include_layers.
"""
import os
import re
import sys

# The kernel's rooms, bottom first: a file may include its own room and the rooms below it.
ROOMS = ["arithmetic", "model", "predicates", "filters", "exact", "queries", "joint"]

# The public headers the kernel's own files may include, by the lowest room that may include them.
# The value types (vectors, primitives, certificates, results' parts) sit with the rooms that
# build them; a query's header sits with the query.
PUBLIC_HEADER_ROOMS = {
    "clearjoint/geometry/vector3.hpp": "arithmetic",
    "clearjoint/geometry/intersect_circle_plane.hpp": "queries",
    "clearjoint/geometry/intersect_circle_cylinder.hpp": "queries",
    "clearjoint/geometry/detect_contacts.hpp": "joint",
    "clearjoint/geometry/contact_kinematics.hpp": "joint",
}
DEFAULT_PUBLIC_HEADER_ROOM = "model"

CHECKED = ["geometry/src", "bench", "fuzz", "bindings", "tests"]
SOURCE_SUFFIXES = (".hpp", ".cpp", ".h", ".c", ".cc", ".hpp.in", ".h.in")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def area_of(path):
    """tests, bench, fuzz, bindings/<name>, geometry/src or the top-level folder of a path."""
    parts = path.split("/")
    if parts[0] == "bindings" and len(parts) > 2:
        return "bindings/" + parts[1]
    if parts[0] == "geometry" and len(parts) > 1 and parts[1] == "src":
        return "geometry/src"
    return parts[0]


def room_of(path):
    """The room of a file of geometry/src (its first folder there), or None."""
    parts = path.split("/")
    return parts[2] if len(parts) > 3 and parts[:2] == ["geometry", "src"] else None


class Tree:
    """The files under a root, and where a quoted include in one of them leads."""

    def __init__(self, root):
        self.root = root
        self.files = []
        self.by_name = {}
        for top, dirs, names in os.walk(root):
            dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "build")
            for name in names:
                relative = os.path.relpath(os.path.join(top, name), root).replace(os.sep, "/")
                self.files.append(relative)
                self.by_name.setdefault(name, []).append(relative)
        self.file_set = set(self.files)

    def resolve(self, including, name):
        """The file `#include "name"` in `including` leads to: beside the including file, then from
        geometry/src or a public include folder, then any file whose path ends with the name (the
        including file's own area first); None for a header from outside the tree."""
        beside = os.path.normpath(os.path.join(os.path.dirname(including), name)).replace(os.sep, "/")
        if beside in self.file_set:
            return beside
        for prefix in ("geometry/src/", "geometry/include/"):
            if prefix + name in self.file_set:
                return prefix + name
        if name.endswith(".hpp") and name.split("/")[0] in ROOMS:
            generated = "geometry/src/" + name + ".in"  # configured into the build folder
            if generated in self.file_set:
                return generated
        suffix = "/" + name
        candidates = [f for f in self.by_name.get(os.path.basename(name), []) if ("/" + f).endswith(suffix)]
        if not candidates:
            return None
        own = [f for f in candidates if area_of(f) == area_of(including)]
        return sorted(own or candidates)[0]


def kernel_problem(tree, path, name, target):
    room = room_of(path)
    if name.startswith("clearjoint/"):
        needed = PUBLIC_HEADER_ROOMS.get(name, DEFAULT_PUBLIC_HEADER_ROOM)
        if room in ROOMS and ROOMS.index(needed) > ROOMS.index(room):
            return f'"{name}" is a public header of room {needed}/, above {room}/'
        return None
    if target is None or not target.startswith("geometry/src/"):
        return None
    if "/" not in name:
        return f'"{name}": include kernel headers by their path from geometry/src ("{target[len("geometry/src/"):]}")'
    target_room = room_of(target)
    if room in ROOMS and target_room in ROOMS and ROOMS.index(target_room) > ROOMS.index(room):
        return f'"{name}" goes up from room {room}/ to {target_room}/ (order: {" < ".join(ROOMS)})'
    return None


def outside_problem(path, name, target):
    if target is None:
        return None
    area, target_area = area_of(path), area_of(target)
    if area in ("bench", "fuzz") or area.startswith("bindings/"):
        if target_area == "tests":
            return f'"{name}" reaches {target}: {area}/ may not use tests/ (shared helpers go to support/)'
    if area.startswith("bindings/"):
        if target_area.startswith("bindings/") and target_area != area and not target.startswith("bindings/c/include/"):
            return f'"{name}" reaches {target}: one binding may use another only through bindings/c/include'
        if target_area == "bench":
            return f'"{name}" reaches {target}: a binding may not use bench/ (its benchmarks go to bench/bindings)'
    return None


def check(root):
    tree = Tree(root)
    problems = []
    for path in tree.files:
        if not path.endswith(SOURCE_SUFFIXES) or not any(path == c or path.startswith(c + "/") for c in CHECKED):
            continue
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as source:
            for number, line in enumerate(source, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                name = match.group(1)
                target = tree.resolve(path, name)
                why = kernel_problem(tree, path, name, target) if path.startswith("geometry/src/") else None
                why = why or outside_problem(path, name, target)
                if why:
                    problems.append(f"{path}:{number}: {why}")
    return problems


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1] in ("-h", "--help")):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    root = argv[1] if len(argv) == 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    if not os.path.isdir(os.path.join(root, "geometry", "src")):
        print(f"check-include-layers: {root} has no geometry/src", file=sys.stderr)
        return 2
    problems = check(os.path.abspath(root))
    for problem in problems:
        print(problem)
    if problems:
        print(f"check-include-layers: {len(problems)} include(s) cross a layer", file=sys.stderr)
        return 1
    print("check-include-layers: every include keeps to its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
