// SPDX-License-Identifier: BSD-3-Clause
#include "answer_families.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <string>

#include <Eigen/Geometry>

#include "answer_text.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "uniform_source.hpp"

namespace clearjoint::bench {
namespace {

namespace geo = clearjoint::geometry;
using geo::Vector3;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Paper Table 2, in metres.
constexpr geo::JointDimensions kTable2{.bearing_radius = 10.0e-3,
                                       .bearing_length = 20.0e-3,
                                       .journal_radius = 9.9e-3,
                                       .journal_length = 19.8e-3};
// A large radial clearance (cr = 0.2, ca = 0.1) on a short journal, and a long journal in a
// bearing twice its radius (cr = 0.5, ca = 0.5): tilts up to 0.5 and 1/3 rad.
constexpr geo::JointDimensions kShortJournal{.bearing_radius = 1.0,
                                             .bearing_length = 0.5,
                                             .journal_radius = 0.8,
                                             .journal_length = 0.3};
constexpr geo::JointDimensions kLongJournal{.bearing_radius = 1.0,
                                            .bearing_length = 4.0,
                                            .journal_radius = 0.5,
                                            .journal_length = 3.0};

// The families and their counts are those of the scratch dump every refactor of November 2026 was
// checked with (192,000 lines); the seeds are new, one a family.
const AnswerFamily kFamilies[] = {
    {"table2", "Table 2, centre up to 1.5 cr off the axis and 1.5 ca along it, any tilt", 4242,
     20000, JointPoses{kTable2, 1.5, 1.5, 1.0, false, 1.0}},
    {"table2_close", "Table 2, centre up to 1.1 cr and 1.1 ca: more poses close to touching", 4243,
     10000, JointPoses{kTable2, 1.1, 1.1, 1.0, false, 1.0}},
    {"table2_aligned", "Table 2, axes parallel (journal axis +z or -z)", 4244, 3000,
     JointPoses{kTable2, 1.5, 1.5, 0.0, false, 1.0}},
    {"table2_moved", "Table 2, joint rotated and translated, 30 % of journal axes of length 1.7",
     4245, 10000, JointPoses{kTable2, 1.5, 1.5, 1.0, true, 1.0}},
    {"table2_moved_x1e3", "table2_moved with every length times 1e3", 4246, 5000,
     JointPoses{kTable2, 1.5, 1.5, 1.0, true, 1e3}},
    {"table2_moved_x1e-4", "table2_moved with every length times 1e-4", 4247, 5000,
     JointPoses{kTable2, 1.5, 1.5, 1.0, true, 1e-4}},
    {"short_journal_moved", "Ri 1, Rj 0.8, Li 0.5, Lj 0.3, centre up to 1.3 cr and 1.3 ca, moved",
     4248, 10000, JointPoses{kShortJournal, 1.3, 1.3, 1.0, true, 1.0}},
    {"long_journal", "Ri 1, Rj 0.5, Li 4, Lj 3, centre up to 1.3 cr and 1.3 ca", 4249, 10000,
     JointPoses{kLongJournal, 1.3, 1.3, 1.0, false, 1.0}},
    {"kernel_random", "random rims against a wall and a plane, scales 2^-20..2^20", 4250, 20000,
     RandomRims{}},
    {"near_tangent", "rims touching the unit wall to within 4 ulps, and their joints", 4251, 3000,
     NearTangentRims{}},
};

// Components drawn one statement at a time: the order in which a constructor's arguments are
// evaluated is unspecified, and the inputs must not depend on the compiler.
Vector3 uniform_vector(UniformSource& uniform, double low, double high) {
  Vector3 v;
  v.x() = uniform(low, high);
  v.y() = uniform(low, high);
  v.z() = uniform(low, high);
  return v;
}

// A whole number uniform in [low, high].
int uniform_integer(UniformSource& uniform, int low, int high) {
  return static_cast<int>(std::floor(uniform(low, high + 1.0)));
}

// Builds "<family> <input> <query>", then the query's answer or what it threw, and hands the line
// to the sink. `line` is reused to keep its capacity.
template <class Query>
void print_answer(const LineSink& sink, std::string& line, const AnswerFamily& family, int input,
                  std::string_view query, Query&& answer_of) {
  line.assign(family.name);
  line += ' ';
  line += std::to_string(input);
  line += ' ';
  line += query;
  try {
    append_answer(line, answer_of());
  } catch (const std::exception& error) {
    append_exception(line, error);
  }
  sink(line);
}

void print_joint_poses(const AnswerFamily& family, const JointPoses& poses, const LineSink& sink,
                       int input_count) {
  UniformSource uniform(family.seed);
  const geo::JointDimensions& d = poses.dimensions;
  const double cr = d.radial_clearance(), ca = d.axial_clearance();
  const double max_tilt = poses.tilt_share * std::min(2.0 * cr / d.journal_length, 0.5);
  const double s = poses.scale;
  const geo::JointDimensions dimensions{d.bearing_radius * s, d.bearing_length * s,
                                        d.journal_radius * s, d.journal_length * s};
  const geo::DetectionOptions uncertified{.intersection = {.certify = false}};
  geo::JointContacts reused;
  std::string line;
  for (int input = 0; input < input_count; ++input) {
    // Journal pose in the bearing's frame B (centre at the origin, axis +z).
    const double offset = uniform(0.0, poses.offset_in_cr * cr);
    const double offset_azimuth = uniform(0.0, kTwoPi);
    const double shift = uniform(-poses.shift_in_ca * ca, poses.shift_in_ca * ca);
    const double tilt = uniform(0.0, max_tilt);
    const double tilt_azimuth = uniform(0.0, kTwoPi);
    Vector3 p_BJ(offset * std::cos(offset_azimuth), offset * std::sin(offset_azimuth), shift);
    Vector3 axis_J(std::sin(tilt) * std::cos(tilt_azimuth), std::sin(tilt) * std::sin(tilt_azimuth),
                   std::cos(tilt));
    // A reversed journal axis: rim A is then the journal's far end.
    if (uniform(0.0, 1.0) < 0.2) axis_J = -axis_J;
    geo::PartPose bearing{Vector3::Zero(), Vector3::UnitZ()};
    geo::PartPose journal{p_BJ, axis_J};
    if (poses.moved_in_world) {
      const double about_z = uniform(0.0, kTwoPi);
      const double about_x = uniform(0.0, kTwoPi);
      const Vector3 p_WB = uniform_vector(uniform, -1.0, 1.0);
      const Eigen::Matrix3d R_WB = (Eigen::AngleAxisd(about_x, Vector3::UnitX()) *
                                    Eigen::AngleAxisd(about_z, Vector3::UnitZ()))
                                       .toRotationMatrix();
      bearing = {p_WB, R_WB * Vector3::UnitZ()};
      journal = {p_WB + R_WB * p_BJ, R_WB * axis_J};
      if (uniform(0.0, 1.0) < 0.3) journal.axis_W *= 1.7;  // a non-unit axis
    }
    bearing.p_WP *= s;
    journal.p_WP *= s;
    print_answer(sink, line, family, input, "detect", [&]() -> const geo::JointContacts& {
      geo::detect_contacts(dimensions, bearing, journal, reused);
      return reused;
    });
    print_answer(sink, line, family, input, "detect_uncertified",
                 [&] { return geo::detect_contacts(dimensions, bearing, journal, uncertified); });
  }
}

void print_random_rims(const AnswerFamily& family, const LineSink& sink, int input_count) {
  UniformSource uniform(family.seed);
  std::string line;
  for (int input = 0; input < input_count; ++input) {
    const double s = std::ldexp(1.0, uniform_integer(uniform, -20, 20));
    geo::Circle3 rim;
    rim.center = uniform_vector(uniform, -1.0, 1.0) * s;
    rim.normal = uniform_vector(uniform, -1.0, 1.0);
    rim.radius = uniform(0.1, 1.5) * s;
    geo::Cylinder3 wall;
    wall.axis_point = uniform_vector(uniform, -0.1, 0.1) * s;
    wall.axis.x() = uniform(-0.2, 0.2);
    wall.axis.y() = uniform(-0.2, 0.2);
    wall.axis.z() = 1.0;
    wall.radius = uniform(0.5, 1.5) * s;
    print_answer(sink, line, family, input, "circle_cylinder",
                 [&] { return geo::intersect_circle_cylinder(rim, wall); });
    geo::Plane3 plane;
    plane.point = uniform_vector(uniform, -0.5, 0.5) * s;
    plane.normal = uniform_vector(uniform, -1.0, 1.0);
    print_answer(sink, line, family, input, "circle_plane",
                 [&] { return geo::intersect_circle_plane(rim, plane); });
  }
}

void print_near_tangent_rims(const AnswerFamily& family, const LineSink& sink, int input_count) {
  UniformSource uniform(family.seed);
  const geo::Cylinder3 wall{Vector3::Zero(), Vector3::UnitZ(), 1.0};
  geo::JointContacts reused;
  std::string line;
  for (int input = 0; input < input_count; ++input) {
    const double radius = uniform(0.2, 0.9);
    const double tilt = input % 3 == 0 ? 0.0 : uniform(0.0, 1e-3);
    // The rim's far point at x = centre + radius ~ 1: on the wall to within rounding.
    double centre_x = 1.0 - radius;
    const int ulps = uniform_integer(uniform, -4, 4);
    for (int k = 0; k < std::abs(ulps); ++k) centre_x = std::nextafter(centre_x, ulps > 0 ? 2.0 : 0.0);
    const double centre_z = uniform(-1.0, 1.0);
    const Vector3 normal(std::sin(tilt), 0.0, std::cos(tilt));
    const geo::Circle3 rim{Vector3(centre_x, 0.0, centre_z), normal, radius};
    print_answer(sink, line, family, input, "circle_cylinder",
                 [&] { return geo::intersect_circle_cylinder(rim, wall); });
    // The same rim as a journal's, at its mid-length: its rims touch the wall where this one does.
    const geo::JointDimensions dimensions{1.0, 2.0, radius, 1.8};
    const geo::PartPose bearing{Vector3::Zero(), Vector3::UnitZ()};
    const geo::PartPose journal{Vector3(centre_x, 0.0, 0.0), normal};
    print_answer(sink, line, family, input, "detect", [&]() -> const geo::JointContacts& {
      geo::detect_contacts(dimensions, bearing, journal, reused);
      return reused;
    });
  }
}

}  // namespace

std::span<const AnswerFamily> answer_families() { return kFamilies; }

const AnswerFamily* find_answer_family(std::string_view name) {
  for (const AnswerFamily& family : kFamilies) {
    if (family.name == name) return &family;
  }
  return nullptr;
}

void print_family(const AnswerFamily& family, const LineSink& sink, int input_limit) {
  const int input_count = std::min(family.input_count, input_limit);
  if (const auto* poses = std::get_if<JointPoses>(&family.inputs)) {
    print_joint_poses(family, *poses, sink, input_count);
  } else if (std::holds_alternative<RandomRims>(family.inputs)) {
    print_random_rims(family, sink, input_count);
  } else {
    print_near_tangent_rims(family, sink, input_count);
  }
}

}  // namespace clearjoint::bench
