#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of scripts/check-include-layers.py on small trees written for each case: it passes a tree
that keeps to its layers and names file and line of each include that crosses one, at every zoom:
the module order, the kernel's rooms (sources and public headers), installed headers, and
includes followed through files outside every layer."""
import os
import subprocess
import sys
import tempfile
import unittest

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "check-include-layers.py")

PUBLIC = "geometry/include/clearjoint/geometry/"

# A tree that keeps to its layers: each room includes its own and lower rooms by path, a query's
# public header from its own room, each module the modules below it, the bindings share the C
# API's public header only, the test code (support/, tests/, bench/, fuzz/) sits on top.
CLEAN_TREE = {
    "geometry/src/arithmetic/error_bounded.hpp": '#include "clearjoint/geometry/arithmetic/vector3.hpp"\n',
    "geometry/src/arithmetic/build.hpp.in": "",
    "geometry/src/model/checks.cpp": '#include "clearjoint/geometry/model/primitives.hpp"\n'
                                     '#include "clearjoint/validation_error.hpp"\n',
    "geometry/src/predicates/plane_terms.hpp": '#include "arithmetic/error_bounded.hpp"\n',
    "geometry/src/predicates/plane_terms.cpp": '#include "predicates/plane_terms.hpp"\n#include "arithmetic/build.hpp"\n',
    "geometry/src/queries/intersect.cpp": '#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"\n'
                                          '#include "predicates/plane_terms.hpp"\n',
    "geometry/src/joint/detect.cpp": '#include "queries/rounded.hpp"\n#include "clearjoint/geometry/joint/detect_contacts.hpp"\n',
    "geometry/src/queries/rounded.hpp": "",
    "geometry/include/clearjoint/validation_error.hpp": "",
    PUBLIC + "arithmetic/vector3.hpp": "#include <Eigen/Core>\n",
    PUBLIC + "model/primitives.hpp": '#include "clearjoint/geometry/arithmetic/vector3.hpp"\n'
                                     '#include "clearjoint/validation_error.hpp"\n',
    PUBLIC + "queries/intersect_circle_plane.hpp": '#include "clearjoint/geometry/model/primitives.hpp"\n',
    PUBLIC + "joint/detect_contacts.hpp": '#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"\n',
    PUBLIC + "detect_contacts.hpp": '#include "clearjoint/geometry/joint/detect_contacts.hpp"\n',
    "json_input/include/clearjoint/json_input/json_reader.hpp": '#include "clearjoint/validation_error.hpp"\n',
    "lubrication/include/clearjoint/lubrication/film.hpp": '#include "clearjoint/geometry/model/primitives.hpp"\n',
    "dynamics/include/clearjoint/dynamics/joint.hpp": '#include "clearjoint/geometry/joint/detect_contacts.hpp"\n'
                                                      '#include "clearjoint/lubrication/film.hpp"\n',
    "dynamics/src/model_file.cpp": '#include "clearjoint/dynamics/joint.hpp"\n'
                                   '#include "clearjoint/json_input/json_reader.hpp"\n',
    "engines/simbody/src/force.cpp": '#include "clearjoint/dynamics/joint.hpp"\n',
    "apps/clearjoint/json_lines.hpp": '#include "clearjoint/json_input/json_reader.hpp"\n',
    "support/testing/joint_properties.hpp": '#include <clearjoint/geometry/joint/detect_contacts.hpp>\n',
    "tests/geometry/joint/test_detect.cpp": '#include "joint_properties.hpp"\n#include "scenarios.hpp"\n',
    "tests/geometry/joint/scenarios.hpp": "",
    "tests/apps/test_lines.cpp": '#include "json_lines.hpp"\n',
    "bench/geometry/bench_detect.cpp": '#include "joint_properties.hpp"\n#include "common/source.hpp"\n',
    "bench/common/source.hpp": "",
    "bench/bindings/bench_python.cpp": '#include "common/source.hpp"\n',
    "fuzz/fuzz_detect.cpp": '#include "joint_properties.hpp"\n#include <vector>\n#include "not_in_tree.hpp"\n',
    "fuzz/fuzz_lines.cpp": '#include "json_lines.hpp"\n',
    "bindings/c/include/clearjoint/clearjoint.h": "",
    "bindings/c/src/detect.cpp": '#include "clearjoint/clearjoint.h"\n#include "clearjoint/geometry/joint/detect_contacts.hpp"\n',
    "bindings/matlab/cj_detect.c": '#include "clearjoint/clearjoint.h"\n',
    "third_party/glue.hpp": "",
    "support/CMakeLists.txt": "add_library(clearjoint_test_joints INTERFACE)\n",
    "dynamics/CMakeLists.txt": "# not clearjoint_test_joints\nadd_library(clearjoint_dynamics src/model_file.cpp)\n",
    "tests/CMakeLists.txt": "target_link_libraries(test_detect PRIVATE clearjoint_test_joints)\n",
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
                              '#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"\n'},
                             "geometry/src/predicates/plane_terms.cpp:1", "goes up from room predicates/ to queries/")

    def test_reports_a_public_header_that_includes_an_upper_room(self):
        self.assert_reported({PUBLIC + "model/primitives.hpp":
                              '#include "clearjoint/geometry/joint/detect_contacts.hpp"\n'},
                             PUBLIC + "model/primitives.hpp:1", "goes up from room model/ to joint/")

    def test_reports_a_public_header_that_includes_the_kernels_sources(self):
        self.assert_reported({PUBLIC + "joint/detect_contacts.hpp": '#include "queries/rounded.hpp"\n'},
                             PUBLIC + "joint/detect_contacts.hpp:1", "installed public header")

    def test_reports_an_installed_header_that_includes_json_input(self):
        self.assert_reported({"dynamics/include/clearjoint/dynamics/joint.hpp":
                              '#include "clearjoint/json_input/json_reader.hpp"\n'},
                             "dynamics/include/clearjoint/dynamics/joint.hpp:1", "installed public header")

    def test_reports_an_installed_header_that_includes_test_scaffolding(self):
        # The helpers that change one field or option at a time (support/testing/) are test code:
        # a public header that reached them would ship them.
        self.assert_reported({PUBLIC + "joint/detect_contacts.hpp":
                              '#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"\n'
                              '#include "joint_properties.hpp"\n'},
                             PUBLIC + "joint/detect_contacts.hpp:2", "shipped code may not use test code")

    def test_reports_a_kernel_header_named_without_its_room(self):
        self.assert_reported({"geometry/src/joint/detect.cpp": '#include "rounded.hpp"\n'},
                             "geometry/src/joint/detect.cpp:1", '("queries/rounded.hpp")')

    def test_reports_a_forwarding_header_included_by_the_repository(self):
        self.assert_reported({"dynamics/src/model_file.cpp": '#include "clearjoint/geometry/detect_contacts.hpp"\n'},
                             "dynamics/src/model_file.cpp:1", "forwarding header")

    def test_reports_the_kernel_including_a_dynamics_header(self):
        self.assert_reported({"geometry/src/joint/detect.cpp": '#include "clearjoint/dynamics/joint.hpp"\n'},
                             "geometry/src/joint/detect.cpp:1", "geometry/ may not use dynamics/, a higher layer")

    def test_reports_lubrication_including_dynamics_and_dynamics_including_engines(self):
        self.assert_reported({"lubrication/include/clearjoint/lubrication/film.hpp":
                              '#include "clearjoint/dynamics/joint.hpp"\n'},
                             "lubrication/include/clearjoint/lubrication/film.hpp:1", "lubrication/ may not use dynamics/")
        self.assert_reported({"dynamics/src/model_file.cpp": '#include "force.cpp"\n'},
                             "dynamics/src/model_file.cpp:1", "dynamics/ may not use engines/simbody/")

    def test_reports_shipped_code_that_uses_test_code(self):
        self.assert_reported({"dynamics/src/model_file.cpp": '#include "joint_properties.hpp"\n'},
                             "dynamics/src/model_file.cpp:1", "shipped code may not use test code")
        self.assert_reported({"apps/clearjoint/json_lines.hpp": '#include "common/source.hpp"\n'},
                             "apps/clearjoint/json_lines.hpp:1", "shipped code may not use test code")

    def test_reports_a_module_using_another_modules_sources(self):
        self.assert_reported({"dynamics/src/model_file.cpp": '#include "queries/rounded.hpp"\n'},
                             "dynamics/src/model_file.cpp:1", "dynamics/ may not use the sources of geometry/")

    def test_reports_a_shipped_library_that_links_test_code(self):
        self.assert_reported({"dynamics/CMakeLists.txt": "add_library(clearjoint_dynamics src/model_file.cpp)\n"
                                                         "target_link_libraries(clearjoint_dynamics PRIVATE clearjoint_test_joints)\n"},
                             "dynamics/CMakeLists.txt:2", "links clearjoint_test_joints")

    def test_reports_one_application_using_another(self):
        self.assert_reported({"bindings/c/src/detect.cpp": '#include "json_lines.hpp"\n'},
                             "bindings/c/src/detect.cpp:1", "bindings/c/ may not use apps/")

    def test_reports_fuzz_and_bench_reaching_into_tests(self):
        self.assert_reported({"fuzz/fuzz_detect.cpp": '#include "scenarios.hpp"\n'},
                             "fuzz/fuzz_detect.cpp:1", "fuzz/ may not use tests/")
        self.assert_reported({"bench/geometry/bench_detect.cpp": '\n#include "scenarios.hpp"\n'},
                             "bench/geometry/bench_detect.cpp:2", "bench/ may not use tests/")

    def test_reports_a_binding_reaching_into_another_binding_or_bench(self):
        self.assert_reported({"bindings/matlab/cj_detect.c": '#include "detect.cpp"\n'},
                             "bindings/matlab/cj_detect.c:1", "may not use the sources of bindings/c/")
        self.assert_reported({"bindings/c/src/detect.cpp": '#include "common/source.hpp"\n'},
                             "bindings/c/src/detect.cpp:1", "bindings/c/ may not use bench/")

    def test_reports_an_engine_or_binding_the_module_order_does_not_list(self):
        self.assert_reported({"engines/racing/src/race.cpp": '#include "clearjoint/dynamics/joint.hpp"\n'},
                             "engines/racing/src/race.cpp", "a module the order does not list")

    def test_lets_the_engine_choice_use_an_engine_and_the_program_use_the_choice(self):
        code, out = self.run_checker({
            "engines/choice/include/clearjoint/engines/choice.hpp": '#include "clearjoint/dynamics/joint.hpp"\n',
            "engines/choice/src/choice.cpp": '#include "clearjoint/engines/choice.hpp"\n'
                                             '#include "clearjoint/dynamics/joint.hpp"\n',
            "apps/clearjoint/simulate.cpp": '#include "clearjoint/engines/choice.hpp"\n'})
        self.assertEqual(code, 0, out)

    def test_reports_an_engine_using_the_engine_choice_above_it(self):
        self.assert_reported({
            "engines/choice/include/clearjoint/engines/choice.hpp": "",
            "engines/simbody/src/force.cpp": '#include "clearjoint/engines/choice.hpp"\n'},
            "engines/simbody/src/force.cpp:1", "a higher layer")

    def test_follows_includes_through_files_outside_every_layer(self):
        self.assert_reported({"geometry/src/model/checks.cpp": '#include "third_party/glue.hpp"\n',
                              "third_party/glue.hpp": '#include "clearjoint/dynamics/joint.hpp"\n'},
                             "geometry/src/model/checks.cpp:1",
                             "reaches dynamics/include/clearjoint/dynamics/joint.hpp through third_party/glue.hpp")


if __name__ == "__main__":
    unittest.main()
