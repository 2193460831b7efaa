#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of scripts/projections/generate_projections.py on a small tree and a description written
by hand: it writes every projection from the description, passes --check on what it wrote, and
fails --check, naming the file, when a value is added to an enum or a field to a result."""
import json
import os
import stat
import subprocess
import sys
import tempfile
import unittest

GENERATOR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "projections",
                         "generate_projections.py")

C_TYPES = ["ContactScenario", "Certainty", "CertificateReason", "ContactType", "ContactBase",
           "CirclePlaneTopology", "CircleCylinderTopology", "PinInHoleScenario"]


def description():
    enums = [{"type": name, "module": "geometry",
              "entries": [{"code": 0, "name": "first", "key": "first", "label": "the first"},
                          {"code": 1, "name": "second", "key": "2nd", "label": ""}]}
             for name in C_TYPES]
    enums.append({"type": "JointType", "module": "dynamics",
                  "entries": [{"code": 0, "name": "spherical", "key": "spherical", "label": ""}]})
    plain = {"point_journal": "vector3", "point_bearing": "vector3", "normal": "vector3", "type": "ContactType",
             "base": "ContactBase", "certificate": "Certificate"}
    bounds = ["depth_error", "point_journal_error", "point_bearing_error"]
    results = [{"type": "Contact", "fields": [
        {"key": "depth", "doc": "", "kind": "plain", "value": "float"},
        {"key": "crossings", "doc": "", "kind": "list", "value": "RimCrossing", "capacity": 2}]
        + [{"key": key, "doc": "", "kind": "plain", "value": value} for key, value in plain.items()]
        + [{"key": key, "doc": "", "kind": "bound", "value": "float"} for key in bounds]}]
    return {"enums": enums, "results": results}


def enum_node():
    return {"enum": []}


SCHEMAS = {
    "docs/schema/detect-answer.schema.json": {"$defs": {
        "certainty": enum_node(),
        "contact": {"properties": {"type": enum_node(), "base": enum_node()}},
        "answer": {"properties": {"scenario": enum_node()}}}},
    "docs/schema/intersect-answer.schema.json": {"$defs": {
        "certainty": enum_node(),
        "plane_answer": {"properties": {"topology": enum_node()}},
        "cylinder_answer": {"properties": {"topology": enum_node()}}}},
    "docs/schema/model.schema.json": {"$defs": {
        "joint": {"properties": {"type": enum_node()}},
        "force": {"oneOf": [{}, {}, {"properties": {"normal_force": {"properties": {"model": enum_node()}}}}]}}},
}

MARKED = {
    "bindings/c/include/clearjoint/clearjoint.h": "/* BEGIN GENERATED enums */\n/* END GENERATED enums */\n"
        "/* BEGIN GENERATED cj_contact members */\n/* END GENERATED cj_contact members */\n",
    "bindings/fortran/clearjoint.f90": "! BEGIN GENERATED enums\n! END GENERATED enums\n"
        "! BEGIN GENERATED cj_contact components\n! END GENERATED cj_contact components\n",
    "bindings/c/src/c_members.hpp": "// BEGIN GENERATED c members\n// END GENERATED c members\n",
    "bindings/matlab/mex_results.c": "/* BEGIN GENERATED Contact names */\n/* END GENERATED Contact names */\n"
        "/* BEGIN GENERATED Contact values */\n/* END GENERATED Contact values */\n",
    "tests/bindings/equivalence/contact_line.inc":
        "! BEGIN GENERATED Contact fields\n! END GENERATED Contact fields\n",
    "tests/bindings/equivalence/contact_line.h":
        "/* BEGIN GENERATED Contact fields */\n/* END GENERATED Contact fields */\n",
    "bindings/python/clearjoint/__init__.pyi":
        "# BEGIN GENERATED enums\n# END GENERATED enums\n# BEGIN GENERATED results\n# END GENERATED results\n",
}


class GenerateProjections(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.root = self.folder.name
        for path, text in MARKED.items():
            self.write(path, text)
        for path, schema in SCHEMAS.items():
            self.write(path, json.dumps(schema, indent=2) + "\n")
        self.describe = os.path.join(self.root, "describe")
        self.set_description(description())

    def tearDown(self):
        self.folder.cleanup()

    def write(self, path, text):
        full = os.path.join(self.root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w") as f:
            f.write(text)

    def read(self, path):
        with open(os.path.join(self.root, path)) as f:
            return f.read()

    def set_description(self, value):
        with open(self.describe, "w") as f:
            f.write(f"#!{sys.executable}\nimport json\nprint(json.dumps({value!r}))\n")
        os.chmod(self.describe, os.stat(self.describe).st_mode | stat.S_IXUSR)

    def run_generator(self, mode):
        return subprocess.run([sys.executable, GENERATOR, "--describe", self.describe, "--root", self.root, mode],
                              capture_output=True, text=True)

    def test_writes_every_projection_and_then_passes_the_check(self):
        self.assertEqual(self.run_generator("--write").returncode, 0)
        header = self.read("bindings/c/include/clearjoint/clearjoint.h")
        self.assertIn("CJ_SCENARIO_SECOND = 1", header)
        self.assertIn("CJ_CONTACT_FIRST = 0, /**< the first */", header)
        self.assertIn("CJ_BASE_SECOND = 1", self.read("bindings/fortran/clearjoint.f90"))
        stub = self.read("bindings/python/clearjoint/__init__.pyi")
        self.assertIn("class ContactType(enum.IntEnum):\n    first = 0\n    second = 1", stub)
        self.assertNotIn("JointType", stub)  # not one of the enums the package shows
        self.assertIn("def crossings(self) -> List[RimCrossing]: ...", stub)
        answer = json.loads(self.read("docs/schema/detect-answer.schema.json"))
        self.assertEqual(answer["$defs"]["answer"]["properties"]["scenario"]["enum"], ["first", "2nd"])
        model = json.loads(self.read("docs/schema/model.schema.json"))
        self.assertEqual(model["$defs"]["joint"]["properties"]["type"]["enum"], ["spherical"])
        check = self.run_generator("--check")
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)

    def test_a_value_added_to_an_enum_makes_the_check_fail_naming_the_stale_files(self):
        self.run_generator("--write")
        grown = description()
        grown["enums"][0]["entries"].append({"code": 2, "name": "third", "key": "third", "label": ""})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertEqual(check.returncode, 1)
        self.assertIn("+  CJ_SCENARIO_THIRD = 2", check.stdout)
        self.assertIn("stale: bindings/c/include/clearjoint/clearjoint.h", check.stdout)
        self.assertIn("docs/schema/detect-answer.schema.json", check.stdout)

    def test_a_field_added_to_a_result_makes_the_check_fail_on_the_stub(self):
        self.run_generator("--write")
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "bound", "value": "float"})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertEqual(check.returncode, 1)
        self.assertIn("+    def trial(self) -> float: ...", check.stdout)
        self.assertIn("bindings/python/clearjoint/__init__.pyi", check.stdout.split("stale:")[1])

    def test_the_c_struct_and_fortran_type_keep_the_abi_order_not_the_field_list_order(self):
        self.assertEqual(self.run_generator("--write").returncode, 0)
        header = self.read("bindings/c/include/clearjoint/clearjoint.h")
        self.assertLess(header.index("double p_WCj[3];"), header.index("double depth;"))
        self.assertIn("int32_t crossing_count;\n  int32_t reserved0;\n  cj_certificate certificate;\n"
                      "  double reserved[4];", header)
        self.assertIn("real(c_double) :: p_WCj(3)", self.read("bindings/fortran/clearjoint.f90"))

    def test_the_c_members_follow_the_abi_order_with_the_c_names_and_their_fields_places(self):
        self.assertEqual(self.run_generator("--write").returncode, 0)
        members = self.read("bindings/c/src/c_members.hpp")
        self.assertIn("struct CMembers<geometry::Contact> {\n  using type = cj_contact;\n"
                      "  static constexpr std::size_t fields[] = {5, 6, 2, 3, 4, 0, 8, 9, 10, 1, 7};\n"
                      "  static constexpr std::tuple members{\n      &cj_contact::type,\n"
                      "      &cj_contact::base,\n      &cj_contact::p_WCj,", members)
        self.assertIn("      Whole{&cj_contact::crossings, &cj_contact::crossing_count},\n", members)

    def test_a_field_added_to_a_result_makes_the_check_fail_on_the_c_members(self):
        self.run_generator("--write")
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "plain", "value": "float"})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertEqual(check.returncode, 1)
        self.assertIn("+      &cj_contact::trial};", check.stdout)
        self.assertIn("+  static constexpr std::size_t fields[] = {5, 6, 2, 3, 4, 0, 8, 9, 10, 1, 7, 11};",
                      check.stdout)
        self.assertIn("bindings/c/src/c_members.hpp", check.stdout.split("stale:")[1])

    def test_a_field_added_to_a_result_is_written_by_the_c_and_fortran_equivalence_writers_after_the_certificate(self):
        self.run_generator("--write")
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "plain", "value": "float"})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertIn('  if (with_text) add(line, " \\"%s\\"", c->certificate.reason_text);\n'
                      '+  add_hex(line, c->trial);', check.stdout)
        self.assertIn("tests/bindings/equivalence/contact_line.h", check.stdout.split("stale:")[1])
        self.assertIn("reason_text)//'\"'\n+    line = line//hex(c%trial)\n", check.stdout)
        self.assertIn("tests/bindings/equivalence/contact_line.inc", check.stdout.split("stale:")[1])

    def test_a_field_added_to_a_result_is_set_by_the_mex_results_after_the_others(self):
        self.run_generator("--write")
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "plain", "value": "float"})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertIn('"crossings", "certificate", "trial"', check.stdout)
        self.assertIn("+    mxSetFieldByNumber(out, k, 11, mxCreateDoubleScalar(c->trial));", check.stdout)
        self.assertIn("bindings/matlab/mex_results.c", check.stdout.split("stale:")[1])

    def test_a_field_added_to_a_result_takes_the_room_of_its_reserved_members(self):
        self.run_generator("--write")
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "plain", "value": "float"})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertEqual(check.returncode, 1)
        self.assertIn("-  double reserved[4];\n+  double trial;\n+  double reserved[3];", check.stdout)
        self.assertIn("+    real(c_double) :: trial\n", check.stdout)
        self.assertIn("bindings/fortran/clearjoint.f90", check.stdout.split("stale:")[1])

    def test_a_field_that_does_not_fit_the_reserved_room_is_an_error_naming_the_abi(self):
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "plain", "value": "vector3"})
        grown["results"][0]["fields"].append({"key": "other", "doc": "", "kind": "plain", "value": "vector3"})
        self.set_description(grown)
        run = self.run_generator("--check")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("cj_contact: no reserved room left for the new field other", run.stderr)
        self.assertIn("CJ_ABI_VERSION", run.stderr)

    def test_a_field_removed_from_a_result_is_an_error_naming_the_abi(self):
        shrunk = description()
        shrunk["results"][0]["fields"] = [f for f in shrunk["results"][0]["fields"] if f["key"] != "normal"]
        self.set_description(shrunk)
        run = self.run_generator("--check")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("the field list of Contact no longer has normal", run.stderr)

    def test_the_schema_lists_every_field_of_a_result_as_the_command_writes_it(self):
        self.assertEqual(self.run_generator("--write").returncode, 0)
        contact = json.loads(self.read("docs/schema/detect-answer.schema.json"))["$defs"]["contact"]
        self.assertEqual(contact["properties"]["depth"], {"type": "number"})
        self.assertEqual(contact["properties"]["depth_error"], {"$ref": "#/$defs/error_bound"})
        self.assertEqual(contact["properties"]["crossings"]["maxItems"], 2)
        self.assertEqual(contact["properties"]["certificate_reason"], {"type": "string"})
        self.assertIn("crossing_errors", contact["required"])
        self.assertIn("point_journal", contact["required"])

    def test_a_field_added_to_a_result_makes_the_check_fail_on_the_schema(self):
        self.run_generator("--write")
        grown = description()
        grown["results"][0]["fields"].append({"key": "trial", "doc": "", "kind": "plain", "value": "bool"})
        self.set_description(grown)
        check = self.run_generator("--check")
        self.assertIn('+        "trial": {\n+          "type": "boolean"', check.stdout)
        self.assertIn("docs/schema/detect-answer.schema.json", check.stdout.split("stale:")[1])

    def test_a_field_removed_from_a_result_leaves_the_schema_and_the_command_s_own_keys_stay(self):
        sys.path.insert(0, os.path.dirname(GENERATOR))
        import schema_results
        schema = {"$defs": {"contact": {"required": ["depth", "gone", "approach_velocity"], "properties": {
            "depth": {"type": "number"}, "gone": {"type": "number"},
            "approach_velocity": {"type": "number", "description": "kept"}}}}}
        fields = [{"key": "depth", "doc": "", "kind": "plain", "value": "float"}]
        schema_results.apply(schema, "docs/schema/detect-answer.schema.json",
                             [{"type": "Contact", "fields": fields}], {})
        contact = schema["$defs"]["contact"]
        self.assertEqual(list(contact["properties"]), ["depth", "approach_velocity"])
        self.assertEqual(contact["required"], ["depth", "approach_velocity"])

    def test_detect_help_lists_the_answer_and_contact_keys_of_the_schema(self):
        sys.path.insert(0, os.path.dirname(GENERATOR))
        import schema_results
        schema = {"$defs": {"answer": {"properties": {"v": {}, "id": {}, "contacts": {}}},
                            "contact": {"properties": {"depth": {}, "trial": {}}}}}
        self.assertEqual(schema_results.detect_help_lines(schema),
                         ['    "  {\\"v\\": 1, \\"id\\", \\"contacts\\": [{\\"depth\\", \\"trial\\"}]}\\n"'])

    def test_a_file_without_its_markers_is_an_error_naming_it(self):
        self.write("bindings/fortran/clearjoint.f90", "module clearjoint\nend module\n")
        run = self.run_generator("--check")
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("bindings/fortran/clearjoint.f90: needs one 'BEGIN GENERATED enums' line", run.stderr)


if __name__ == "__main__":
    unittest.main()
