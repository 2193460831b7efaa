#include "clearjoint/dynamics/model_file.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {
namespace {

const char* kMinimal = R"({
  "bodies": [{"name": "ball", "mass": 1.5, "inertia": [1, 2, 3], "position": [0, 0, 1]}],
  "solver": {"end_time": 0.5, "report_step": 0.01}
})";

std::string error_of(const std::string& json) {
  try {
    parse_model(json, "m.json");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ModelFile, ReadsAMinimalModelWithDefaults) {
  const ModelDescription m = parse_model(kMinimal, "m.json");
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].properties.mass, 1.5);
  EXPECT_EQ(m.bodies[0].initial.euler_parameters, Vector4(1, 0, 0, 0));
  EXPECT_EQ(m.solver.end_time, 0.5);
  EXPECT_EQ(m.solver.relative_tolerance, 1e-7);
  EXPECT_EQ(m.output_bodies, std::vector<std::string>{"ball"});
}

TEST(ModelFile, NamesTheFieldAndValueOfANonPositiveMass) {
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mass": -2, "inertia": [1,1,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].mass = -2: must be positive");
}

TEST(ModelFile, NamesANonPositiveInertia) {
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mass": 2, "inertia": [1,0,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].inertia[1] = 0: must be positive");
}

TEST(ModelFile, RejectsNonNumbersWhereNumbersBelong) {
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mass": "heavy", "inertia": [1,1,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].mass = \"heavy\": must be a number");
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mass": 1, "inertia": [1,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].inertia = [1,1]: must be an array of 3 numbers");
}

TEST(ModelFile, RejectsUnknownKeysAsLikelyTypos) {
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mas": 1, "inertia": [1,1,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].mas: unknown key (a typo?)");
}

TEST(ModelFile, RejectsUnknownJointTypes) {
  const std::string e = error_of(R"({"bodies": [], "joints": [{"name": "j", "type": "screw", "body_i": "a", "body_j": "b"}]})");
  EXPECT_NE(e.find("joints[0].type = \"screw\": unknown joint type"), std::string::npos) << e;
}

TEST(ModelFile, ReportsMalformedJson) {
  EXPECT_NE(error_of("{\"bodies\": [").find("m.json: not valid JSON"), std::string::npos);
}

TEST(ModelFile, ReportsAMissingFile) {
  EXPECT_THROW(read_model_file("/nonexistent/model.json"), ModelError);
}

TEST(ModelFile, RejectsAnEndTimeBeforeTheStart) {
  EXPECT_EQ(error_of(R"({"bodies": [], "solver": {"end_time": -1}})"),
            "m.json: solver.end_time = -1: must be after solver.start_time = 0");
}

TEST(ModelFile, ReadsTheShippedModels) {
  for (const char* file : {"slider_crank_planar_ideal.json", "slider_crank_spatial_ideal.json"}) {
    const ModelDescription m = read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
    EXPECT_EQ(m.bodies.size(), 3u) << file;
    EXPECT_EQ(m.joints.size(), 4u) << file;
    EXPECT_FALSE(m.notes.empty()) << file;
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
