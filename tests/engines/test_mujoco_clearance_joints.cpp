// SPDX-License-Identifier: BSD-3-Clause
// Clearance joints in MuJoCo (engines/mujoco): the example slider-cranks against clearjoint's own
// runs of the same mechanisms (models/slider_crank_planar_clearance_aligned.json; the pin-in-hole
// example against models/slider_crank_planar_clearance_pin_in_hole.json with its pin tilted as in
// the example), and the errors that name a bad declaration.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include <unistd.h>

#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/mujoco/clearance_joints.hpp"

namespace clearjoint::mujoco {
namespace {

constexpr size_t kComparedImpacts = 10;
constexpr double kImpactSpeedTolerance = 2e-2;  // relative (issue 35)
constexpr double kReferenceTolerance = 1e-10;   // clearjoint's run
constexpr double kReferenceDuration = 0.005;   // [s]: the first 10 impacts end by 2.4 ms
constexpr double kLongestRun = kReferenceDuration;  // [s] of MuJoCo time at most

const std::string kExample = std::string(CLEARJOINT_MUJOCO_EXAMPLES_DIR) + "/slider_crank_planar_clearance.xml";
const std::string kPinExample =
    std::string(CLEARJOINT_MUJOCO_EXAMPLES_DIR) + "/slider_crank_planar_pin_in_hole_misaligned.xml";
/// The pin's tilt in kPinExample: 0.3 degrees from the rod's zeta towards its eta.
constexpr double kPinTilt = 0.3 * std::numbers::pi / 180.0;  // [rad]

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPointer = std::unique_ptr<mjModel, ModelDeleter>;

ModelPointer load(const std::string& path) {
  char error[1000] = "";
  ModelPointer model(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  if (!model) ADD_FAILURE() << path << ": " << error;
  return model;
}

/// clearjoint's own run of `model_file` (models/) for kReferenceDuration; `edit` changes the
/// description first.
std::vector<dynamics::RecordedImpact> clearjoint_impacts(
    const std::string& model_file = "slider_crank_planar_clearance_aligned.json",
    const std::function<void(dynamics::ModelDescription&)>& edit = {}) {
  dynamics::ModelDescription model = dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + model_file);
  if (edit) edit(model);
  model.solver.relative_tolerance = model.solver.absolute_tolerance = kReferenceTolerance;
  model.solver.end_time = kReferenceDuration;
  model.solver.report_step = model.solver.end_time;
  dynamics::BuiltModel built = dynamics::build_model(model);
  std::vector<double> y = built.initial_state;
  dynamics::integrate(*built.system, y, model.solver, [](double, std::span<const double>) {});
  return dynamic_cast<const dynamics::ClearanceRevoluteJoint&>(*built.system->force_elements().back())
      .recorded_impacts();
}

/// The impacts the example's single clearance joint records in MuJoCo, stepped from its first
/// keyframe until kComparedImpacts of them or kLongestRun of simulated time.
std::vector<dynamics::RecordedImpact> first_mujoco_impacts(const mjModel* model) {
  ClearanceJoints clearance(model);
  EXPECT_EQ(clearance.count(), 1);
  std::unique_ptr<mjData, DataDeleter> data(mj_makeData(model));
  mj_resetDataKeyframe(model, data.get(), 0);
  clearance.install();
  mj_forward(model, data.get());
  clearance.after_step(data.get());
  const auto& impacts = clearance.joint(0).recorded_impacts();
  while (impacts.size() < kComparedImpacts && data->time < kLongestRun) {
    mj_step(model, data.get());
    clearance.after_step(data.get());
  }
  return impacts;
}

/// Expects the first kComparedImpacts impacts in the same slots as the reference's, their speeds
/// within kImpactSpeedTolerance; returns the worst relative speed and the worst instant apart.
std::pair<double, double> compare_first_impacts(const std::vector<dynamics::RecordedImpact>& impacts,
                                                const std::vector<dynamics::RecordedImpact>& reference) {
  double worst_speed = 0.0;
  double worst_time = 0.0;
  for (size_t k = 0; k < kComparedImpacts; ++k) {
    EXPECT_EQ(impacts[k].slot, reference[k].slot) << "impact " << k;
    EXPECT_NEAR(impacts[k].impact_speed, reference[k].impact_speed,
                kImpactSpeedTolerance * reference[k].impact_speed)
        << "impact " << k << " at t = " << reference[k].time;
    worst_speed = std::max(worst_speed, std::abs(impacts[k].impact_speed / reference[k].impact_speed - 1.0));
    worst_time = std::max(worst_time, std::abs(impacts[k].time - reference[k].time));
  }
  return {worst_speed, worst_time};
}

TEST(MujocoClearanceJoints, ExampleSliderCranksFirstImpactSpeedsAgreeWithClearjoint) {
  const std::vector<dynamics::RecordedImpact> reference = clearjoint_impacts();
  ASSERT_GE(reference.size(), kComparedImpacts);

  const ModelPointer model = load(kExample);
  ASSERT_TRUE(model);
  const std::vector<dynamics::RecordedImpact> impacts = first_mujoco_impacts(model.get());
  ASSERT_GE(impacts.size(), kComparedImpacts);
  const auto [worst_speed, worst_time] = compare_first_impacts(impacts, reference);
  // The figures of docs/engines.md.
  std::printf("MuJoCo RK4 at %.3g s against clearjoint at %.3g: first %zu impact speeds within "
              "%.2g (relative), instants within %.2g s\n",
              model->opt.timestep, kReferenceTolerance, kComparedImpacts, worst_speed, worst_time);
}

TEST(MujocoClearanceJoints, OnlyAfterStepChangesTheImpactMemoryNeverAnIntegratorStage) {
  const ModelPointer model = load(kExample);
  ASSERT_TRUE(model);
  ClearanceJoints clearance(model.get());
  std::unique_ptr<mjData, DataDeleter> data(mj_makeData(model.get()));
  mj_resetDataKeyframe(model.get(), data.get(), 0);
  clearance.install();
  mj_forward(model.get(), data.get());
  clearance.after_step(data.get());
  // Up to the first impact: its speed is remembered.
  while (clearance.joint(0).recorded_impacts().empty() && data->time < kLongestRun) {
    mj_step(model.get(), data.get());
    clearance.after_step(data.get());
  }
  ASSERT_EQ(clearance.joint(0).recorded_impacts().size(), 1u);
  const std::vector<double> remembered(clearance.impact_memory(0).begin(), clearance.impact_memory(0).end());
  // Ten RK4 steps (forty force evaluations) deeper into the contact without after_step: the
  // passive-force callback reads the memory and never writes it.
  for (int k = 0; k < 10; ++k) mj_step(model.get(), data.get());
  EXPECT_TRUE(std::equal(remembered.begin(), remembered.end(), clearance.impact_memory(0).begin()));
  // The same contact at the next accepted state: nothing new to record.
  EXPECT_FALSE(clearance.after_step(data.get()));
  EXPECT_EQ(clearance.joint(0).recorded_impacts().size(), 1u);
}

/// The example with `from` replaced by `to`, written to a temporary file; the error its
/// ClearanceJoints throws, or "no error"; `field_path` receives the error's field_path().
std::string error_for_edited_example(const std::string& from, const std::string& to,
                                     std::string* field_path = nullptr, const std::string& example = kExample) {
  std::ifstream in(example);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find(from);
  if (at == std::string::npos) return "example has no " + from;
  text.replace(at, from.size(), to);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("clearjoint_mujoco_test_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << text;
  const ModelPointer model = load(path.string());
  std::filesystem::remove(path);
  if (!model) return "MuJoCo refused the edited model";
  try {
    ClearanceJoints clearance(model.get());
  } catch (const ModelError& e) {
    if (field_path != nullptr) *field_path = e.field_path();
    return e.what();
  }
  return "no error";
}

TEST(MujocoClearanceJoints, NamesASiteThatDoesNotExist) {
  const std::string error = error_for_edited_example(
      "data=\"rod_slider.bearing rod_slider.journal\"", "data=\"rod_slider.bearing no_such_site\"");
  EXPECT_NE(error.find("no_such_site"), std::string::npos) << error;
  EXPECT_NE(error.find("clearance:rod_slider"), std::string::npos) << error;
}

TEST(MujocoClearanceJoints, NamesDimensionsThatFailTheJointsChecks) {
  const std::string error = error_for_edited_example("data=\"0.01 0.02 0.0099 0.0198\"",
                                                     "data=\"0.01 0.02 0.0101 0.0198\"");
  EXPECT_NE(error.find("rod_slider.journal.radius"), std::string::npos) << error;
}

TEST(MujocoClearanceJoints, KeepsTheFieldPathOfTheJointsChecksBesideTheDeclaration) {
  // The declaration was pasted into the message, and the field's path was lost.
  std::string path;
  const std::string error = error_for_edited_example("data=\"0.01 0.02 0.0099 0.0198\"",
                                                     "data=\"0.01 0.02 0.0101 0.0198\"", &path);
  EXPECT_EQ(path, "rod_slider.journal.radius") << error;
  EXPECT_TRUE(error.starts_with("<text name=\"clearance:rod_slider\">: rod_slider.journal.radius = "))
      << error;
}

TEST(MujocoClearanceJoints, RefusesABadDeclarationAsTheProjectsBadInputError) {
  // One catch of clearjoint::ValidationError handles every engine's bad model.
  static_assert(std::is_base_of_v<ValidationError, ModelError>);
  static_assert(std::is_base_of_v<dynamics::ModelError, ModelError>);
  std::string path = "unset";
  const std::string error = error_for_edited_example("clearance:rod_slider:friction", "clearance:rod_slider:frictoin",
                                                     &path);
  EXPECT_NE(error.find("unknown field"), std::string::npos) << error;
  EXPECT_EQ(path, "") << "an element of the adapter's own is named in the message, not as a model field";
}

TEST(MujocoClearanceJoints, NamesAMissingDimensionsElement) {
  const std::string error = error_for_edited_example("clearance:rod_slider:dimensions", "something_else");
  EXPECT_NE(error.find("clearance:rod_slider:dimensions"), std::string::npos) << error;
}

TEST(MujocoClearanceJoints, NamesAnUnknownForceLaw) {
  const std::string error = error_for_edited_example("data=\"lankarani_nikravesh\"", "data=\"hooke\"");
  EXPECT_NE(error.find("hooke"), std::string::npos) << error;
}

TEST(MujocoClearanceJoints, NamesAMisspeltFieldAndTheKnownOnes) {
  // A misspelt optional field left the joint at paper Table 2's friction without a word.
  const std::string error = error_for_edited_example("clearance:rod_slider:friction", "clearance:rod_slider:frictoin");
  EXPECT_NE(error.find("<numeric name=\"clearance:rod_slider:frictoin\">: unknown field \"frictoin\""),
            std::string::npos) << error;
  EXPECT_NE(error.find("dimensions, normal_force, friction, parallel_angle_tolerance"), std::string::npos) << error;
}

TEST(MujocoClearanceJoints, NamesAFieldOfAJointThatIsNotDeclared) {
  const std::string error = error_for_edited_example("clearance:rod_slider:normal_force\"",
                                                     "clearance:rod_slidr:normal_force\"");
  EXPECT_NE(error.find("no clearance joint \"rod_slidr\" is declared"), std::string::npos) << error;
  EXPECT_NE(error.find("the declared ones: \"rod_slider\""), std::string::npos) << error;
}

TEST(MujocoClearanceJoints, RefusesAnOilFilmNamingItsElementAndWhereFilmsRun) {
  // A viscosity was refused as an unknown field, as if misspelt, without saying that no film runs
  // here.
  for (const std::string element : {"<numeric name=\"clearance:rod_slider:viscosity\" data=\"0.04\"/>",
                                    "<text name=\"clearance:rod_slider:cavitation\" data=\"half_sommerfeld\"/>"}) {
    const std::string error = error_for_edited_example("  <custom>\n", "  <custom>\n" + element);
    const std::string name = element.substr(1, element.find("\" data") - 1);
    EXPECT_NE(error.find(name + "\">: lubricated clearance joints are not supported by the MuJoCo adapter"),
              std::string::npos) << error;
    EXPECT_NE(error.find("--engine simbody"), std::string::npos) << error;
  }
}

TEST(MujocoClearanceJoints, NamesAFieldGivenAsTheWrongElement) {
  const std::string error =
      error_for_edited_example("<text name=\"clearance:rod_slider:normal_force_model\" data=\"lankarani_nikravesh\"",
                               "<numeric name=\"clearance:rod_slider:normal_force_model\" data=\"1\"");
  EXPECT_NE(error.find("\"normal_force_model\" must be a <text> element"), std::string::npos) << error;
}

}  // namespace
}  // namespace clearjoint::mujoco

namespace clearjoint::mujoco {
namespace {

// The pin-in-hole joint (issue 48): its declaration, its refusals and its run.

/// kPinExample with `from` replaced by `to`: the error its ClearanceJoints throws, or "no error".
std::string error_for_edited_pin_example(const std::string& from, const std::string& to,
                                         std::string* field_path = nullptr) {
  return error_for_edited_example(from, to, field_path, kPinExample);
}

constexpr const char* kPinData = "data=\"0.01 0.02 0.0099 0.0101 0.015 -0.0101 0.015\"";

TEST(MujocoPinInHoleJoints, ReadsTheDimensionsInTheModelFilesOrder) {
  const ModelPointer model = load(kPinExample);
  ASSERT_TRUE(model);
  const ClearanceJoints clearance(model.get());
  ASSERT_EQ(clearance.count(), 1);
  const auto& pin = clearance.joint(0).parameters().pin_in_hole;
  ASSERT_TRUE(pin.has_value()) << "read as the paper's joint";
  // The example's data: Rh L Rp, then (position, outer_radius) for each head.
  EXPECT_EQ(pin->hole_radius, 0.01);
  EXPECT_EQ(pin->hole_length, 0.02);
  EXPECT_EQ(pin->pin_radius, 0.0099);
  ASSERT_EQ(pin->stop_count, 2);
  EXPECT_EQ(pin->stops[0].position, 0.0101);
  EXPECT_EQ(pin->stops[0].outer_radius, 0.015);
  EXPECT_EQ(pin->stops[1].position, -0.0101);
  EXPECT_EQ(pin->stops[1].outer_radius, 0.015);
}

TEST(MujocoPinInHoleJoints, ReadsOneStopOrNoneFromFiveOrThreeValues) {
  for (const auto& [data, stops] : {std::pair<std::string, int>{"0.01 0.02 0.0099 -0.0101 0.015", 1},
                                    std::pair<std::string, int>{"0.01 0.02 0.0099", 0}}) {
    std::ifstream in(kPinExample);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find(kPinData), std::string(kPinData).size(), "data=\"" + data + "\"");
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("clearjoint_mujoco_pin_test_" + std::to_string(::getpid()) + ".xml");
    std::ofstream(path) << text;
    const ModelPointer model = load(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(model);
    const ClearanceJoints clearance(model.get());
    const auto& pin = clearance.joint(0).parameters().pin_in_hole;
    ASSERT_TRUE(pin.has_value());
    EXPECT_EQ(pin->stop_count, stops) << data;
    if (stops == 1) {
      EXPECT_EQ(pin->stops[0].position, -0.0101);
      EXPECT_EQ(pin->stops[0].outer_radius, 0.015);
    }
  }
}

TEST(MujocoPinInHoleJoints, RefusesAPinThickerThanItsHoleNamingTheElementFieldAndValue) {
  std::string path;
  const std::string error = error_for_edited_pin_example(
      kPinData, "data=\"0.01 0.02 0.0101 0.0101 0.015 -0.0101 0.015\"", &path);
  EXPECT_TRUE(error.starts_with("<numeric name=\"clearance:rod_slider:pin_in_hole\">: "
                                "rod_slider.pin.radius = 0.0101: must be smaller than hole.radius = 0.01"))
      << error;
  EXPECT_EQ(path, "rod_slider.pin.radius") << error;
}

TEST(MujocoPinInHoleJoints, RefusesAStopInsideTheHoleNamingIt) {
  std::string path;
  const std::string error = error_for_edited_pin_example(
      kPinData, "data=\"0.01 0.02 0.0099 0.0101 0.015 -0.005 0.015\"", &path);
  EXPECT_NE(error.find("rod_slider.pin.stops[1].position = -0.005: the stop lies inside the hole"),
            std::string::npos) << error;
  EXPECT_EQ(path, "rod_slider.pin.stops[1].position") << error;
}

TEST(MujocoPinInHoleJoints, RefusesAStopNoLargerThanTheHoleNamingIt) {
  const std::string error = error_for_edited_pin_example(
      kPinData, "data=\"0.01 0.02 0.0099 0.0101 0.01 -0.0101 0.015\"");
  EXPECT_NE(error.find("rod_slider.pin.stops[0].outer_radius = 0.01: must be larger than hole.radius"),
            std::string::npos) << error;
}

TEST(MujocoPinInHoleJoints, RefusesANonFiniteSizeNamingIt) {
  // MJCF's numeric data cannot spell NaN; a program that builds or edits the model in memory can.
  const ModelPointer model = load(kPinExample);
  ASSERT_TRUE(model);
  const int id = mj_name2id(model.get(), mjOBJ_NUMERIC, "clearance:rod_slider:pin_in_hole");
  ASSERT_GE(id, 0);
  model->numeric_data[model->numeric_adr[id] + 1] = std::numeric_limits<double>::quiet_NaN();
  try {
    ClearanceJoints clearance(model.get());
    ADD_FAILURE() << "a NaN hole length was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.field_path(), "rod_slider.hole.length") << e.what();
    EXPECT_TRUE(std::string(e.what()).starts_with("<numeric name=\"clearance:rod_slider:pin_in_hole\">: "
                                                  "rod_slider.hole.length = nan"))
        << e.what();
  }
}

TEST(MujocoPinInHoleJoints, RefusesAWrongNumberOfValuesSayingWhatTheyAre) {
  for (const std::string data : {"0.01 0.02 0.0099 0.0101 0.015 -0.0101", "0.01 0.02",
                                 "0.01 0.02 0.0099 0.0101 0.015 -0.0101 0.015 0.02 0.015"}) {
    const std::string error = error_for_edited_pin_example(kPinData, "data=\"" + data + "\"");
    EXPECT_NE(error.find("<numeric name=\"clearance:rod_slider:pin_in_hole\">: holds "), std::string::npos) << error;
    EXPECT_NE(error.find("values, needs 3, 5 or 7: hole.radius hole.length pin.radius"), std::string::npos) << error;
  }
}

TEST(MujocoPinInHoleJoints, RefusesAnOilFilmOnAPinAsTheModelFileDoes) {
  for (const std::string element : {"<numeric name=\"clearance:rod_slider:viscosity\" data=\"0.04\"/>",
                                    "<text name=\"clearance:rod_slider:lubrication\" data=\"on\"/>"}) {
    const std::string error = error_for_edited_pin_example("  <custom>\n", "  <custom>\n" + element);
    const std::string name = element.substr(1, element.find("\" data") - 1);
    EXPECT_NE(error.find(name + "\">: an oil film is not supported with geometry \"pin_in_hole\""),
              std::string::npos) << error;
  }
}

TEST(MujocoPinInHoleJoints, RefusesAnUnknownGeometryNamingIt) {
  const std::string error = error_for_edited_pin_example("data=\"pin_in_hole\"", "data=\"pin_in_bore\"");
  EXPECT_NE(error.find("<text name=\"clearance:rod_slider:geometry\">: \"pin_in_bore\": must be "
                       "\"journal_bearing\" (the paper's joint, the default) or \"pin_in_hole\""),
            std::string::npos) << error;
}

TEST(MujocoPinInHoleJoints, RefusesAPinsSizesWithoutItsGeometryAndTheJournalsWithIt) {
  // Without geometry "pin_in_hole" the joint is the paper's: a pin_in_hole element would be ignored.
  const std::string without = error_for_edited_pin_example(
      "<text name=\"clearance:rod_slider:geometry\" data=\"pin_in_hole\"/>", "");
  EXPECT_NE(without.find("<numeric name=\"clearance:rod_slider:pin_in_hole\">: needs <text "
                         "name=\"clearance:rod_slider:geometry\" data=\"pin_in_hole\"/>"),
            std::string::npos) << without;
  const std::string both = error_for_edited_pin_example(
      "  <custom>\n", "  <custom>\n<numeric name=\"clearance:rod_slider:dimensions\" data=\"0.01 0.02 0.0099 0.0198\"/>");
  EXPECT_NE(both.find("<numeric name=\"clearance:rod_slider:dimensions\">: not used with geometry \"pin_in_hole\""),
            std::string::npos) << both;
  const std::string missing = error_for_edited_pin_example("clearance:rod_slider:pin_in_hole", "something_else");
  EXPECT_NE(missing.find("<text name=\"clearance:rod_slider\">: geometry \"pin_in_hole\" needs <numeric "
                         "name=\"clearance:rod_slider:pin_in_hole\""),
            std::string::npos) << missing;
}

TEST(MujocoPinInHoleJoints, MisalignedPinExamplesFirstImpactsAgreeWithClearjointAndLoadAnEdge) {
  // clearjoint's run of the shipped pin-in-hole model with the pin tilted as in the example.
  const std::vector<dynamics::RecordedImpact> reference =
      clearjoint_impacts("slider_crank_planar_clearance_pin_in_hole.json", [](dynamics::ModelDescription& m) {
        auto& joint = std::get<dynamics::ClearanceRevoluteDescription>(m.forces.back());
        joint.journal.axis_B = dynamics::Vector3(0.0, std::sin(kPinTilt), std::cos(kPinTilt));
      });
  ASSERT_GE(reference.size(), kComparedImpacts);

  const ModelPointer model = load(kPinExample);
  ASSERT_TRUE(model);
  const std::vector<dynamics::RecordedImpact> impacts = first_mujoco_impacts(model.get());
  ASSERT_GE(impacts.size(), kComparedImpacts);
  const auto [worst_speed, worst_time] = compare_first_impacts(impacts, reference);
  int edge_impacts = 0;
  for (size_t k = 0; k < kComparedImpacts; ++k) {
    edge_impacts += impacts[k].slot == dynamics::ContactSlot::radial_a || impacts[k].slot == dynamics::ContactSlot::radial_b;
  }
  // The tilt makes the hole's edges, not the line along the bore, take the impacts.
  EXPECT_GE(edge_impacts, 1);
  std::printf("MuJoCo RK4 at %.3g s against clearjoint at %.3g, misaligned pin in hole: first %zu impact speeds "
              "within %.2g (relative), instants within %.2g s; %d at an edge\n",
              model->opt.timestep, kReferenceTolerance, kComparedImpacts, worst_speed, worst_time, edge_impacts);
}

}  // namespace
}  // namespace clearjoint::mujoco
