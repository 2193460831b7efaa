// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_overrides.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"

namespace clearjoint::dynamics {
namespace {

// Two bodies so that an element other than the first can be addressed; no solver.end_time, so
// that setting a field the file leaves out is covered.
const char* kModel = R"({
  "bodies": [{"name": "a", "mass": 1.5, "inertia": [1, 2, 3], "position": [0, 0, 1]},
             {"name": "b", "mass": 2.5, "inertia": [1, 1, 1], "position": [0, 0, 2]}],
  "solver": {"report_step": 0.01}
})";

ModelDescription with(const ModelOverrides& overrides, const char* model = kModel) {
  return parse_model(apply_overrides(model, "m.json", overrides), "m.json");
}

/// The message of the ModelError that applying and reading `overrides` throws.
std::string error_of(const ModelOverrides& overrides) {
  try {
    with(overrides);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

std::string assignment_error(const std::string& text) {
  try {
    parse_override_assignment(text, "--set " + text);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ModelOverrides, SetAFieldTheFileLeavesOutByADottedPathOrAPointer) {
  // The default end time is not 0.25 (integrator_settings.hpp): the value read is the one set.
  ASSERT_NE(parse_model(kModel, "m.json").solver.end_time, 0.25);
  EXPECT_EQ(with({{"solver.end_time", "0.25", ""}}).solver.end_time, 0.25);
  EXPECT_EQ(with({{"/solver/end_time", "0.25", ""}}).solver.end_time, 0.25);
}

TEST(ModelOverrides, SetAnArrayElementAndLeaveTheOthersAsTheFileHasThem) {
  const ModelDescription dotted = with({{"bodies[1].mass", "7", ""}, {"bodies[0].position[2]", "-3", ""}});
  EXPECT_EQ(dotted.bodies[1].properties.mass, 7.0);
  EXPECT_EQ(dotted.bodies[0].properties.mass, 1.5);
  EXPECT_EQ(dotted.bodies[0].initial.position_W, Vector3(0, 0, -3));
  EXPECT_EQ(with({{"/bodies/1/mass", "7", ""}}).bodies[1].properties.mass, 7.0);
}

TEST(ModelOverrides, CreateAMissingObjectOnTheWay) {
  const char* no_solver = R"({"bodies": [{"name": "a", "mass": 1, "inertia": [1, 1, 1], "position": [0, 0, 0]}]})";
  EXPECT_EQ(with({{"solver.end_time", "0.125", ""}}, no_solver).solver.end_time, 0.125);
}

TEST(ModelOverrides, ReplaceAWholeArray) {
  EXPECT_EQ(with({{"gravity", "[0, -9.81, 0]", ""}}).gravity_W, Vector3(0, -9.81, 0));
}

TEST(ModelOverrides, LeaveAMisspeltKeyToTheReaderWhichListsTheKnownOnes) {
  // The reader's list of the solver's fields grows with its methods; the message's start and the
  // field the user meant are what this checks.
  const std::string error = error_of({{"solver.end_tme", "1", "--set solver.end_tme=1"}});
  EXPECT_EQ(error.rfind("m.json: solver.end_tme: unknown field (expected start_time, end_time, ", 0), 0u)
      << error;
  EXPECT_EQ(error.back(), ')') << error;
}

TEST(ModelOverrides, NameAValueOfTheWrongTypeByItsField) {
  EXPECT_EQ(error_of({{"bodies[1].mass", "\"heavy\"", ""}}), "m.json: bodies[1].mass = \"heavy\": must be a number");
  EXPECT_EQ(error_of({{"gravity", "[0, 0]", ""}}), "m.json: gravity = [0,0]: must be an array of 3 numbers");
}

TEST(ModelOverrides, RefuseAnElementPastTheEndOfAnArray) {
  EXPECT_EQ(error_of({{"bodies[5].mass", "1", "--set bodies[5].mass=1"}}),
            "--set bodies[5].mass=1: bodies has 2 elements, [0] to [1]: there is no [5]");
}

TEST(ModelOverrides, RefuseAKeyOnAnArraySayingHowToWriteTheElement) {
  EXPECT_EQ(error_of({{"bodies.1.mass", "1", ""}}), "bodies.1.mass: bodies is an array: write its elements as bodies[1]");
}

TEST(ModelOverrides, RefuseAnElementOfAnObject) {
  EXPECT_EQ(error_of({{"solver[0]", "1", ""}}),
            "solver[0]: solver is an object, not an array: [0] names no member (members: report_step)");
}

TEST(ModelOverrides, RefuseAMissingArrayNamingTheMembersThereAre) {
  EXPECT_EQ(error_of({{"bodys[0].mass", "1", ""}}), "bodys[0].mass: the model has no member bodys (members: bodies, solver)");
}

TEST(ModelOverrides, RefuseAPathThroughANumber) {
  EXPECT_EQ(error_of({{"bodies[0].mass.x", "1", ""}}),
            "bodies[0].mass.x: bodies[0].mass is a number, which has no member or element x");
}

TEST(ModelOverrides, RefuseMalformedPaths) {
  EXPECT_NE(error_of({{"solver..end_time", "1", ""}}).find("malformed path: an empty key at character 8"), std::string::npos);
  EXPECT_NE(error_of({{"bodies[1", "1", ""}}).find("malformed path: '[' without ']'"), std::string::npos);
  EXPECT_NE(error_of({{"solver.", "1", ""}}).find("malformed path: it ends with '.'"), std::string::npos);
  EXPECT_EQ(error_of({{"bodies[x].mass", "1", ""}}), "bodies[x].mass: [x]: an array element is a whole number, from 0");
  EXPECT_EQ(error_of({{"/bodies/01/mass", "1", ""}}), "/bodies/01/mass: [01]: an array element is a whole number, from 0");
}

TEST(ModelOverrides, RefuseTheSameFieldSetTwiceHoweverItIsWritten) {
  EXPECT_EQ(error_of({{"solver.end_time", "1", "--end-time 1"}, {"/solver/end_time", "2", "--set /solver/end_time=2"}}),
            "--set /solver/end_time=2: sets solver.end_time, which --end-time 1 sets too");
}

TEST(ModelOverrides, RefuseAFieldInsideAnotherSetOne) {
  EXPECT_EQ(error_of({{"solver", "{\"end_time\": 1}", ""}, {"solver.end_time", "2", ""}}),
            "solver.end_time: sets solver.end_time, which overlaps solver set by solver");
  EXPECT_EQ(error_of({{"bodies[0].mass", "2", ""}, {"bodies[0]", "{}", ""}}),
            "bodies[0]: sets bodies[0], which overlaps bodies[0].mass set by bodies[0].mass");
}

TEST(ModelOverrides, ReadTheValueOfAnAssignmentAsJson) {
  EXPECT_EQ(parse_override_assignment("solver.end_time=1e-3", "-").value, "1e-3");
  EXPECT_EQ(parse_override_assignment("gravity=[0, 0, -1]", "-").value, "[0, 0, -1]");
  EXPECT_EQ(parse_override_assignment("name=\"a=b\"", "-").path, "name");
  EXPECT_EQ(parse_override_assignment("name=\"a=b\"", "-").value, "\"a=b\"");
  EXPECT_EQ(parse_override_assignment("x=true", "-").value, "true");
}

TEST(ModelOverrides, ReadABareWordAsAString) {
  EXPECT_EQ(parse_override_assignment("forces[0].normal_force.model=hertz", "-").value, "\"hertz\"");
  // A word is a string even where a number belongs; the reader then names the field.
  EXPECT_EQ(error_of({parse_override_assignment("solver.end_time=soon", "-")}),
            "m.json: solver.end_time = \"soon\": must be a number");
}

TEST(ModelOverrides, RefuseAnAssignmentWithoutPathOrValueOrWithAValueThatIsNotJson) {
  EXPECT_EQ(assignment_error("solver.end_time"), "--set solver.end_time: must be PATH=VALUE, e.g. solver.end_time=0.01");
  EXPECT_NE(assignment_error("=1").find("no PATH before '='"), std::string::npos);
  EXPECT_NE(assignment_error("solver.end_time=").find("no VALUE after '='"), std::string::npos);
  EXPECT_NE(assignment_error("solver.end_time=.5").find("--set solver.end_time=.5: the VALUE is not JSON"),
            std::string::npos);
  EXPECT_NE(assignment_error("gravity=[0, 0").find("the VALUE is not JSON"), std::string::npos);
}

TEST(ModelOverrides, RefuseAValueThatIsNotJsonNamingTheOverride) {
  EXPECT_NE(error_of({{"solver.end_time", "1e400", "overrides['solver.end_time']"}})
                .find("overrides['solver.end_time']: the value: malformed JSON: number overflow"),
            std::string::npos);
}

TEST(ModelOverrides, NameTheSourceOfAMalformedModel) {
  EXPECT_NE(error_of({}).find("no error"), std::string::npos);
  try {
    apply_overrides("{\"bodies\": [", "m.json", {{"solver.end_time", "1", ""}});
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("m.json: malformed JSON", 0), 0u) << e.what();
  }
}

TEST(ModelOverrides, RecordTheOverridesAsAJsonObjectInTheOrderGiven) {
  EXPECT_EQ(overrides_json({{"solver.end_time", "0.25", ""}, {"bodies[1].mass", "7", ""}, {"n", "\"x\"", ""}}),
            R"({"solver.end_time":0.25,"bodies[1].mass":7,"n":"x"})");
  EXPECT_EQ(overrides_json({}), "{}");
}

}  // namespace
}  // namespace clearjoint::dynamics
