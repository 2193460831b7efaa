// SPDX-License-Identifier: BSD-3-Clause
// Writes the inputs of the equivalence test (README.md in this folder): the detection test
// cases of every scenario, bad inputs and option variants (answered one call each), then
// random realistic poses (answered by each language's batch call).
//
// usage: write_equivalence_inputs FILE [RANDOM_POSES]

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "tilted_journal_scenarios.hpp"

namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

/// One input record: 19 doubles (README.md).
struct Record {
  geo::JointDimensions dims;
  geo::PartPose bearing;
  geo::PartPose journal;
  double certify = 1.0;
  double parallel_angle_tolerance = 0.0;
  double exact_fallback = 1.0;
};

void append(std::vector<double>& out, const Record& r) {
  const double values[19] = {r.dims.bearing_radius, r.dims.bearing_length, r.dims.journal_radius,
                             r.dims.journal_length, r.bearing.p_WP.x(), r.bearing.p_WP.y(),
                             r.bearing.p_WP.z(), r.bearing.axis_W.x(), r.bearing.axis_W.y(),
                             r.bearing.axis_W.z(), r.journal.p_WP.x(), r.journal.p_WP.y(),
                             r.journal.p_WP.z(), r.journal.axis_W.x(), r.journal.axis_W.y(),
                             r.journal.axis_W.z(), r.certify, r.parallel_angle_tolerance,
                             r.exact_fallback};
  out.insert(out.end(), values, values + 19);
}

/// The configurations of tests/geometry/joint/test_detect_contacts.cpp, one per scenario and
/// the model's limits, then option variants and bad inputs.
std::vector<Record> test_cases() {
  using clearjoint::geometry::testing::bearing_on_z;
  using clearjoint::geometry::testing::kMisalignedCases;
  using clearjoint::geometry::testing::kTable2;
  using clearjoint::geometry::testing::TiltedJournal;
  const geo::PartPose bearing = bearing_on_z();
  std::vector<Record> cases;
  for (const auto& c : kMisalignedCases) cases.push_back({c.dimensions, bearing, c.journal.pose()});
  const auto aligned = [&](Vector3 centre, Vector3 axis) {
    cases.push_back({kTable2, bearing, {centre, axis}});
  };
  aligned({0.0, 0.0, 0.0}, Vector3::UnitZ());          // none, centred
  aligned({0.01, 0.02, 0.03}, Vector3::UnitZ());       // none
  aligned({0.0, 0.15, 0.02}, Vector3::UnitZ());        // (j) line
  aligned({0.03, 0.04, 0.13}, Vector3::UnitZ());       // (k) face
  aligned({0.0, 0.15, -0.13}, -Vector3::UnitZ());      // (l) line and face
  aligned({0.0, 0.25, 0.0}, Vector3::UnitZ());         // beyond: line deeper than cr
  aligned({0.0, 0.0, 0.0}, Vector3(0.0, 0.0, 3.0));    // exactly parallel, non-unit axis
  cases.push_back({kTable2, bearing, TiltedJournal{0.2, 0.0, 0.005}.pose()});   // beyond: deep radial
  cases.push_back({kTable2, bearing, TiltedJournal{1.3, 0.0, 0.001}.pose()});   // beyond: half-rim arcs
  cases.push_back({kTable2, bearing, TiltedJournal{0.0, 0.5, 0.005}.pose()});   // beyond: rim past a base
  cases.push_back({{10.0, 20.0, 9.9, 2.0}, bearing,
                   TiltedJournal{1.0 - std::sin(0.5), 0.0, 0.5}.pose()});       // four wall crossings
  cases.push_back({kTable2, bearing,                                             // rims wholly beyond
                   {Vector3(kTable2.bearing_radius + kTable2.journal_radius + 1e-3, 0.0, 0.0),
                    Vector3(std::sin(1e-3), 0.0, std::cos(1e-3))}});
  // Options: nearly parallel axes treated as parallel (uncertain), certificates off.
  cases.push_back({kTable2, bearing, TiltedJournal{0.15, 0.0, 1e-6}.pose()});
  cases.push_back({kTable2, bearing, TiltedJournal{0.15, 0.0, 1e-6}.pose(), 1.0, 1e-5});
  cases.push_back({kTable2, bearing, TiltedJournal{0.0, 0.0, 0.013}.pose(), 0.0});
  cases.push_back({kTable2, bearing, {Vector3(0.0, 0.15, 0.02), Vector3::UnitZ()}, 0.0});
  // The exact fallback off: a journal touching the wall along a line (eccentricity exactly cr),
  // which only the exact tier proves clear, with and without it.
  const geo::JointDimensions eighths{0.5, 1.0, 0.375, 0.75};
  cases.push_back({eighths, bearing, {Vector3(0.0, 0.125, 0.0), Vector3::UnitZ()}});
  cases.push_back({eighths, bearing, {Vector3(0.0, 0.125, 0.0), Vector3::UnitZ()}, 1.0, 0.0, 0.0});
  // A moved, rotated bearing.
  cases.push_back({kTable2, {Vector3(1.5, -2.0, 0.25), Vector3(0.3, -0.4, 0.866)},
                   {Vector3(1.5, -1.9, 0.3), Vector3(0.3, -0.39, 0.87)}});
  // Bad inputs, one field each.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const geo::PartPose centred{Vector3::Zero(), Vector3::UnitZ()};
  cases.push_back({{-10.0, 20.0, 9.9, 19.8}, bearing, centred});
  cases.push_back({{10.0, nan, 9.9, 19.8}, bearing, centred});
  cases.push_back({{10.0, 20.0, 10.0, 19.8}, bearing, centred});
  cases.push_back({{10.0, 20.0, 9.9, 21.0}, bearing, centred});
  cases.push_back({{10.0, 20.0, 0.0, 19.8}, bearing, centred});
  cases.push_back({kTable2, bearing, {Vector3::Zero(), Vector3::Zero()}});
  cases.push_back({kTable2, {Vector3(inf, 0.0, 0.0), Vector3::UnitZ()}, centred});
  cases.push_back({kTable2, bearing, {Vector3(0.0, nan, 0.0), Vector3::UnitZ()}});
  cases.push_back({kTable2, {Vector3::Zero(), Vector3(0.0, -inf, 1.0)}, centred});
  cases.push_back({kTable2, bearing, centred, 1.0, -1e-3});
  cases.push_back({kTable2, bearing, centred, 1.0, nan});
  cases.push_back({kTable2, bearing, centred, 1.0, 2.0});
  return cases;
}

/// A unit quaternion uniform on the sphere (Shoemake), as a rotation matrix.
Eigen::Matrix3d random_rotation(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double u1 = unit(random), u2 = 2 * std::numbers::pi * unit(random), u3 = 2 * std::numbers::pi * unit(random);
  const Eigen::Quaterniond q(std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2),
                             std::sqrt(1 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3));
  return q.toRotationMatrix();
}

/// Poses a multibody simulation of the paper's joint (Table 2, metres) meets: the journal off
/// the bearing axis by up to 1.5 cr and along it by up to 1.5 ca, tilted by up to 2 cr / Lj; the
/// whole joint then moved by a random rotation and a translation of up to 1 m. About half of
/// them are in contact.
std::vector<Record> random_poses(std::size_t count) {
  const geo::JointDimensions table2{10.0e-3, 20.0e-3, 9.9e-3, 19.8e-3};
  const double cr = table2.radial_clearance(), ca = table2.axial_clearance();
  const double max_tilt = 2.0 * cr / table2.journal_length;
  std::mt19937_64 random(20170824);
  std::uniform_real_distribution<double> unit(0.0, 1.0), symmetric(-1.0, 1.0);
  std::vector<Record> out;
  for (std::size_t k = 0; k < count; ++k) {
    const double radial = 1.5 * cr * std::sqrt(unit(random)), azimuth = 2 * std::numbers::pi * unit(random);
    const double tilt = max_tilt * unit(random), tilt_azimuth = 2 * std::numbers::pi * unit(random);
    const Vector3 centre(radial * std::cos(azimuth), radial * std::sin(azimuth), 1.5 * ca * symmetric(random));
    const Vector3 axis(std::sin(tilt) * std::cos(tilt_azimuth), std::sin(tilt) * std::sin(tilt_azimuth),
                       std::cos(tilt));
    const Eigen::Matrix3d rotation = random_rotation(random);
    const Vector3 shift(symmetric(random), symmetric(random), symmetric(random));
    out.push_back({table2, {shift, rotation * Vector3::UnitZ()}, {shift + rotation * centre, rotation * axis}});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s FILE [RANDOM_POSES]\n", argv[0]);
    return 2;
  }
  const std::size_t random_count = argc == 3 ? std::strtoul(argv[2], nullptr, 10) : 10000;
  const std::vector<Record> singles = test_cases();
  const std::vector<Record> batch = random_poses(random_count);
  std::vector<double> data(19, 0.0);
  data[0] = static_cast<double>(singles.size() + batch.size());
  data[1] = static_cast<double>(singles.size());
  for (const Record& r : singles) append(data, r);
  for (const Record& r : batch) append(data, r);
  std::FILE* file = std::fopen(argv[1], "wb");
  if (file == nullptr || std::fwrite(data.data(), sizeof(double), data.size(), file) != data.size() ||
      std::fclose(file) != 0) {
    std::fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[1]);
    return 1;
  }
  std::printf("%zu single-call records, %zu batch records\n", singles.size(), batch.size());
  return 0;
}
