#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of scripts/check-include-layers.py on small trees written for each case: it passes a tree
that keeps to its layers and names file and line of each include that crosses one."""
import os
import subprocess
import sys
import tempfile
import unittest

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "check-include-layers.py")

# A tree that keeps to its layers: each room includes its own and lower rooms by path, a query's
# public header from its own room, the bindings share the C API's public header only.
CLEAN_TREE = {
    "geometry/src/arithmetic/error_bounded.hpp": '#include "clearjoint/geometry/vector3.hpp"\n',
    "geometry/src/arithmetic/build.hpp.in": "",
    "geometry/src/predicates/plane_terms.hpp": '#include "arithmetic/error_bounded.hpp"\n',
    "geometry/src/predicates/plane_terms.cpp": '#include "predicates/plane_terms.hpp"\n#include "arithmetic/build.hpp"\n',
    "geometry/src/queries/intersect.cpp": '#include "clearjoint/geometry/intersect_circle_plane.hpp"\n'
                                          '#include "predicates/plane_terms.hpp"\n',
    "geometry/src/joint/detect.cpp": '#include "queries/rounded.hpp"\n',
    "geometry/src/queries/rounded.hpp": "",
    "geometry/include/clearjoint/geometry/vector3.hpp": "",
    "geometry/include/clearjoint/geometry/intersect_circle_plane.hpp": "",
    "support/testing/joint_properties.hpp": "",
    "tests/geometry/joint/test_detect.cpp": '#include "joint_properties.hpp"\n#include "scenarios.hpp"\n',
    "tests/geometry/joint/scenarios.hpp": "",
    "bench/geometry/bench_detect.cpp": '#include "joint_properties.hpp"\n#include "common/source.hpp"\n',
    "bench/common/source.hpp": "",
    "bench/bindings/bench_python.cpp": '#include "common/source.hpp"\n',
    "fuzz/fuzz_detect.cpp": '#include "joint_properties.hpp"\n#include <vector>\n#include "not_in_tree.hpp"\n',
    "bindings/c/include/clearjoint/clearjoint.h": "",
    "bindings/c/src/detect.cpp": '#include "clearjoint/clearjoint.h"\n',
    "bindings/matlab/cj_detect.c": '#include "clearjoint/clearjoint.h"\n',
}


class CheckIncludeLayers(unittest.TestCase):
    def run_checker(self, changes):
        """Writes CLEAN_TREE with `changes` (path: text) into a temporary folder and checks it."""
        with tempfile.TemporaryDirectory() as root:
            for path, text in {**CLEAN_TREE, **changes}.items():
                os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
                with open(os.path.join(root, path), "w", encoding="utf-8") as out:
                    out.write(text)
            done = subprocess.run([sys.executable, CHECKER, root], capture_output=True, text=True)
        return done.returncode, done.stdout

    def assert_reported(self, changes, where, words):
        code, out = self.run_checker(changes)
        self.assertEqual(code, 1, out)
        lines = out.splitlines()
        self.assertEqual(len(lines), 1, out)
        self.assertTrue(lines[0].startswith(where + ": "), out)
        self.assertIn(words, lines[0])

    def test_passes_a_tree_that_keeps_to_its_layers(self):
        code, out = self.run_checker({})
        self.assertEqual(code, 0, out)
        self.assertEqual(out.strip(), "check-include-layers: every include keeps to its layer")

    def test_reports_an_include_that_goes_up_a_room(self):
        self.assert_reported({"geometry/src/predicates/plane_terms.hpp":
                              '#include "arithmetic/error_bounded.hpp"\n#include "queries/rounded.hpp"\n'},
                             "geometry/src/predicates/plane_terms.hpp:2", "goes up from room predicates/ to queries/")

    def test_reports_a_query_header_included_below_its_room(self):
        self.assert_reported({"geometry/src/predicates/plane_terms.cpp":
                              '#include "clearjoint/geometry/intersect_circle_plane.hpp"\n'},
                             "geometry/src/predicates/plane_terms.cpp:1", "public header of room queries/")

    def test_reports_a_kernel_header_named_without_its_room(self):
        self.assert_reported({"geometry/src/joint/detect.cpp": '#include "rounded.hpp"\n'},
                             "geometry/src/joint/detect.cpp:1", '("queries/rounded.hpp")')

    def test_reports_fuzz_and_bench_reaching_into_tests(self):
        self.assert_reported({"fuzz/fuzz_detect.cpp": '#include "scenarios.hpp"\n'},
                             "fuzz/fuzz_detect.cpp:1", "fuzz/ may not use tests/")
        self.assert_reported({"bench/geometry/bench_detect.cpp": '\n#include "scenarios.hpp"\n'},
                             "bench/geometry/bench_detect.cpp:2", "bench/ may not use tests/")

    def test_reports_a_binding_reaching_into_another_binding_or_bench(self):
        self.assert_reported({"bindings/matlab/cj_detect.c": '#include "detect.cpp"\n'},
                             "bindings/matlab/cj_detect.c:1", "through bindings/c/include")
        self.assert_reported({"bindings/c/src/detect.cpp": '#include "common/source.hpp"\n'},
                             "bindings/c/src/detect.cpp:1", "may not use bench/")


if __name__ == "__main__":
    unittest.main()
