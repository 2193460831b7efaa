// SPDX-License-Identifier: BSD-3-Clause
#include "input_families.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>

#include "joint_reference.hpp"
#include "uniform_source.hpp"

namespace clearjoint::bench {
namespace {

using geometry::ContactBase;
using geometry::JointDimensions;
using geometry::PartPose;
using geometry::Vector3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = std::numbers::pi;

using clearjoint::bench::UniformSource;

/// A direction uniform on the sphere (Archimedes: z uniform in [-1, 1]), rounded to double.
Vector3 random_direction(UniformSource& uniform) {
  const double z = uniform(-1.0, 1.0);
  const double azimuth = uniform(0.0, 2.0 * kPi);
  const double rho = std::sqrt(1.0 - z * z);
  return {rho * std::cos(azimuth), rho * std::sin(azimuth), z};
}

/// Two unit vectors completing the unit `axis` to a right-handed orthonormal frame.
std::pair<Vector3, Vector3> perpendiculars(const Vector3& axis) {
  const Vector3 p = axis.unitOrthogonal();
  return {p, axis.cross(p)};
}

/// The largest tilt at which a journal centred in its bearing still fits (no contact): the
/// smaller of the radial limit (Lj/2) sin t + Rj cos t = Ri and the axial one
/// (Lj/2) cos t + Rj sin t = Li/2, each solved by bisection on [0, pi/4].
double largest_tilt(const JointDimensions& d) {
  auto solve = [](auto reach_minus_limit) {
    double lo = 0.0, hi = kPi / 4;
    for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (reach_minus_limit(mid) > 0.0 ? hi : lo) = mid;
    }
    return lo;
  };
  const double half_lj = 0.5 * d.journal_length;
  const double radial = solve([&](double t) {
    return half_lj * std::sin(t) + d.journal_radius * std::cos(t) - d.bearing_radius;
  });
  const double axial = solve([&](double t) {
    return half_lj * std::cos(t) + d.journal_radius * std::sin(t) - 0.5 * d.bearing_length;
  });
  return std::min(radial, axial);
}

/// The journal pose in a bearing frame: axis tilted by `tilt` towards azimuth `lean`, centre
/// offset `radial` towards azimuth `toward` and `axial` along the bearing axis. Double arithmetic.
PartPose journal_in_bearing_frame(const PartPose& bearing, double tilt, double lean, double radial,
                                  double toward, double axial) {
  const Vector3 e = bearing.axis_W.normalized();
  const auto [p, q] = perpendiculars(e);
  const Vector3 axis = std::cos(tilt) * e + std::sin(tilt) * (std::cos(lean) * p + std::sin(lean) * q);
  const Vector3 center =
      bearing.p_WP + radial * (std::cos(toward) * p + std::sin(toward) * q) + axial * e;
  return {center, axis};
}

DetectionInput make_input(const std::string& family, const std::string& group, double group_value,
                          std::size_t serial, const JointDimensions& d, const PartPose& bearing,
                          const PartPose& journal) {
  DetectionInput input;
  input.family = family;
  input.group = group;
  input.group_value = group_value;
  input.id = family + "/" + (group.empty() ? "" : group + "/") + std::to_string(serial);
  input.measured_margin = kNaN;
  input.measured_tilt = kNaN;
  input.dimensions = d;
  input.bearing = bearing;
  input.journal = journal;
  return input;
}

std::size_t scaled_count(SuiteSize size, std::size_t full, std::size_t quick) {
  return size == SuiteSize::full ? full : quick;
}

// ---- realistic --------------------------------------------------------------------------------

/// The room a journal of dimensions `d` tilted by `tilt` leaves when centred: how far its rims
/// are from the wall (radial) and from the base planes (axial).
struct Room {
  double radial;
  double axial;
};
Room room_at_tilt(const JointDimensions& d, double tilt) {
  const double half_lj = 0.5 * d.journal_length;
  return {d.bearing_radius - (half_lj * std::sin(tilt) + d.journal_radius * std::cos(tilt)),
          0.5 * d.bearing_length - (half_lj * std::cos(tilt) + d.journal_radius * std::sin(tilt))};
}

/// A random realistic pose of a joint with dimensions `d`: bearing centre within `reach` of the
/// origin (0: at the origin), any axis; journal tilt uniform up to the largest, centre offset
/// uniform up to 1.5 times the room left at that tilt (1.5 cr and 1.5 ca when untilted), radially
/// and axially (either way). A rim then touches in about a third of the poses per direction, so
/// about half of the poses are in contact.
std::pair<PartPose, PartPose> realistic_pose(UniformSource& uniform, const JointDimensions& d,
                                             double reach) {
  const PartPose bearing{Vector3(uniform(-reach, reach), uniform(-reach, reach), uniform(-reach, reach)),
                         random_direction(uniform)};
  const double tilt = uniform(0.0, largest_tilt(d));
  const Room room = room_at_tilt(d, tilt);
  const double lean = uniform(0.0, 2.0 * kPi);
  const double radial = uniform(0.0, 1.5) * room.radial;
  const double toward = uniform(0.0, 2.0 * kPi);
  const double axial = uniform(-1.5, 1.5) * room.axial;
  return {bearing, journal_in_bearing_frame(bearing, tilt, lean, radial, toward, axial)};
}

/// Mechanism scale: bearings within 0.2 m of the world origin.
constexpr double kMechanismReach = 0.2;

std::vector<DetectionInput> realistic(std::uint64_t seed, SuiteSize size) {
  UniformSource uniform(seed);
  const JointDimensions d = table2_dimensions();
  std::vector<DetectionInput> out;
  const std::size_t count = scaled_count(size, 4096, 256);
  for (std::size_t n = 0; n < count; ++n) {
    const auto [bearing, journal] = realistic_pose(uniform, d, kMechanismReach);
    out.push_back(make_input("realistic", "", kNaN, n, d, bearing, journal));
  }
  return out;
}

// ---- near-tangent -------------------------------------------------------------------------------

enum class TangentKind { radial_a, radial_b, axial_a, axial_b, line, face_a, face_b };

const char* kind_name(TangentKind kind) {
  switch (kind) {
    case TangentKind::radial_a: return "radial_a";
    case TangentKind::radial_b: return "radial_b";
    case TangentKind::axial_a: return "axial_a";
    case TangentKind::axial_b: return "axial_b";
    case TangentKind::line: return "line";
    case TangentKind::face_a: return "face_a";
    case TangentKind::face_b: return "face_b";
  }
  return "";
}

ContactBase kind_base(TangentKind kind) {
  return kind == TangentKind::radial_b || kind == TangentKind::axial_b || kind == TangentKind::face_b
             ? ContactBase::b
             : ContactBase::a;
}

RealPose to_real(const PartPose& pose) { return {bench::to_real(pose.p_WP), bench::to_real(pose.axis_W)}; }

/// The journal centre s d + z e (MPFR, exact in the directions given).
RealVector centre_at(const Real& s, const RealVector& d, const Real& z, const RealVector& e) {
  return add(scale(s, d), scale(z, e));
}

/// Solves for the radial offset s along `d` (perpendicular to the bearing axis, pointing where
/// rim `base` leans) at which the rim's farthest reach exceeds Ri by `margin`: Newton on s, whose
/// derivative is (unit radial direction of the farthest point) . d by the envelope theorem. The
/// reach is convex in s, so Newton from the right converges monotonically.
Real solve_radial_offset(const JointDimensions& d, const RealPose& bearing, const RealVector& axis,
                         const RealVector& direction, const Real& z, const RealVector& e,
                         ContactBase base, const Real& margin) {
  // Newton stops when a step is below this fraction of cr: 45 orders below the smallest margin
  // generated (1e-15 cr), and far above the reference's working precision (1e-120).
  static const Real kStepTolerance("1e-60");
  // The offset direction is within 60 degrees of the rim's lean, so the farthest point's radial
  // direction has a component along it of about cos(60) = 0.5; a slope below this means the
  // construction went wrong, not a hard input.
  static const Real kSmallestSlope("0.05");
  // Quadratic convergence from 2 cr needs ~10 steps; the cap only guards against a bug.
  constexpr int kMaxSteps = 100;
  const Real cr = Real(d.bearing_radius) - Real(d.journal_radius);
  Real s = 2 * cr;  // beyond the root for the tilts used (the journal then reaches past the wall)
  const Real tolerance = cr * kStepTolerance;
  for (int iteration = 0; iteration < kMaxSteps; ++iteration) {
    const ReferenceJoint joint = joint_as_given(d, bearing, RealPose{centre_at(s, direction, z, e), axis});
    const RadialMargin m = radial_margin(joint, base);
    const Real f = m.margin - margin;
    const Real slope = dot(m.direction, direction);
    if (!(slope > kSmallestSlope)) throw std::runtime_error("near-tangent generator: reach not increasing");
    const Real step = f / slope;
    s -= step;
    if (abs(step) < tolerance) return s;
  }
  throw std::runtime_error("near-tangent generator: Newton on the radial offset did not converge");
}

/// One near-tangent input: candidate `kind` at signed `margin` (clearances) from touching.
DetectionInput near_tangent_input(UniformSource& uniform, TangentKind kind, int k, int sign,
                                  std::size_t serial) {
  const JointDimensions d = table2_dimensions();
  const Vector3 bearing_axis = random_direction(uniform);
  const PartPose bearing{Vector3::Zero(), bearing_axis};
  const RealPose real_bearing = to_real(bearing);
  const RealVector e = normalized(real_bearing.axis_W);
  const auto [p_d, q_d] = perpendiculars(bearing_axis.normalized());
  // An MPFR frame perpendicular to the exact bearing axis (p_d, q_d are only nearly so).
  const RealVector p = normalized(sub(bench::to_real(p_d), scale(dot(bench::to_real(p_d), e), e)));
  const RealVector q = cross(e, p);
  auto planar = [&](double angle) {
    return add(scale(Real(std::cos(angle)), p), scale(Real(std::sin(angle)), q));
  };
  const bool aligned = kind == TangentKind::line || kind == TangentKind::face_a || kind == TangentKind::face_b;
  const bool radial = kind == TangentKind::radial_a || kind == TangentKind::radial_b || kind == TangentKind::line;
  const double clearance = radial ? d.radial_clearance() : d.axial_clearance();
  const Real margin = Real(sign) * pow(Real(10), -k) * Real(clearance);
  const ContactBase base = kind_base(kind);
  const int base_sign = base == ContactBase::a ? 1 : -1;

  Vector3 journal_axis;
  if (aligned) {
    // Exactly parallel: the bearing axis itself, reversed, or doubled (exact in binary).
    const double factors[] = {1.0, -1.0, 2.0, -0.5};
    journal_axis = factors[serial % 4] * bearing_axis;
  } else {
    const double tilt = uniform(0.1, 0.8) * largest_tilt(d);
    const double lean = uniform(0.0, 2.0 * kPi);
    journal_axis = journal_in_bearing_frame(bearing, tilt, lean, 0.0, 0.0, 0.0).axis_W;
  }
  const RealVector axis = bench::to_real(journal_axis);
  // Azimuth towards which rim `base` leans (rim A leans along the tilt, rim B against it).
  const RealVector axis_hat = normalized(axis);
  const Real lean_p = dot(axis_hat, p) * (dot(axis, e) >= 0 ? 1 : -1) * base_sign;
  const Real lean_q = dot(axis_hat, q) * (dot(axis, e) >= 0 ? 1 : -1) * base_sign;
  const double lean_azimuth = std::atan2(lean_q.convert_to<double>(), lean_p.convert_to<double>());

  RealVector centre;
  switch (kind) {
    case TangentKind::radial_a:
    case TangentKind::radial_b: {
      const RealVector direction = planar(lean_azimuth + uniform(-kPi / 3, kPi / 3));
      const Real z = Real(uniform(-0.3, 0.3) * d.axial_clearance());
      const Real s = solve_radial_offset(d, real_bearing, axis, direction, z, e, base, margin);
      centre = centre_at(s, direction, z, e);
      break;
    }
    case TangentKind::axial_a:
    case TangentKind::axial_b:
    case TangentKind::face_a:
    case TangentKind::face_b: {
      // The axial margin is alpha + rho with alpha linear in the axial offset z (slope base_sign).
      const RealVector radial_offset =
          scale(Real(uniform(0.0, 0.5) * d.radial_clearance()), planar(uniform(0.0, 2.0 * kPi)));
      const ReferenceJoint at_zero = joint_as_given(d, real_bearing, RealPose{radial_offset, axis});
      const Real z = base_sign * (margin - axial_margin(at_zero, base));
      centre = centre_at(Real(1), radial_offset, z, e);
      break;
    }
    case TangentKind::line: {
      const Real z = Real(uniform(-0.3, 0.3) * d.axial_clearance());
      centre = centre_at(Real(clearance) + margin, planar(uniform(0.0, 2.0 * kPi)), z, e);
      break;
    }
  }
  const PartPose journal{to_double(centre), journal_axis};
  const std::string group = "k=" + std::to_string(k);
  DetectionInput input = make_input("near_tangent", group, k, serial, d, bearing, journal);
  input.id = std::string("near_tangent/") + kind_name(kind) + "/" + group + "/" + (sign > 0 ? "+" : "-") +
             "/" + std::to_string(serial);
  const ReferenceJoint rounded = joint_as_given(d, bearing, journal);
  const Real measured = kind == TangentKind::line ? line_margin(rounded)
                        : radial                  ? radial_margin(rounded, base).margin
                                                  : axial_margin(rounded, base);
  input.measured_margin = (measured / Real(clearance)).convert_to<double>();
  return input;
}

std::vector<DetectionInput> near_tangent(std::uint64_t seed, SuiteSize size,
                                         const std::function<void(double)>& progress) {
  UniformSource uniform(seed);
  const std::size_t per_case = scaled_count(size, 12, 1);
  const TangentKind kinds[] = {TangentKind::radial_a, TangentKind::radial_b, TangentKind::axial_a,
                               TangentKind::axial_b,  TangentKind::line,     TangentKind::face_a,
                               TangentKind::face_b};
  std::vector<DetectionInput> out;
  const double total = 7.0 * 13 * 2 * static_cast<double>(per_case);
  for (const TangentKind kind : kinds) {
    for (int k = 3; k <= 15; ++k) {
      for (const int sign : {1, -1}) {
        for (std::size_t n = 0; n < per_case; ++n) {
          out.push_back(near_tangent_input(uniform, kind, k, sign, n));
          if (progress && out.size() % 64 == 0) progress(static_cast<double>(out.size()) / total);
        }
      }
    }
  }
  return out;
}

// ---- near-parallel ---------------------------------------------------------------------------------

std::vector<DetectionInput> near_parallel(std::uint64_t seed, SuiteSize size) {
  UniformSource uniform(seed);
  const JointDimensions d = table2_dimensions();
  const std::size_t per_group = scaled_count(size, 64, 4);
  std::vector<DetectionInput> out;
  for (int k = 0; k <= 16; ++k) {
    if (k >= 1 && k <= 3) continue;  // groups: exactly parallel (k = 0), then 10^-4 .. 10^-16
    const std::string group = k == 0 ? "parallel" : "k=" + std::to_string(k);
    for (std::size_t n = 0; n < per_group; ++n) {
      // Half the bearings along z, where a tilt of 1e-16 is representable exactly, half along a
      // random axis, where the rounded journal axis carries the tilt only to ~1e-16 rad.
      const bool canonical = n % 2 == 0;
      const PartPose bearing{Vector3::Zero(), canonical ? Vector3::UnitZ() : random_direction(uniform)};
      const Vector3 e = bearing.axis_W.normalized();
      const auto [p, q] = perpendiculars(e);
      const double lean = uniform(0.0, 2.0 * kPi);
      Vector3 axis;
      if (k == 0) {
        const double factors[] = {1.0, -1.0, 2.0, -0.5};
        axis = factors[(n / 2) % 4] * bearing.axis_W;
      } else if (canonical) {
        const double tilt = std::pow(10.0, -k);
        axis = Vector3(tilt * std::cos(lean), tilt * std::sin(lean), 1.0);  // angle atan(tilt)
      } else {
        const double tilt = std::pow(10.0, -k);
        axis = e + tilt * (std::cos(lean) * p + std::sin(lean) * q);
        // Rounding may leave the axis exactly parallel: move one component by an ulp.
        const Vector3 c = axis.cross(bearing.axis_W);
        if (c.x() == 0.0 && c.y() == 0.0 && c.z() == 0.0) axis.x() = std::nextafter(axis.x(), 2.0);
      }
      const double radial = uniform(0.0, 1.5 * d.radial_clearance());
      const double toward = uniform(0.0, 2.0 * kPi);
      const double axial = uniform(-1.5, 1.5) * d.axial_clearance();
      const PartPose journal{radial * (std::cos(toward) * p + std::sin(toward) * q) + axial * e, axis};
      DetectionInput input = make_input("near_parallel", group, k, n, d, bearing, journal);
      // The tilt the doubles carry: the angle between the stored axes, in MPFR.
      const RealVector ai = bench::to_real(bearing.axis_W), aj = bench::to_real(axis);
      input.measured_tilt = (atan2(norm(cross(ai, aj)), abs(dot(ai, aj)))).convert_to<double>();
      out.push_back(input);
    }
  }
  return out;
}

// ---- extreme ----------------------------------------------------------------------------------

std::vector<DetectionInput> extreme(std::uint64_t seed, SuiteSize size) {
  UniformSource uniform(seed);
  const JointDimensions table2 = table2_dimensions();
  std::vector<DetectionInput> out;

  // Scenario (i): the journal centred at its largest tilt (all four rims at the surfaces) and
  // tilted just beyond it (all four in contact, depths growing with the excess).
  {
    const double t_max = largest_tilt(table2);
    const double excesses[] = {0.0, 1e-12, 1e-9, 1e-6, 1e-3};
    for (const double excess : excesses) {
      const std::string group = excess == 0.0 ? "largest_tilt" : "largest_tilt*(1+" + [&] {
        char text[16];
        std::snprintf(text, sizeof text, "%.0e", excess);
        return std::string(text);
      }() + ")";
      for (std::size_t n = 0; n < scaled_count(size, 8, 2); ++n) {
        const PartPose bearing{Vector3::Zero(), n % 2 == 0 ? Vector3::UnitZ() : random_direction(uniform)};
        const PartPose journal = journal_in_bearing_frame(bearing, t_max * (1.0 + excess),
                                                          uniform(0.0, 2.0 * kPi), 0.0, 0.0, 0.0);
        out.push_back(make_input("extreme", group, kNaN, n, table2, bearing, journal));
      }
    }
  }
  // The journal axis reversed (labels must follow the bearing).
  for (std::size_t n = 0; n < scaled_count(size, 64, 8); ++n) {
    auto [bearing, journal] = realistic_pose(uniform, table2, kMechanismReach);
    journal.axis_W = -journal.axis_W;
    out.push_back(make_input("extreme", "reversed_journal", kNaN, n, table2, bearing, journal));
  }
  // Coincident axes: the journal centre on the bearing axis, axes exactly parallel.
  {
    std::size_t n = 0;
    for (const bool canonical : {true, false}) {
      const PartPose bearing{Vector3::Zero(), canonical ? Vector3::UnitZ() : random_direction(uniform)};
      for (const double factor : {1.0, -1.0, 0.5}) {
        for (const double shift : {0.0, 0.5, -0.5, 1.0, -1.0, 1.5, -1.5}) {
          const PartPose journal{shift * table2.axial_clearance() * bearing.axis_W,
                                 factor * bearing.axis_W};
          out.push_back(make_input("extreme", "coincident_axes", kNaN, n++, table2, bearing, journal));
        }
      }
    }
  }
  // Clearance ratios cr/Ri from 1e-6 to 0.2 (ca = cr), realistic poses scaled to the clearances.
  for (const double ratio : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.2}) {
    JointDimensions d;
    d.bearing_radius = 0.01;
    d.journal_radius = d.bearing_radius * (1.0 - ratio);
    d.bearing_length = 0.02;
    d.journal_length = d.bearing_length - 2.0 * d.radial_clearance();
    char group[32];
    std::snprintf(group, sizeof group, "cr/Ri=%g", ratio);
    for (std::size_t n = 0; n < scaled_count(size, 32, 4); ++n) {
      const auto [bearing, journal] = realistic_pose(uniform, d, kMechanismReach);
      out.push_back(make_input("extreme", group, ratio, n, d, bearing, journal));
    }
  }
  // The same configurations in metres, micrometres and kilometres.
  for (std::size_t n = 0; n < scaled_count(size, 32, 4); ++n) {
    const auto [bearing, journal] = realistic_pose(uniform, table2, kMechanismReach);
    const std::pair<const char*, double> units[] = {{"metres", 1.0}, {"micrometres", 1e6}, {"kilometres", 1e-3}};
    for (const auto& [unit, factor] : units) {
      const JointDimensions d{table2.bearing_radius * factor, table2.bearing_length * factor,
                              table2.journal_radius * factor, table2.journal_length * factor};
      out.push_back(make_input("extreme", unit, factor, n, d, {bearing.p_WP * factor, bearing.axis_W},
                               {journal.p_WP * factor, journal.axis_W}));
    }
  }
  return out;
}

// ---- trajectories --------------------------------------------------------------------------------

/// A journal bouncing inside its bearing: its centre moves in straight lines across the radial
/// clearance and reflects when its eccentricity exceeds 1.15 cr (so it penetrates a little
/// before bouncing); meanwhile it oscillates axially over +-1.1 ca and its axis precesses with a
/// tilt oscillating between 0 and 0.7 of the largest tilt.
std::vector<DetectionInput> trajectories(std::uint64_t seed, SuiteSize size) {
  UniformSource uniform(seed);
  const JointDimensions d = table2_dimensions();
  const double cr = d.radial_clearance(), ca = d.axial_clearance();
  const double t_max = largest_tilt(d);
  const PartPose bearing{Vector3(0.12, -0.05, 0.3), Vector3(0.3, -0.2, 0.93)};
  const Vector3 e = bearing.axis_W.normalized();
  const auto [p, q] = perpendiculars(e);
  constexpr double kBounceEccentricity = 1.15;  // in clearances
  constexpr double kStepsToCross = 40.0;        // steps to cross the clearance circle
  const double speed = 2.0 * cr / kStepsToCross;
  const double heading = uniform(0.0, 2.0 * kPi);
  double vx = speed * std::cos(heading), vy = speed * std::sin(heading);
  double x = 0.0, y = 0.0;
  const double axial_rate = uniform(0.02, 0.04), tilt_rate = uniform(0.01, 0.02), precession = uniform(0.005, 0.01);
  std::vector<DetectionInput> out;
  const std::size_t count = scaled_count(size, 3000, 300);
  for (std::size_t n = 0; n < count; ++n) {
    const double t = static_cast<double>(n);
    x += vx;
    y += vy;
    const double eccentricity = std::hypot(x, y);
    if (eccentricity > kBounceEccentricity * cr) {
      // Reflect the velocity about the radial direction (a specular bounce).
      const double nx = x / eccentricity, ny = y / eccentricity;
      const double normal_speed = vx * nx + vy * ny;
      if (normal_speed > 0.0) {
        vx -= 2.0 * normal_speed * nx;
        vy -= 2.0 * normal_speed * ny;
      }
    }
    const double axial = 1.1 * ca * std::sin(axial_rate * t);
    const double tilt = 0.35 * t_max * (1.0 + std::sin(tilt_rate * t));
    const double lean = precession * t;
    const Vector3 axis = std::cos(tilt) * e + std::sin(tilt) * (std::cos(lean) * p + std::sin(lean) * q);
    const PartPose journal{bearing.p_WP + x * p + y * q + axial * e, axis};
    out.push_back(make_input("trajectories", "", kNaN, n, d, bearing, journal));
  }
  return out;
}

}  // namespace

JointDimensions table2_dimensions() { return {10.0e-3, 20.0e-3, 9.9e-3, 19.8e-3}; }

const std::vector<FamilySpec>& family_specs() {
  static const std::vector<FamilySpec> specs = {
      {"realistic", 20170501,
       "Table 2, bearing anywhere within 0.2 m, tilt up to the largest, offsets up to 1.5 times the room the clearances leave at that tilt"},
      {"near_tangent", 20170502,
       "one candidate contact at a signed margin of 10^-k clearances from touching, k = 3..15"},
      {"near_parallel", 20170503, "journal tilts of 10^-k rad, k = 4..16, and exactly parallel axes"},
      {"extreme", 20170504,
       "largest tilt (i), reversed journal, coincident axes, cr/Ri 1e-6..0.2, m / µm / km"},
      {"trajectories", 20170505, "consecutive poses of a scripted journal bouncing in the bearing"},
  };
  return specs;
}

std::vector<DetectionInput> generate_family(const std::string& family, SuiteSize size,
                                            const std::function<void(double)>& progress) {
  for (const FamilySpec& spec : family_specs()) {
    if (family != spec.name) continue;
    if (family == "realistic") return realistic(spec.seed, size);
    if (family == "near_tangent") return near_tangent(spec.seed, size, progress);
    if (family == "near_parallel") return near_parallel(spec.seed, size);
    if (family == "extreme") return extreme(spec.seed, size);
    if (family == "trajectories") return trajectories(spec.seed, size);
  }
  throw std::invalid_argument("unknown input family: " + family);
}

}  // namespace clearjoint::bench
