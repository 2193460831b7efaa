# SPDX-License-Identifier: BSD-3-Clause
"""Print where a package installed under PREFIX is importable by this interpreter.

Relative to PREFIX when the directory lies under it: one of the interpreter's site directories
(site.getsitepackages() and the user site) below PREFIX, the nearest, else the standard
lib/pythonX.Y/site-packages (which then has to be put on PYTHONPATH). Used by
bindings/python/CMakeLists.txt at configure time.
"""
import os
import site
import sys
import sysconfig


def site_directory(prefix: str) -> str:
    prefix = os.path.realpath(prefix)
    candidates = list(site.getsitepackages()) + [site.getusersitepackages()]
    below = [os.path.relpath(os.path.realpath(d), prefix) for d in candidates
             if os.path.realpath(d).startswith(prefix + os.sep)]
    if below:
        # The nearest one: under /usr, lib/python3/dist-packages rather than /usr/local's.
        return min(below, key=len)
    standard = sysconfig.get_path("platlib", "posix_prefix", vars={"base": prefix, "platbase": prefix})
    return os.path.relpath(standard, prefix)


if __name__ == "__main__":
    print(site_directory(sys.argv[1]))
