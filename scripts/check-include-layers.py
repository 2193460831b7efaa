#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Fails on an include that crosses the project's layers (docs/architecture.md, "Layers").

    check-include-layers.py [ROOT]

Reads every `#include "..."` and `#include <clearjoint/...>` in the C and C++ sources
under ROOT (default: this checkout), follows each to the file it names, and prints
`file:line: why` for each one that
  - goes up the module order (MODULES, bottom first): geometry < json_input < lubrication <
    dynamics < nonsmooth and engines < apps and bindings < support (test-only helpers) < bench, fuzz and
    examples < tests and the paper's reproduction; modules of one rank may not include each
    other (but any binding may include the C API's public header, bindings/c/include);
  - inside the kernel, goes up its rooms (ROOMS, bottom first), in geometry/src/<room> and in
    the public headers, geometry/include/clearjoint/geometry/<room>, alike;
  - in an installed public header, reaches a file that is not installed (a module's src/,
    json_input/, support/, ...); in shipped code, reaches another module's src/;
  - in geometry/src, names a kernel header by its bare name instead of its path from src/
    ("arithmetic/error_bounded.hpp");
  - in the repository, names a forwarding header left at a public header's path from before the
    rooms (geometry/include/clearjoint/geometry/<name>.hpp): include the room's path;
  - reaches, through files that are allowed one step at a time, a file the including file may
    not reach (the check follows includes transitively).
It also reads the CMake files of the shipped modules and prints `file:line: why` for each line
that names a target of support/ (test code linked into shipped code).
Exits 1 when it printed any, 0 otherwise. ctest runs it as the test include_layers.
"""
import os
import re
import sys

# The modules, bottom first, with their rank: a file may include files of its own module and of
# modules of a lower rank. Modules of one rank are siblings and may not include each other.
# `bindings/<name>` and `engines/<name>` are modules of their own (see SUBMODULE_PARENTS).
MODULES = {
    "geometry": 0,
    "json_input": 1,
    "lubrication": 2,
    "dynamics": 3,
    "nonsmooth": 4,
    "engines/common": 4,
    "engines/mujoco": 5,
    "engines/simbody": 5,
    # The choice of an engine for a run (the program's --engine, Python's engine=): above every
    # engine it dispatches to, below the front-ends that ask for one.
    "engines/choice": 6,
    "apps": 7,
    "bindings/c": 7,
    "bindings/python": 7,
    "bindings/matlab": 8,
    "bindings/fortran": 8,
    "support": 9,
    "bench": 10,
    "fuzz": 10,
    "examples": 10,
    "tests": 11,
    "scripts": 11,
    "reproduction": 11,
    "models": 11,
}
SUBMODULE_PARENTS = ("engines", "bindings")
# Shipped code: what the libraries, the program and the bindings are built from. Test code
# (support/, tests/, bench/, fuzz/) sits above all of it, so that nothing shipped depends on it.
SHIPPED_RANK = MODULES["support"]
# One exception to "siblings may not include each other": the C API's public header is the
# interface of the bindings built on it.
SHARED_WITH_SIBLINGS = ("bindings/c/include/",)

# The kernel's rooms, bottom first: a file may include its own room and the rooms below it. The
# sources (geometry/src/<room>) and the public headers (geometry/include/clearjoint/geometry/<room>)
# share them.
ROOMS = ["arithmetic", "model", "predicates", "filters", "exact", "queries", "joint"]
PUBLIC_ROOT = "geometry/include/clearjoint/geometry/"
# The kernel's public headers outside clearjoint/geometry/, shared by every module, by room.
OTHER_PUBLIC_HEADER_ROOMS = {
    "geometry/include/clearjoint/validation_error.hpp": "model",
    "geometry/include/clearjoint/version.hpp.in": "model",
}

# Installed public headers: each may include only other installed headers.
INSTALLED = re.compile(r"^(geometry|lubrication|dynamics|nonsmooth|engines/[^/]+|bindings/c)/include/")
# A module's sources: other shipped modules use it through its public headers only (test code may
# test its pieces).
PRIVATE = re.compile(r"^(geometry|json_input|lubrication|dynamics|nonsmooth|engines/[^/]+|bindings/[^/]+)/src/")

SOURCE_SUFFIXES = (".hpp", ".cpp", ".h", ".c", ".cc", ".hpp.in", ".h.in")
SKIPPED_FOLDERS = {"build", "corpus", "node_modules"}
INCLUDE = re.compile(r'^\s*#\s*include\s+(?:"([^"]+)"|<(clearjoint/[^>]+)>)')


def module_of(path):
    """The module of a path (its top-level folder, or bindings/<name>, engines/<name>), or None
    for a file outside MODULES."""
    parts = path.split("/")
    if parts[0] in SUBMODULE_PARENTS and len(parts) > 2:
        name = parts[0] + "/" + parts[1]
    else:
        name = parts[0]
    return name if name in MODULES else None


def room_of(path):
    """The kernel room of a file of geometry/src or of the kernel's public headers, or None."""
    parts = path.split("/")
    if len(parts) > 3 and parts[:2] == ["geometry", "src"] and parts[2] in ROOMS:
        return parts[2]
    if path.startswith(PUBLIC_ROOT):
        rest = path[len(PUBLIC_ROOT):].split("/")
        return rest[0] if len(rest) > 1 and rest[0] in ROOMS else None
    return OTHER_PUBLIC_HEADER_ROOMS.get(path)


def is_forwarding_header(path):
    """A header left at its path from before the public headers had rooms."""
    return path.startswith(PUBLIC_ROOT) and "/" not in path[len(PUBLIC_ROOT):]


class Tree:
    """The files under a root, and where an include in one of them leads."""

    def __init__(self, root):
        self.root = root
        self.files = []
        self.by_name = {}
        for top, dirs, names in os.walk(root):
            dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIPPED_FOLDERS
                             and not d.startswith("build"))
            for name in names:
                relative = os.path.relpath(os.path.join(top, name), root).replace(os.sep, "/")
                self.files.append(relative)
                self.by_name.setdefault(name, []).append(relative)
        self.file_set = set(self.files)
        self.include_roots = sorted({f[:f.index("/include/") + len("/include/")]
                                     for f in self.files if "/include/" in f})
        self.includes = {}

    def find(self, name):
        """`name` or the template it is configured from (name.in)."""
        for candidate in (name, name + ".in"):
            if candidate in self.file_set:
                return candidate
        return None

    def resolve(self, including, name, angled):
        """The file an include of `name` in `including` leads to: beside the including file, then
        from geometry/src or a public include folder, then (quoted includes only) any file whose
        path ends with the name, the including file's own module first; None for a header from
        outside the tree."""
        if not angled:
            beside = os.path.normpath(os.path.join(os.path.dirname(including), name)).replace(os.sep, "/")
            found = self.find(beside)
            if found:
                return found
        for prefix in ["geometry/src/"] + self.include_roots:
            found = self.find(prefix + name)
            if found:
                return found
        if angled:
            return None
        suffix = "/" + name
        candidates = [f for f in self.by_name.get(os.path.basename(name), []) + self.by_name.get(os.path.basename(name) + ".in", [])
                      if ("/" + f).endswith(suffix) or ("/" + f).endswith(suffix + ".in")]
        if not candidates:
            return None
        own = [f for f in candidates if module_of(f) == module_of(including)]
        return sorted(own or candidates)[0]

    def includes_of(self, path):
        """[(line number, name, target or None)] of a file's includes."""
        if path not in self.includes:
            found = []
            with open(os.path.join(self.root, path), encoding="utf-8", errors="replace") as source:
                for number, line in enumerate(source, 1):
                    match = INCLUDE.match(line)
                    if match:
                        name = match.group(1) or match.group(2)
                        found.append((number, name, self.resolve(path, name, match.group(2) is not None)))
            self.includes[path] = found
        return self.includes[path]


def layer_problem(path, target):
    """Why a file may not reach `target` (module order, rooms, installed headers), or None."""
    module, target_module = module_of(path), module_of(target)
    if module is None or target_module is None:
        return None
    if module != target_module:
        rank, target_rank = MODULES[module], MODULES[target_module]
        if target_rank > rank:
            if rank < SHIPPED_RANK <= target_rank:
                return f"{module}/ may not use {target_module}/ (shipped code may not use test code)"
            return f"{module}/ may not use {target_module}/, a higher layer"
        if target_rank == rank and not target.startswith(SHARED_WITH_SIBLINGS):
            return f"{module}/ may not use {target_module}/ (one layer; only the C API's public header is shared)"
        if rank < SHIPPED_RANK and PRIVATE.match(target):
            return f"{module}/ may not use the sources of {target_module}/ (only its public headers)"
    room, target_room = room_of(path), room_of(target)
    if room and target_room and ROOMS.index(target_room) > ROOMS.index(room):
        return f"goes up from room {room}/ to {target_room}/ (order: {' < '.join(ROOMS)})"
    if INSTALLED.match(path) and not INSTALLED.match(target):
        return "an installed public header may include only installed public headers"
    return None


def direct_problem(path, name, target):
    """Why one include is wrong on its own, or None."""
    if target is None:
        return None
    if path.startswith("geometry/src/") and target.startswith("geometry/src/") and "/" not in name:
        return f'"{name}": include kernel headers by their path from geometry/src ("{target[len("geometry/src/"):]}")'
    if is_forwarding_header(target) and not is_forwarding_header(path):
        moved = os.path.basename(target)
        return f'"{name}" is a forwarding header: include the public header by its room (clearjoint/geometry/<room>/{moved})'
    why = layer_problem(path, target)
    return f'"{name}" reaches {target}: {why}' if why else None


def transitive_problem(tree, path, target):
    """A file reached from `target` through allowed includes that `path` may not reach, with the
    chain, or None. Each step of the chain was allowed, so no other line reports it."""
    seen = {target}
    stack = [(target, [target])]
    while stack:
        current, chain = stack.pop()
        for _, name, reached in tree.includes_of(current):
            if reached is None or reached in seen or direct_problem(current, name, reached):
                continue
            seen.add(reached)
            why = layer_problem(path, reached)
            if why:
                return f"reaches {reached} through {' -> '.join(chain)}: {why}"
            stack.append((reached, chain + [reached]))
    return None


TARGET = re.compile(r"^\s*add_library\s*\(\s*([A-Za-z0-9_]+)", re.MULTILINE)


def cmake_problems(tree):
    """Lines of a shipped module's CMake files that name a library defined in support/."""
    cmake = [f for f in tree.files if f.endswith(("CMakeLists.txt", ".cmake"))]
    test_targets = set()
    for path in cmake:
        if module_of(path) == "support":
            with open(os.path.join(tree.root, path), encoding="utf-8", errors="replace") as source:
                test_targets.update(TARGET.findall(source.read()))
    if not test_targets:
        return []
    named = re.compile(r"(?<![A-Za-z0-9_])(" + "|".join(sorted(test_targets)) + r")(?![A-Za-z0-9_])")
    problems = []
    for path in cmake:
        module = module_of(path)
        if module is None or MODULES[module] >= SHIPPED_RANK:
            continue
        with open(os.path.join(tree.root, path), encoding="utf-8", errors="replace") as source:
            for number, line in enumerate(source, 1):
                match = named.search(line.split("#", 1)[0])
                if match:
                    problems.append(f"{path}:{number}: links {match.group(1)}, test code of support/: "
                                    f"shipped code may not use test code")
    return problems


def check(root):
    tree = Tree(root)
    problems = cmake_problems(tree)
    for path in tree.files:
        parts = path.split("/")
        if path.endswith(SOURCE_SUFFIXES) and parts[0] in SUBMODULE_PARENTS and len(parts) > 2 \
                and module_of(path) is None:
            # A new engine or binding must take its place in the order before it is checked.
            problems.append(f"{path}: {parts[0]}/{parts[1]}/ is a module the order does not list "
                            "(add it to MODULES)")
            continue
        if not path.endswith(SOURCE_SUFFIXES) or module_of(path) is None and not path.startswith("geometry/"):
            continue
        for number, name, target in tree.includes_of(path):
            why = direct_problem(path, name, target)
            if why is None and target is not None:
                why = transitive_problem(tree, path, target)
                why = f'"{name}" {why}' if why else None
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
        print(f"check-include-layers: {len(problems)} line(s) cross a layer", file=sys.stderr)
        return 1
    print("check-include-layers: every include keeps to its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
