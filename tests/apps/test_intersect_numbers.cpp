// SPDX-License-Identifier: BSD-3-Clause
// `clearjoint intersect` on the shipped example (examples/rims.jsonl): the numbers it prints,
// crossing points and depths, against values derived by hand from each line's geometry
// (intersect_command_test.cmake checks the topologies, counts and certificate levels).

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// The answers to examples/rims.jsonl, by id.
std::map<std::string, json> answers() {
  const fs::path dir = fs::path(CLEARJOINT_TEST_WORK_DIR);
  fs::create_directories(dir);
  // One file per process: ctest runs each case in a process of its own, in parallel.
  const fs::path out = dir / ("rims_answers_" + std::to_string(getpid()) + ".jsonl");
  const std::string command = "\"" CLEARJOINT_PROGRAM "\" intersect \"" CLEARJOINT_SOURCE_DIR
                              "/examples/rims.jsonl\" > \"" + out.string() + "\"";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  std::map<std::string, json> by_id;
  std::ifstream in(out);
  for (std::string line; std::getline(in, line);) {
    const json answer = json::parse(line);
    by_id[answer.at("id").get<std::string>()] = answer;
  }
  in.close();
  fs::remove(out);
  return by_id;
}

struct Point {
  double x, y, z;
};

double distance(const json& point, const Point& p) {
  return std::hypot(point.at(0).get<double>() - p.x, point.at(1).get<double>() - p.y,
                    point.at(2).get<double>() - p.z);
}

// The hand-derived points are evaluated in double from square roots of integers below 1e8:
// within ~1e-12 of the true points, themselves ~1e4 from the origin.
constexpr double kHandRounding = 1e-11;

/// Each expected point matches one crossing, within the crossing's own point_error (the
/// certificate's promise) plus the rounding of the hand value.
void expect_crossings_at(const json& answer, const std::vector<Point>& expected) {
  const json& crossings = answer.at("crossings");
  ASSERT_EQ(crossings.size(), expected.size()) << answer.dump();
  for (const Point& p : expected) {
    bool found = false;
    for (const json& c : crossings) {
      const double error = c.at("point_error").get<double>();
      if (distance(c.at("point"), p) <= error + kHandRounding) found = true;
    }
    EXPECT_TRUE(found) << "no crossing within its point_error of (" << p.x << ", " << p.y << ", " << p.z
                       << ") in " << answer.dump();
  }
}

class IntersectExample : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { answers_ = new std::map<std::string, json>(answers()); }
  static void TearDownTestSuite() { delete answers_; }
  static const json& answer(const std::string& id) { return answers_->at(id); }
  static std::map<std::string, json>* answers_;
};
std::map<std::string, json>* IntersectExample::answers_ = nullptr;

TEST_F(IntersectExample, TiltedBaseCrossesThePlaneWhereTheRimsPlaneMeetsIt) {
  // Rim centre (0, 0, 9950), normal (0, 1, 100), radius 9900; plane z = 10000. A common point
  // has n . (p - c) = y + 100 (z - 9950) = 0, so y = -5000, and |p - c| = 9900, so
  // x^2 = 9900^2 - 5000^2 - 50^2 = 73,007,500.
  const double x = std::sqrt(73007500.0);
  const json& a = answer("base-B-tilted-crossing");
  expect_crossings_at(a, {{-x, -5000, 10000}, {x, -5000, 10000}});
  // Deepest rim point: c + r (the rim-plane direction closest to +z), whose z component is
  // sqrt(1 - n_z^2) = 1 / sqrt(10001): depth 9950 + 9900 / sqrt(10001) - 10000.
  EXPECT_NEAR(a.at("max_signed_distance").get<double>(), 9900 / std::sqrt(10001.0) - 50, 1e-10);
  // Its mirror image at base A: the same depth.
  EXPECT_NEAR(answer("base-A-tilted-crossing").at("max_signed_distance").get<double>(),
              9900 / std::sqrt(10001.0) - 50, 1e-10);
  expect_crossings_at(answer("base-A-tilted-crossing"), {{-x, 5000, -10000}, {x, 5000, -10000}});
}

TEST_F(IntersectExample, NominalBaseLiesOneHundredBelowThePlane) {
  EXPECT_EQ(answer("base-B-nominal").at("max_signed_distance").get<double>(), -100.0);  // 9900 - 10000
}

TEST_F(IntersectExample, ExactTangenciesTouchAtTheirHandDerivedPoints) {
  // Plane normal (0, 199, 19800) through (0, 0, 10000), flat rim at z = 9900.5 of radius 9900:
  // the rim point farthest along the normal is (0, 9900, 9900.5), where
  // 199 * 9900 + 19800 * (9900.5 - 10000) = 1,970,100 - 1,970,100 = 0: a tangency.
  expect_crossings_at(answer("base-B-exact-tangent"), {{0, 9900, 9900.5}});
  EXPECT_EQ(answer("base-B-exact-tangent").at("max_signed_distance").get<double>(), 0.0);
  // A flat rim of radius 9900 centred 100 off the axis of a radius-10000 wall: (10000, 0, 9900).
  expect_crossings_at(answer("wall-B-exact-tangent"), {{10000, 0, 9900}});
}

TEST_F(IntersectExample, RimAcrossTheWallCrossesItAtFourHandDerivedPoints) {
  // Rim in the plane x = 2000 (centre (2000, 0, 0), radius 9900); wall x^2 + y^2 = 10000^2:
  // y^2 = 1e8 - 4e6 = 96,000,000 and z^2 = 9900^2 - y^2 = 2,010,000.
  const double y = std::sqrt(96000000.0), z = std::sqrt(2010000.0);
  expect_crossings_at(answer("wall-four-crossings"),
                      {{2000, y, z}, {2000, -y, z}, {2000, y, -z}, {2000, -y, -z}});
}

}  // namespace
