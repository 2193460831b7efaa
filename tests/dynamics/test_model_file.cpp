// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_file.hpp"

#include <gtest/gtest.h>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/geometry/model/option_fields.hpp"
#include "option_changes.hpp"

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

TEST(ModelFile, ReadsAStepBudgetWholeAndLeavesItsRangeToTheSettingsCheck) {
  const auto with_max_steps = [](const std::string& value) {
    return error_of(R"({"bodies": [{"name": "b", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]}],
                        "solver": {"end_time": 0.5, "report_step": 0.01, "max_steps": )" + value + "}}");
  };
  // A fraction is not a count: refused, not truncated.
  EXPECT_EQ(with_max_steps("2.5"), "m.json: solver.max_steps = 2.5: must be a whole number of steps (at most 2^53 in size)");
  EXPECT_EQ(with_max_steps("1e300").rfind("m.json: solver.max_steps = 1.0000000000000001e+300: must be a whole", 0), 0u);
  // The range is validate(IntegratorSettings)'s, with its words.
  EXPECT_EQ(with_max_steps("0"), "m.json: solver.max_steps = 0: must be in [1, 1e15]");
  EXPECT_EQ(with_max_steps("1000"), "no error");
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

TEST(ModelFile, RejectsUnknownKeysListingTheKnownOnes) {
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mas": 1, "inertia": [1,1,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].mas: unknown field (expected name, mass, inertia, position, "
            "euler_parameters, velocity, angular_velocity)");
}

TEST(ModelFile, RejectsAKeyGivenTwiceNamingItsPath) {
  // The last "gravity" won without a word, and a ball meant to fall floated.
  EXPECT_EQ(error_of(R"({"gravity": [0, 0, -9.81], "bodies": [], "gravity": [0, 0, 0]})"),
            "m.json: gravity: key given twice in one object (each key may appear once)");
  EXPECT_EQ(error_of(R"({"bodies": [{"name": "b", "mass": 1, "mass": 2, "inertia": [1,1,1], "position": [0,0,0]}]})"),
            "m.json: bodies[0].mass: key given twice in one object (each key may appear once)");
}

TEST(ModelFile, AcceptsTheSameKeyInDifferentObjects) {
  const ModelDescription m = parse_model(R"({
    "bodies": [{"name": "a", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]},
               {"name": "b", "mass": 2, "inertia": [1,1,1], "position": [1,0,0]}],
    "solver": {"end_time": 0.5, "report_step": 0.01}})", "m.json");
  EXPECT_EQ(m.bodies.size(), 2u);
}

TEST(ModelFile, RejectsUnknownJointTypes) {
  const std::string e = error_of(R"({"bodies": [], "joints": [{"name": "j", "type": "screw", "body_i": "a", "body_j": "b"}]})");
  EXPECT_NE(e.find("joints[0].type = \"screw\": unknown joint type"), std::string::npos) << e;
}

TEST(ModelFile, ReportsMalformedJson) {
  EXPECT_EQ(error_of("{\"bodies\": [\n"),
            "m.json: malformed JSON: parse error at line 2, column 1: syntax error while parsing value - "
            "unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(error_of(R"({"gravity": [0, 0, 1e400]})"), "m.json: malformed JSON: number overflow parsing '1e400'");
}

TEST(ModelFile, ReportsAMissingFile) {
  EXPECT_THROW(read_model_file("/nonexistent/model.json"), ModelError);
}

TEST(ModelFile, RejectsAnEndTimeBeforeTheStart) {
  EXPECT_EQ(error_of(R"({"bodies": [], "solver": {"end_time": -1}})"),
            "m.json: solver.end_time = -1: must be after solver.start_time = 0");
}

// A journal on body "rod" in a bearing on "slider" (Table 2 sizes); `extra` is spliced into the
// force object.
std::string clearance_model(const std::string& journal_radius, const std::string& extra = "") {
  return R"({"bodies": [{"name": "rod", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]},
                        {"name": "slider", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]}],
  "forces": [{"type": "clearance_revolute", "name": "gap",
    "bearing": {"body": "slider", "axis": [0,0,1], "radius": 0.01, "length": 0.02},
    "journal": {"body": "rod", "point": [0,0.1,0], "axis": [0,0,1], "radius": )" + journal_radius +
         R"(, "length": 0.0198},
    "normal_force": {"model": "lankarani_nikravesh", "stiffness": 1e11, "restitution": 0.9})" +
         extra + "}]}";
}

TEST(ModelFile, ReadsAClearanceJointWithDefaultsForWhatItOmits) {
  const ModelDescription m = parse_model(clearance_model("0.0099"), "m.json");
  ASSERT_EQ(m.forces.size(), 1u);
  const auto& d = std::get<ClearanceRevoluteDescription>(m.forces[0]);
  EXPECT_EQ(d.name, "gap");
  EXPECT_EQ(d.bearing.body, "slider");
  EXPECT_EQ(d.journal.point_B, Vector3(0, 0.1, 0));
  EXPECT_EQ(d.parameters.dimensions.journal_radius, 0.0099);
  EXPECT_EQ(d.parameters.normal.model, NormalForceModel::lankarani_nikravesh);
  EXPECT_EQ(d.parameters.normal.exponent, 1.5);
  EXPECT_EQ(d.parameters.friction.coefficient, 0.0);  // no friction object: frictionless
  EXPECT_EQ(d.parameters.detection.parallel_angle_tolerance, 0.0);
  const ModelDescription with_friction = parse_model(
      clearance_model("0.0099", R"(, "friction": {"coefficient": 0.1, "velocity_coefficient": 500})"), "m.json");
  EXPECT_EQ(std::get<ClearanceRevoluteDescription>(with_friction.forces[0]).parameters.friction.velocity_coefficient, 500.0);
}

TEST(ModelFile, NamesTheFieldOfAJournalNoSmallerThanItsBearing) {
  EXPECT_EQ(error_of(clearance_model("0.01")),
            "m.json: forces[0].journal.radius = 0.01: must be smaller than bearing.radius = 0.01 "
            "(the radial clearance Ri - Rj, eq. 1, must be positive)");
  EXPECT_EQ(error_of(clearance_model("-1")), "m.json: forces[0].journal.radius = -1: must be positive");
}

// A pin on body "rod" through a hole in "slider" (Table 2 clearances, heads 0.1 mm beyond the
// link's faces); `pin_radius` and `extra` (spliced into the force object) vary it.
std::string pin_in_hole_model(const std::string& pin_radius, const std::string& extra = "") {
  return R"({"bodies": [{"name": "rod", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]},
                        {"name": "slider", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]}],
  "forces": [{"type": "clearance_revolute", "name": "pin", "geometry": "pin_in_hole",
    "hole": {"body": "slider", "axis": [0,0,1], "radius": 0.01, "length": 0.02},
    "pin": {"body": "rod", "point": [0,0.1,0], "axis": [0,0,1], "radius": )" + pin_radius +
         R"(, "stops": [{"position": 0.0101, "outer_radius": 0.015}, {"position": -0.0101, "outer_radius": 0.015}]},
    "normal_force": {"model": "lankarani_nikravesh", "stiffness": 1e11, "restitution": 0.9})" +
         extra + "}]}";
}

TEST(ModelFile, ReadsAPinInHoleClearanceJointWithTheHoleAsBearingAndThePinAsJournal) {
  const ModelDescription m = parse_model(pin_in_hole_model("0.0099"), "m.json");
  const auto& d = std::get<ClearanceRevoluteDescription>(m.forces[0]);
  ASSERT_TRUE(d.parameters.pin_in_hole.has_value());
  EXPECT_EQ(d.bearing.body, "slider");
  EXPECT_EQ(d.journal.body, "rod");
  EXPECT_EQ(d.journal.point_B, Vector3(0, 0.1, 0));
  EXPECT_EQ(d.parameters.pin_in_hole->hole_length, 0.02);
  EXPECT_EQ(d.parameters.pin_in_hole->pin_radius, 0.0099);
  EXPECT_EQ(d.parameters.pin_in_hole->stop_count, 2);
  EXPECT_EQ(d.parameters.pin_in_hole->stops[1].position, -0.0101);
}

TEST(ModelFile, NamesTheFieldOfABadPinInHoleJoint) {
  EXPECT_EQ(error_of(pin_in_hole_model("0.01")).rfind("m.json: forces[0].pin.radius = 0.01: must be smaller than", 0),
            0u) << error_of(pin_in_hole_model("0.01"));
  std::string model = pin_in_hole_model("0.0099");
  model.replace(model.find("\"pin_in_hole\""), 13, "\"pin_in_bush\"");
  EXPECT_EQ(error_of(model).rfind("m.json: forces[0].geometry = \"pin_in_bush\": must be \"journal_bearing\"", 0), 0u)
      << error_of(model);
  EXPECT_NE(error_of(pin_in_hole_model("0.0099", R"(, "lubrication": {"viscosity": 0.04, "film_thickness_limit": 1e-6})"))
                .find("forces[0].lubrication: not supported with \"geometry\": \"pin_in_hole\""),
            std::string::npos);
  // The paper's part keys are not the pin-in-hole's.
  model = pin_in_hole_model("0.0099");
  model.replace(model.find("\"hole\""), 6, "\"bearing\"");
  EXPECT_NE(error_of(model).find("forces[0].bearing: unknown field"), std::string::npos) << error_of(model);
}

TEST(ModelFile, RejectsAnUnknownContactLawAndAMisspeltFrictionKey) {
  std::string model = clearance_model("0.0099");
  model.replace(model.find("lankarani_nikravesh"), 19, "kelvin");
  EXPECT_NE(error_of(model).find("forces[0].normal_force.model = \"kelvin\": unknown normal force model"),
            std::string::npos) << error_of(model);
  EXPECT_EQ(error_of(clearance_model("0.0099", R"(, "friction": {"coeficient": 0.1})")),
            "m.json: forces[0].friction.coeficient: unknown field (expected coefficient, velocity_coefficient)");
}

TEST(ModelFile, ReadsEveryDetectionOptionByTheKeyOfTheOptionList) {
  // One option at a time, changed from its default: a member added to DetectionOptions (and so
  // to its option list, which the compiler requires) that the model file cannot set fails here.
  for (int k = 0; k < geometry::kDetectionOptionCount; ++k) {
    const geometry::OptionChange change = geometry::change_one_option(k);
    std::string value;
    geometry::visit_options(change.options, [&](std::string_view key, const auto& v) {
      if (key != change.key) return;
      if constexpr (std::is_same_v<std::decay_t<decltype(v)>, bool>) {
        value = v ? "true" : "false";
      } else {
        value = format_number(v);
      }
    });
    const std::string detection = R"(, "detection": {")" + std::string(change.key) + R"(": )" + value + "}";
    const ModelDescription m = parse_model(clearance_model("0.0099", detection), "m.json");
    const auto& read = std::get<ClearanceRevoluteDescription>(m.forces[0]).parameters.detection;
    EXPECT_EQ(geometry::option_values(read), geometry::option_values(change.options)) << detection;
  }
  EXPECT_EQ(error_of(clearance_model("0.0099", R"(, "detection": {"certfy": false})")),
            "m.json: forces[0].detection.certfy: unknown field (expected certify, exact_fallback, "
            "parallel_angle_tolerance)");
}

TEST(ModelFile, ReadsAClearanceJointsOilFilmWithDefaultsForWhatItOmits) {
  const ModelDescription m = parse_model(
      clearance_model("0.0099", R"(, "lubrication": {"viscosity": 0.04, "film_thickness_limit": 2e-6})"),
      "m.json");
  const auto& l = std::get<ClearanceRevoluteDescription>(m.forces[0]).parameters.lubrication;
  ASSERT_TRUE(l.has_value());
  EXPECT_EQ(l->viscosity, 0.04);
  EXPECT_EQ(l->method, FilmMethod::short_bearing);
  EXPECT_EQ(l->cavitation, lubrication::CavitationModel::half_sommerfeld);
  EXPECT_EQ(l->transition_width, 2e-6);  // as wide as the limit
  EXPECT_FALSE(l->groove_direction_B.has_value());
  const ModelDescription grid = parse_model(
      clearance_model("0.0099", R"(, "lubrication": {"viscosity": 0.04, "film_thickness_limit": 2e-6,
        "method": "grid", "grid": [64, 16], "cavitation": "mass_conserving",
        "groove_direction": [0, 1, 0], "supply_pressure": 1e5, "transition_width": 1e-6})"),
      "m.json");
  const auto& g = *std::get<ClearanceRevoluteDescription>(grid.forces[0]).parameters.lubrication;
  EXPECT_EQ(g.method, FilmMethod::grid);
  EXPECT_EQ(g.circumferential_cells, 64);
  EXPECT_EQ(g.axial_cells, 16);
  EXPECT_EQ(g.cavitation, lubrication::CavitationModel::mass_conserving);
  EXPECT_EQ(*g.groove_direction_B, Vector3::UnitY());
  EXPECT_EQ(g.supply_pressure, 1e5);
  EXPECT_EQ(g.transition_width, 1e-6);
  EXPECT_FALSE(g.allow_large_grid);
}

TEST(ModelFile, RefusesAGridAboveTheSolversCostLimitsUnlessTheFileAllowsIt) {
  const auto model = [](const std::string& extra) {
    return clearance_model("0.0099", R"(, "lubrication": {"viscosity": 0.04, "film_thickness_limit": 2e-6,
        "method": "grid", "grid": [96, 400])" + extra + "}");
  };
  const std::string refused = error_of(model(""));
  EXPECT_NE(refused.find("m.json: forces[0].lubrication.grid = [96, 400]: options.circumferential_cells x "
                         "axial_cells = 96x400: estimated"),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find("allow_large_grid"), std::string::npos) << refused;
  const ModelDescription allowed = parse_model(model(R"(, "allow_large_grid": true)"), "m.json");
  EXPECT_TRUE(std::get<ClearanceRevoluteDescription>(allowed.forces[0]).parameters.lubrication->allow_large_grid);
  EXPECT_EQ(error_of(model(R"(, "allow_large_grid": 1)")),
            "m.json: forces[0].lubrication.allow_large_grid = 1: must be true or false");
}

TEST(ModelFile, NamesTheFieldOfABadOilFilm) {
  const auto lubricated = [](const std::string& fields) {
    return error_of(clearance_model("0.0099", R"(, "lubrication": {)" + fields + "}"));
  };
  EXPECT_EQ(lubricated(R"("viscosity": -0.04, "film_thickness_limit": 2e-6)"),
            "m.json: forces[0].lubrication.viscosity = -0.040000000000000001: must be positive");
  EXPECT_EQ(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 0)"),
            "m.json: forces[0].lubrication.film_thickness_limit = 0: must be positive");
  // Ranges, named where the file gives them (the Table 2 joint's clearance is 1e-4 m).
  EXPECT_EQ(lubricated(R"("viscosity": 1e300, "film_thickness_limit": 2e-6)"),
            "m.json: forces[0].lubrication.viscosity = 1e+300: must be in [1e-06, 1e+06] Pa s "
            "(gases to the stiffest greases)");
  EXPECT_EQ(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 2e-6, "supply_pressure": 1e300)"),
            "m.json: forces[0].lubrication.supply_pressure = 1e+300: must be in [0, 1e+09] Pa "
            "(a gauge pressure; 1 GPa is above any oil feed)");
  EXPECT_NE(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 1e300)")
                .find("m.json: forces[0].lubrication.film_thickness_limit = 1e+300: must be in ["),
            std::string::npos);
  EXPECT_NE(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 2e-6, "transition_width": 1e300)")
                .find("m.json: forces[0].lubrication.transition_width = 1e+300: must be in ["),
            std::string::npos);
  EXPECT_EQ(lubricated(R"("viscosity": 0.04)"),
            "m.json: forces[0].lubrication.film_thickness_limit: missing");
  EXPECT_EQ(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 2e-6, "method": "grid", "grid": [1, 1])"),
            "m.json: forces[0].lubrication.grid = [1, 1]: options.circumferential_cells = 1: must be at least 8");
  EXPECT_EQ(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 2e-6, "grid": [48.5, 12])"),
            "m.json: forces[0].lubrication.grid[0] = 48.5: must be a whole number of cells in [1, 4096]");
  EXPECT_NE(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 2e-6, "method": "finite")")
                .find("forces[0].lubrication.method = \"finite\": unknown film method"),
            std::string::npos);
  EXPECT_EQ(lubricated(R"("viscosity": 0.04, "film_thickness_limit": 2e-6, "viscosty": 1)"),
            "m.json: forces[0].lubrication.viscosty: unknown field (expected viscosity, cavitation, method, "
            "grid, allow_large_grid, groove_direction, supply_pressure, film_thickness_limit, transition_width)");
}

TEST(ModelFile, ReadsASpringDamperAndAPointLoadWithEveryField) {
  const ModelDescription m = parse_model(R"({
    "bodies": [{"name": "a", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]}],
    "forces": [
      {"type": "spring_damper", "name": "s", "body_i": "ground", "body_j": "a", "point_i": [1,2,3],
       "point_j": [4,5,6], "stiffness": 7, "damping": 8, "free_length": 9},
      {"type": "point_load", "name": "p", "body": "a", "point": [0.5,0,0], "force": [0,-2,0],
       "moment": [0,0,3]},
      {"type": "spring_damper", "name": "undamped", "body_i": "a", "body_j": "ground",
       "stiffness": 1, "free_length": 0},
      {"type": "point_load", "name": "pure couple", "body": "a", "moment": [1,0,0]}]})",
                                         "m.json");
  ASSERT_EQ(m.forces.size(), 4u);
  const auto& s = std::get<SpringDamperDescription>(m.forces[0]);
  EXPECT_EQ(s.name, "s");
  EXPECT_EQ(s.body_i, "ground");
  EXPECT_EQ(s.body_j, "a");
  EXPECT_EQ(s.point_i_B, Vector3(1, 2, 3));
  EXPECT_EQ(s.point_j_B, Vector3(4, 5, 6));
  EXPECT_EQ(s.parameters.stiffness, 7.0);
  EXPECT_EQ(s.parameters.damping, 8.0);
  EXPECT_EQ(s.parameters.free_length, 9.0);
  const auto& p = std::get<PointLoadDescription>(m.forces[1]);
  EXPECT_EQ(p.name, "p");
  EXPECT_EQ(p.body, "a");
  EXPECT_EQ(p.point_B, Vector3(0.5, 0, 0));
  EXPECT_EQ(p.force_W, Vector3(0, -2, 0));
  EXPECT_EQ(p.moment_W, Vector3(0, 0, 3));
  // What they omit: damping 0, points at the frame origins, no force or moment.
  const auto& undamped = std::get<SpringDamperDescription>(m.forces[2]);
  EXPECT_EQ(undamped.parameters.damping, 0.0);
  EXPECT_EQ(undamped.point_i_B, Vector3::Zero());
  const auto& couple = std::get<PointLoadDescription>(m.forces[3]);
  EXPECT_EQ(couple.force_W, Vector3::Zero());
  EXPECT_EQ(couple.point_B, Vector3::Zero());
  EXPECT_EQ(couple.moment_W, Vector3(1, 0, 0));
}

TEST(ModelFile, NamesTheMissingStiffnessOfASpringAndAnUnknownForceType) {
  const std::string missing = error_of(R"({"bodies": [], "forces": [{"type": "spring_damper", "name": "s",
      "body_i": "a", "body_j": "b", "free_length": 1}]})");
  EXPECT_NE(missing.find("forces[0].stiffness"), std::string::npos) << missing;
  const std::string unknown = error_of(R"({"bodies": [], "forces": [{"type": "torsion_spring", "name": "t"}]})");
  EXPECT_NE(unknown.find("forces[0].type = \"torsion_spring\": unknown force type"), std::string::npos) << unknown;
  EXPECT_EQ(error_of(R"({"bodies": [], "forces": [{"type": "point_load", "name": "p", "body": "a", "force": [1,2]}]})"),
            "m.json: forces[0].force = [1,2]: must be an array of 3 numbers");
}

TEST(ModelFile, ReadsACylindricalJoint) {
  const ModelDescription m = parse_model(R"({
    "bodies": [{"name": "a", "mass": 1, "inertia": [1,1,1], "position": [0,0,0]}],
    "joints": [{"name": "c", "type": "cylindrical", "body_i": "ground", "body_j": "a",
                "point_i": [0,0,1], "point_j": [0,0,0], "axis_i": [0,1,0], "axis_j": [0,2,0]}]})",
                                         "m.json");
  ASSERT_EQ(m.joints.size(), 1u);
  EXPECT_EQ(m.joints[0].type, JointType::cylindrical);
  EXPECT_EQ(m.joints[0].point_i_B, Vector3(0, 0, 1));
  EXPECT_EQ(m.joints[0].axis_j_B, Vector3(0, 2, 0));
}

TEST(ModelFile, ReadsTheShippedModels) {
  for (const char* file : {"slider_crank_planar_ideal.json", "slider_crank_spatial_ideal.json"}) {
    const ModelDescription m = read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
    EXPECT_EQ(m.bodies.size(), 3u) << file;
    EXPECT_EQ(m.joints.size(), 4u) << file;
    EXPECT_FALSE(m.notes.empty()) << file;
  }
  // The file's decimals (Ri = 0.01, Rj = 0.0097, ...) are each within half an ulp of 0.01 m
  // (8.7e-19 m) of the real values, so a clearance is within ~2e-18 m of its decimal value.
  constexpr double kDecimalRounding = 1e-17;
  for (const char* file : {"slider_crank_planar_clearance_aligned.json",
                           "slider_crank_planar_clearance_misaligned.json",
                           "slider_crank_planar_clearance_lubricated.json",
                           "slider_crank_spatial_clearance.json"}) {
    const ModelDescription m = read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
    EXPECT_EQ(m.joints.size(), 3u) << file;  // the clearance joint is a force element
    ASSERT_EQ(m.forces.size(), 1u) << file;
    const auto& joint = std::get<ClearanceRevoluteDescription>(m.forces[0]);
    EXPECT_NEAR(joint.parameters.dimensions.radial_clearance(), 1e-4, kDecimalRounding) << file;
    EXPECT_NEAR(joint.parameters.dimensions.axial_clearance(), 1e-4, kDecimalRounding) << file;
  }
}

TEST(ModelFile, NamesTheFileAndKeepsTheFieldPathOfABadField) {
  // field_path() was empty once the file's name was put before the message.
  try {
    parse_model(R"({"bodies": [{"name": "ball", "mass": -0.5, "inertia": [1, 1, 1], "position": [0, 0, 0]}]})",
                "ball.json");
    FAIL() << "accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("ball.json: bodies[0].mass = -0.5: must be positive", 0), 0u) << e.what();
    EXPECT_EQ(e.field_path(), "bodies[0].mass");
  }
}

}  // namespace
}  // namespace clearjoint::dynamics
