// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Properties every answer of detect_contacts must have, for any valid joint, and the random
// joints they are checked on. Shared by the property test (test_joint_properties.cpp, 1e5 joints
// in ctest), its long run (bench/geometry/joint_properties_run.cpp) and the fuzz target
// fuzz/fuzz_detect_raw.cpp, so that all three check the same things.
//
// Exact transformations define the same exact joint (joint_geometry.hpp), so any answer that is
// certified or exact on both sides must agree:
//   - swapping the roles of bases A and B (the bearing axis reversed): same scenario, contacts at
//     A and B exchanged;
//   - reversing the journal axis: same scenario and contacts (rim A is the rim facing base A);
//   - a power-of-two change of units: same scenario, depths scaled exactly.
// A random rigid motion rounds the inputs (a slightly different joint): same scenario and
// contacts, depths and points moved, within kMotionTolerance; only a contact within that
// tolerance of touching may appear or vanish (and the scenario change with it).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"

namespace clearjoint::geometry::properties {

/// Distance of a contact point from its surface, relative to the joint's size (the largest of
/// |P|, R, L): the points are double evaluations of closed forms whose rounding is a few ulps of
/// that size times a condition number of at most ~1e3 for the shallowest arcs of the generator.
inline constexpr double kSurfaceTolerance = 1e-9;
/// Depth difference between the two answers of an exact transformation, relative to the joint's
/// size: the two runs round differently inside (other frames), never more than a few ulps of it.
inline constexpr double kExactTransformTolerance = 1e-9;
/// Depth and point difference after a random rigid motion, relative to the joint's size: the
/// motion rounds every input by ~1e-16 of the size and the closed forms amplify it by at most
/// ~1e3 (arc middles of shallow arcs; see test_detect_contacts' kMotionTolerance).
inline constexpr double kMotionTolerance = 1e-8;

struct Joint {
  JointDimensions dimensions;
  PartPose bearing;
  PartPose journal;
};

/// The largest length of a joint: differences are measured against it.
inline double joint_size(const Joint& j) {
  return std::max({j.bearing.p_WP.cwiseAbs().maxCoeff(), j.journal.p_WP.cwiseAbs().maxCoeff(),
                   j.dimensions.bearing_radius, j.dimensions.bearing_length});
}

inline bool trusted(const Certificate& c) { return c.level != Certainty::uncertain; }

/// A random joint near contact: dimensions at a random power-of-two scale, clearances from
/// 2^-20 to 1/4 of the size, the journal offset by up to 1.25 times the clearances and tilted by
/// up to 2.5 times the radial clearance over the journal length, so that every scenario, free
/// flight and beyond-the-model answers all occur.
template <class Rng>
Joint random_joint(Rng& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  const double scale = std::ldexp(1.0, exponent(rng));
  Joint j;
  JointDimensions& d = j.dimensions;
  d.bearing_radius = scale * (0.5 + unit(rng));
  d.bearing_length = scale * (0.25 + 4.0 * unit(rng));
  const double radial_fraction = std::ldexp(0.25 + 0.75 * unit(rng), -static_cast<int>(20 * unit(rng)) - 2);
  const double axial_fraction = std::ldexp(0.25 + 0.75 * unit(rng), -static_cast<int>(20 * unit(rng)) - 2);
  d.journal_radius = d.bearing_radius * (1.0 - radial_fraction);
  d.journal_length = d.bearing_length * (1.0 - axial_fraction);
  const double cr = d.radial_clearance(), ca = d.axial_clearance();

  // Bearing anywhere within 100 sizes of the origin, axis in any direction and of any length.
  const Vector3 p_WP = 100.0 * scale * Vector3(sym(rng), sym(rng), sym(rng));
  Vector3 a(sym(rng), sym(rng), sym(rng));
  if (a.norm() < 1e-3) a = Vector3::UnitZ();
  a *= std::ldexp(1.0, exponent(rng) / 4);
  j.bearing = {p_WP, a};

  // The journal in the bearing's frame (u, v, a_hat); a quarter of the joints aligned exactly
  // (the journal axis a multiple of the bearing's).
  const Vector3 a_hat = a.normalized();
  const Vector3 u = a_hat.unitOrthogonal(), v = a_hat.cross(u);
  const double azimuth = 2.0 * M_PI * unit(rng);
  const double radial = 1.25 * cr * unit(rng), axial = 1.25 * ca * sym(rng);
  const Vector3 p_WJ = p_WP + radial * (std::cos(azimuth) * u + std::sin(azimuth) * v) + axial * a_hat;
  Vector3 journal_axis = a;
  if (unit(rng) >= 0.25) {
    const double tilt = 2.5 * cr / d.journal_length * unit(rng);
    const double tilt_azimuth = 2.0 * M_PI * unit(rng);
    journal_axis = a_hat + tilt * (std::cos(tilt_azimuth) * u + std::sin(tilt_azimuth) * v);
  }
  if (unit(rng) < 0.5) journal_axis = -journal_axis;
  j.journal = {p_WJ, journal_axis};
  return j;
}

/// Checks one answer on its own; returns "" or what is wrong.
inline std::string check_answer(const Joint& j, const JointContacts& r) {
  std::ostringstream out;
  const double size = joint_size(j);
  if (r.contact_count < 0 || r.contact_count > kMaxContacts) return "contact_count out of range";
  if ((r.contact_count == 0) != (r.scenario == ContactScenario::none)) {
    out << "scenario " << static_cast<int>(r.scenario) << " with " << r.contact_count << " contacts";
    return out.str();
  }
  const Vector3 a_hat = unit_axis(j.bearing);
  const BaseCenters bases = base_centers(j.bearing, j.dimensions.bearing_length);
  for (int k = 0; k < r.contact_count; ++k) {
    const Contact& c = r.contacts[static_cast<std::size_t>(k)];
    if (static_cast<int>(c.certificate.level) > static_cast<int>(r.certificate.level)) {
      out << "contact " << k << " less certain than the answer's certificate";
      return out.str();
    }
    if (!(c.depth >= 0.0) || !std::isfinite(c.depth)) {
      out << "contact " << k << " depth " << c.depth;
      return out.str();
    }
    if (!c.p_WCi.allFinite() || !c.p_WCj.allFinite() || !(std::abs(c.normal_W.norm() - 1.0) < 1e-12)) {
      out << "contact " << k << " has non-finite points or a normal not of unit length";
      return out.str();
    }
    // p_WCi on the bearing surface: the wall (distance Ri from the axis) or the base plane.
    double off_surface = 0.0;
    if (c.type == ContactType::radial) {
      const Vector3 d = c.p_WCi - j.bearing.p_WP;
      off_surface = std::abs((d - d.dot(a_hat) * a_hat).norm() - j.dimensions.bearing_radius);
    } else {
      const Vector3& center = c.base == ContactBase::b ? bases.p_WB : bases.p_WA;
      off_surface = std::abs((c.p_WCi - center).dot(a_hat));
    }
    if (!(off_surface <= kSurfaceTolerance * size)) {
      out << "contact " << k << " bearing point " << off_surface / size << " sizes off its surface";
      return out.str();
    }
    // p_WCj - p_WCi = depth * normal (eqs. 22-23).
    if (!((c.p_WCj - c.p_WCi - c.depth * c.normal_W).norm() <= kSurfaceTolerance * size)) {
      out << "contact " << k << " breaks p_WCj - p_WCi = depth * normal";
      return out.str();
    }
  }
  return "";
}

/// A contact's key for comparing answers whose lists are in other orders.
inline int contact_key(const Contact& c, bool swap_bases) {
  ContactBase base = c.base;
  if (swap_bases && base != ContactBase::mid) base = base == ContactBase::a ? ContactBase::b : ContactBase::a;
  return static_cast<int>(c.type) * 4 + static_cast<int>(base);
}

/// Compares two answers of one joint seen two ways; `depth_factor` maps the first's depths to
/// the second's, `tolerance` is absolute (in the second's unit). Only when both are trusted.
inline std::string compare(const JointContacts& first, const JointContacts& second, bool swap_bases,
                           double depth_factor, double tolerance) {
  if (!trusted(first.certificate) || !trusted(second.certificate)) return "";
  std::ostringstream out;
  if (first.scenario != second.scenario || first.contact_count != second.contact_count ||
      first.aligned != second.aligned) {
    out << "scenario " << static_cast<int>(first.scenario) << " (" << first.contact_count
        << " contacts) became " << static_cast<int>(second.scenario) << " (" << second.contact_count << ")";
    return out.str();
  }
  // Beyond the model a rim can have two radial contacts (two penetration arcs) with one key:
  // each contact is matched to the unmatched one of its key whose depth is closest.
  std::array<bool, kMaxContacts> used{};
  for (int k = 0; k < first.contact_count; ++k) {
    const Contact& c = first.contacts[static_cast<std::size_t>(k)];
    const Contact* match = nullptr;
    for (int m = 0; m < second.contact_count; ++m) {
      const Contact& d = second.contacts[static_cast<std::size_t>(m)];
      if (used[static_cast<std::size_t>(m)] || contact_key(d, false) != contact_key(c, swap_bases)) continue;
      if (match == nullptr || std::abs(d.depth - depth_factor * c.depth) <
                                  std::abs(match->depth - depth_factor * c.depth)) {
        match = &d;
      }
    }
    if (match == nullptr) {
      out << "contact " << k << " has no counterpart";
      return out.str();
    }
    used[static_cast<std::size_t>(match - second.contacts.data())] = true;
    if (!(std::abs(match->depth - depth_factor * c.depth) <= tolerance)) {
      out << "contact " << k << " depth " << c.depth * depth_factor << " became " << match->depth;
      return out.str();
    }
  }
  return "";
}

/// `r` without its contacts of depth at most `touch` (scenario left as it was).
inline JointContacts without_touches(const JointContacts& r, double touch) {
  JointContacts kept = r;
  kept.contact_count = 0;
  for (int k = 0; k < r.contact_count; ++k) {
    const Contact& c = r.contacts[static_cast<std::size_t>(k)];
    if (c.depth > touch) kept.contacts[static_cast<std::size_t>(kept.contact_count++)] = c;
  }
  return kept;
}

/// The contacts of two answers, matched by key and depth, within `tolerance` (trusted answers).
inline std::string compare_contacts(const JointContacts& first, const JointContacts& second,
                                    double tolerance) {
  JointContacts a = first, b = second;
  a.scenario = b.scenario = ContactScenario::beyond_model;  // compare the contacts only
  a.aligned = b.aligned;
  if (a.contact_count == 0 && b.contact_count == 0) return "";
  return compare(a, b, false, 1.0, tolerance);
}

/// Every property of the header comment for one joint; `motion` is a random rigid motion (or
/// none, for the fuzz target, whose inputs may lie exactly on a scenario boundary). Returns ""
/// or the first violation. InvalidInput from detect_contacts propagates.
inline std::string check_properties(const Joint& j, const std::optional<Eigen::Isometry3d>& motion,
                                    int unit_exponent) {
  const JointContacts reference = detect_contacts(j.dimensions, j.bearing, j.journal);
  const double size = joint_size(j);
  if (std::string e = check_answer(j, reference); !e.empty()) return "answer: " + e;

  // Rim A is the rim facing base A, by the sign of a_i . a_j; with the axes exactly
  // perpendicular (a journal turned across its bearing, far beyond the model) the labels are a
  // convention that neither transformation below changes, so they are not compared there.
  const bool labels_defined = j.bearing.axis_W.dot(j.journal.axis_W) != 0.0;
  if (labels_defined) {
    const PartPose bearing_swapped{j.bearing.p_WP, -j.bearing.axis_W};
    if (std::string e = compare(reference, detect_contacts(j.dimensions, bearing_swapped, j.journal),
                                true, 1.0, kExactTransformTolerance * size);
        !e.empty()) {
      return "A/B swap: " + e;
    }
    const PartPose journal_reversed{j.journal.p_WP, -j.journal.axis_W};
    if (std::string e = compare(reference, detect_contacts(j.dimensions, j.bearing, journal_reversed),
                                false, 1.0, kExactTransformTolerance * size);
        !e.empty()) {
      return "journal axis reversed: " + e;
    }
  }
  const double factor = std::ldexp(1.0, unit_exponent);
  const JointDimensions& d = j.dimensions;
  const Joint scaled{{d.bearing_radius * factor, d.bearing_length * factor, d.journal_radius * factor,
                      d.journal_length * factor},
                     {j.bearing.p_WP * factor, j.bearing.axis_W},
                     {j.journal.p_WP * factor, j.journal.axis_W}};
  if (std::string e = compare(reference, detect_contacts(scaled.dimensions, scaled.bearing, scaled.journal),
                              false, factor, kExactTransformTolerance * size * factor);
      !e.empty()) {
    return "units times 2^" + std::to_string(unit_exponent) + ": " + e;
  }
  if (motion) {
    const Joint moved{j.dimensions, {*motion * j.bearing.p_WP, motion->linear() * j.bearing.axis_W},
                      {*motion * j.journal.p_WP, motion->linear() * j.journal.axis_W}};
    const JointContacts result = detect_contacts(moved.dimensions, moved.bearing, moved.journal);
    const double moved_size = std::max(size, joint_size(moved));
    const double touch = kMotionTolerance * moved_size;
    // The motion rounds the joint: a contact within `touch` of touching may appear or vanish
    // (the 1e7 run met two, at clearances of ~2^-22 of the joint's size). The answers are
    // compared without such contacts.
    const JointContacts reference_kept = without_touches(reference, touch);
    const JointContacts result_kept = without_touches(result, touch);
    const bool touches = reference_kept.contact_count != reference.contact_count ||
                         result_kept.contact_count != result.contact_count;
    if (!touches) {
      if (std::string e = compare(reference, result, false, 1.0, touch); !e.empty()) {
        return "rigid motion: " + e;
      }
    }
    if (std::string e = compare_contacts(reference_kept, result_kept, touch); !e.empty()) {
      return "rigid motion: " + e;
    }
    // Bearing points moved with the joint: each reference contact has a contact of its key at
    // its moved point (two contacts of one key lie on two arcs, far apart).
    for (int k = 0; k < reference_kept.contact_count && trusted(reference.certificate) &&
                    trusted(result.certificate);
         ++k) {
      const Contact& c = reference_kept.contacts[static_cast<std::size_t>(k)];
      bool found = false;
      for (int m = 0; m < result_kept.contact_count && !found; ++m) {
        const Contact& d = result_kept.contacts[static_cast<std::size_t>(m)];
        found = contact_key(d, false) == contact_key(c, false) &&
                (*motion * c.p_WCi - d.p_WCi).norm() <= kMotionTolerance * moved_size;
      }
      if (!found) return "rigid motion: contact " + std::to_string(k) + " bearing point moved wrongly";
    }
  }
  return "";
}

/// A uniformly random rotation and a translation of up to `reach` in each coordinate.
template <class Rng>
Eigen::Isometry3d random_motion(Rng& rng, double reach) {
  std::normal_distribution<double> gauss;
  Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  q.normalize();
  std::uniform_real_distribution<double> shift(-reach, reach);
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = q.toRotationMatrix();
  motion.translation() = Vector3(shift(rng), shift(rng), shift(rng));
  return motion;
}

}  // namespace clearjoint::geometry::properties
