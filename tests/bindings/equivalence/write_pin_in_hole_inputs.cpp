// SPDX-License-Identifier: BSD-3-Clause
// Writes the inputs of the pin-in-hole equivalence test (README.md in this folder, "The
// pin-in-hole joint"): the shipped scenario examples, option variants and bad inputs, then
// random realistic poses, near-parallel ones among them, one joint and the default options: the
// records the batch calls answer.
//
// usage: write_pin_in_hole_inputs EXAMPLES FILE [RANDOM_POSES]

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "pin_in_hole_examples.hpp"

namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

constexpr std::size_t kRecord = 23;

/// One input record: 23 doubles (README.md).
struct Record {
  geo::PinInHoleDimensions dims;
  geo::PartPose hole;
  geo::PartPose pin;
  double certify = 1.0;
  double parallel_angle_tolerance = 0.0;
  double exact_fallback = 1.0;
};

void append(std::vector<double>& out, const Record& r) {
  const geo::PinInHoleDimensions& d = r.dims;
  const double values[kRecord] = {d.hole_radius, d.hole_length, d.pin_radius, static_cast<double>(d.stop_count),
                                  d.stops[0].position, d.stops[0].outer_radius, d.stops[1].position,
                                  d.stops[1].outer_radius, r.hole.p_WP.x(), r.hole.p_WP.y(), r.hole.p_WP.z(),
                                  r.hole.axis_W.x(), r.hole.axis_W.y(), r.hole.axis_W.z(), r.pin.p_WP.x(),
                                  r.pin.p_WP.y(), r.pin.p_WP.z(), r.pin.axis_W.x(), r.pin.axis_W.y(),
                                  r.pin.axis_W.z(), r.certify, r.parallel_angle_tolerance, r.exact_fallback};
  out.insert(out.end(), values, values + kRecord);
}

/// The examples' joint: hole radius 10 mm, length 20 mm, pin radius 9.5 mm, heads at +-11.5 mm of
/// outer radius 13 mm (metres).
geo::PinInHoleDimensions example_joint() {
  geo::PinInHoleDimensions d;
  d.hole_radius = 0.01;
  d.hole_length = 0.02;
  d.pin_radius = 0.0095;
  d.stops[0] = {-0.0115, 0.013};
  d.stops[1] = {0.0115, 0.013};
  d.stop_count = 2;
  return d;
}

/// The shipped examples, one per scenario, then option variants, stop counts and bad inputs.
std::vector<Record> test_cases(const char* examples) {
  std::vector<Record> cases;
  for (const auto& e : clearjoint::testing::read_pin_in_hole_examples(examples)) {
    cases.push_back({e.dimensions, e.hole, e.pin});
  }
  const geo::PartPose hole{Vector3::Zero(), Vector3::UnitZ()};
  const geo::PinInHoleDimensions joint = example_joint();
  // Nearly parallel: within a 1e-5 rad tolerance (uncertain line), and exactly; certificates off.
  const geo::PartPose nearly{Vector3(0.0, 0.0008, 0.0), Vector3(0.0, 1e-6, 1.0)};
  cases.push_back({joint, hole, nearly});
  cases.push_back({joint, hole, nearly, 1.0, 1e-5});
  cases.push_back({joint, hole, {Vector3::Zero(), Vector3(0.0, 0.07, 1.0)}, 0.0});
  cases.push_back({joint, hole, {Vector3(0.0, 0.0004, 0.0), Vector3(0.0, -0.03, 1.0)}, 1.0, 0.0, 0.0});
  // One stop and none; a moved, rotated hole.
  geo::PinInHoleDimensions one = joint, none = joint;
  one.stop_count = 1;
  none.stop_count = 0;
  cases.push_back({one, hole, {Vector3(0.0, 0.0, -0.003), Vector3(0.0, 0.03, 1.0)}});
  cases.push_back({none, hole, {Vector3(0.0, 0.0, 0.004), Vector3(0.0, 0.07, 1.0)}});
  cases.push_back({joint, {Vector3(1.5, -2.0, 0.25), Vector3(0.3, -0.4, 0.866)},
                   {Vector3(1.5, -1.9996, 0.2502), Vector3(0.3, -0.39, 0.87)}});
  // Bad inputs, one field each (a stop count outside [0, 2] is not among them: Octave's stops are
  // the rows of a matrix; tests/bindings/c/test_c_pin_in_hole.cpp has it).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const geo::PartPose centred{Vector3::Zero(), Vector3::UnitZ()};
  const auto bad = [&](auto change) {
    geo::PinInHoleDimensions d = joint;
    change(d);
    cases.push_back({d, hole, centred});
  };
  bad([](geo::PinInHoleDimensions& d) { d.pin_radius = 0.01; });            // as thick as the hole
  bad([](geo::PinInHoleDimensions& d) { d.pin_radius = -0.0095; });
  bad([&](geo::PinInHoleDimensions& d) { d.hole_length = nan; });
  bad([](geo::PinInHoleDimensions& d) { d.hole_radius = 1e200; });          // out of the accepted range
  bad([](geo::PinInHoleDimensions& d) { d.stops[1].position = 0.005; });     // inside the hole
  bad([](geo::PinInHoleDimensions& d) { d.stops[0].outer_radius = 0.009; }); // smaller than the hole
  bad([](geo::PinInHoleDimensions& d) { d.stops[1].position = -0.012; });    // both on one side
  cases.push_back({joint, hole, {Vector3::Zero(), Vector3::Zero()}});
  cases.push_back({joint, {Vector3(inf, 0.0, 0.0), Vector3::UnitZ()}, centred});
  cases.push_back({joint, hole, {Vector3(0.0, nan, 0.0), Vector3::UnitZ()}});
  cases.push_back({joint, hole, centred, 1.0, -1e-3});
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

/// The examples' joint in the poses a simulation meets: the pin off the hole's axis by up to
/// 1.5 cr and along it by up to 1.5 ca, tilted by up to 2 cr / L (one pose in four by at most
/// 1e-9 rad: near-parallel); the whole joint moved by a random rotation and a translation of up to
/// 1 m.
std::vector<Record> random_poses(std::size_t count) {
  const geo::PinInHoleDimensions joint = example_joint();
  const double cr = joint.radial_clearance(), ca = joint.axial_clearance();
  const double max_tilt = 2.0 * cr / joint.hole_length;
  std::mt19937_64 random(48);
  std::uniform_real_distribution<double> unit(0.0, 1.0), symmetric(-1.0, 1.0);
  std::vector<Record> out;
  for (std::size_t k = 0; k < count; ++k) {
    const double radial = 1.5 * cr * std::sqrt(unit(random)), azimuth = 2 * std::numbers::pi * unit(random);
    const double tilt = (k % 4 == 3 ? 1e-9 : max_tilt) * unit(random);
    const double tilt_azimuth = 2 * std::numbers::pi * unit(random);
    const Vector3 centre(radial * std::cos(azimuth), radial * std::sin(azimuth), 1.5 * ca * symmetric(random));
    const Vector3 axis(std::sin(tilt) * std::cos(tilt_azimuth), std::sin(tilt) * std::sin(tilt_azimuth),
                       std::cos(tilt));
    const Eigen::Matrix3d rotation = random_rotation(random);
    const Vector3 shift(symmetric(random), symmetric(random), symmetric(random));
    out.push_back({joint, {shift, rotation * Vector3::UnitZ()}, {shift + rotation * centre, rotation * axis}});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s EXAMPLES FILE [RANDOM_POSES]\n", argv[0]);
    return 2;
  }
  const std::size_t random_count = argc == 4 ? std::strtoul(argv[3], nullptr, 10) : 2000;
  const std::vector<Record> cases = test_cases(argv[1]);
  const std::vector<Record> random = random_poses(random_count);
  std::vector<double> data(kRecord, 0.0);
  data[0] = static_cast<double>(cases.size() + random.size());
  data[1] = static_cast<double>(cases.size());  // the random poses after them: the batch calls'
  for (const Record& r : cases) append(data, r);
  for (const Record& r : random) append(data, r);
  std::FILE* file = std::fopen(argv[2], "wb");
  if (file == nullptr || std::fwrite(data.data(), sizeof(double), data.size(), file) != data.size() ||
      std::fclose(file) != 0) {
    std::fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[2]);
    return 1;
  }
  std::printf("%zu test cases, %zu random poses\n", cases.size(), random.size());
  return 0;
}
