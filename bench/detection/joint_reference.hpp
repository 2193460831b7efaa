// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A multiprecision reference for full-joint contact detection (paper Section 3, eqs. 5-23), the
/// yardstick of the detection benchmarks. Bench-only code, never linked into the library.
///
/// The joint is taken as the library defines it from its input doubles (joint_geometry.hpp),
/// exactly: base centres P +- (L/2) a_hat (eqs. 3-4) with a_hat = geometry::unit_axis(pose), the
/// axis normalised in double (the one rounding in the joint's definition; bitwise a itself when
/// a . a evaluates to 1), and the centres, the rims and every decision evaluated in MPFR with
/// kReferenceDigits10 digits, never rounded to double. joint_with_exact_unit_axes() takes
/// a_hat = a/|a| in MPFR instead, to show what the rounded direction changes. The formulation is
/// independent of the library's kernel:
///
/// * Radial (eqs. 16-21): with the rim x(theta) = c + Rj (u cos theta + v sin theta) and
///   w = c - P_i, the excess G(theta) = |(x(theta) - P_i) x e_i|^2 - Ri^2 (e_i = a_i/|a_i|) is a
///   trigonometric quadratic. After a shift phi (a multiple of pi/4 keeping theta = phi + pi away
///   from a root), t = tan((theta - phi)/2) turns G (1 + t^2)^2 into a quartic; a Sturm sequence
///   isolates its real roots and safeguarded Newton refines them to kRootWidth. The penetration
///   arcs are the gaps between consecutive roots where G > 0; the contact point on the journal is
///   the rim point at the arc's angular middle (eqs. 18-19: the chord-midpoint direction from the
///   rim centre, on the side beyond the wall), on the bearing its projection (eqs. 20-21).
/// * Axial (eqs. 11-15): the signed distance of x(theta) beyond the base plane is
///   alpha + rho cos(theta - theta0) in closed form; the deepest point, which is the arc middle,
///   is c + Rj w_hat with w_hat the base normal projected into the rim plane.
/// * Parallel axes (eq. 5, decided exactly on the input doubles): eqs. (6)-(10) in closed form.
/// * The scenario is named by geometry::classify_scenario (the documented rule, Fig. 2) from the
///   contacts, with beyond_model when a rim has two penetration arcs, is beyond a surface all
///   round, or penetrates deeper than the clearance in its direction (cr radial, ca axial).
///
/// Why hand-written: support/testing/multiprecision_reference takes its rim centres as
/// doubles, while the joint as given has centres P +- (L/2) a_hat that no double holds; and
/// CGAL's algebraic kernels isolate the roots of exact (rational) polynomials, while these
/// coefficients carry square roots (a/|a|). The root isolation (Sturm sequence, bisection,
/// safeguarded Newton) in MPFR is the test reference's (support/multiprecision/
/// trig_quadratic_roots.hpp); tests/test_joint_reference.cpp checks this reference against the test
/// reference on rounded joints and against closed forms.
///
/// The reference says when it cannot decide (`decided == false`): roots closer than
/// kAmbiguousSeparation, a root of even multiplicity, or a sign test within kTieWidth of zero.
/// The benchmark families never come that close (their smallest margin is 1e-15 clearances).

#include <array>
#include <string>
#include <vector>

#include <boost/multiprecision/mpfr.hpp>

#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::bench {

/// 120 decimal digits (about 400 bits): sums and products of the input doubles are exact as long
/// as their exponents lie within ~2^150 of each other (every family does), and the smallest margin
/// the families generate (1e-15 clearances, 1e-21 relative to the coordinates) is 10^99 times
/// the working precision.
inline constexpr unsigned kReferenceDigits10 = 120;
using Real = boost::multiprecision::number<
    boost::multiprecision::mpfr_float_backend<kReferenceDigits10,
                                              boost::multiprecision::allocate_stack>,
    boost::multiprecision::et_off>;
using RealVector = std::array<Real, 3>;

/// Roots closer than this in t = tan(half angle) make an answer ambiguous (a tangency cannot be
/// told from two crossings at this precision).
inline constexpr double kAmbiguousSeparation = 1e-60;
/// Width (in t) to which every isolated root is refined.
inline constexpr double kRootWidth = 1e-90;
/// A sign decision whose value lies within this fraction of its scale of zero, without being
/// exactly zero, is undecided (exact ties, which integer-like inputs produce, are decided).
inline constexpr double kTieWidth = 1e-100;

/// A part pose with coordinates in MPFR (the generators solve for poses before rounding them).
struct RealPose {
  RealVector p_WP;
  RealVector axis_W;
};

/// The joint the reference decides on. Indices of the arrays: 0 = base A, 1 = base B.
struct ReferenceJoint {
  Real bearing_radius, journal_radius;
  Real radial_clearance;  ///< cr = Ri - Rj, eq. (1)
  Real axial_clearance;   ///< ca = (Li - Lj)/2, eq. (2)
  RealVector p_WPi, p_WPj;
  RealVector bearing_axis_hat, journal_axis_hat;  ///< e_i, e_j (the journal's as given, not flipped)
  std::array<RealVector, 2> bearing_base;         ///< base centres A, B (eqs. 3-4)
  std::array<RealVector, 2> journal_rim;          ///< centres of the journal rims facing A and B
  bool exactly_parallel = false;                  ///< eq. (5) on the stored axes, exactly
};

/// The joint exactly as the library defines it from its doubles (see the file comment).
ReferenceJoint joint_as_given(const geometry::JointDimensions& dimensions,
                              const geometry::PartPose& bearing, const geometry::PartPose& journal);
/// The same from MPFR poses (generators); their axes must be doubles (std::invalid_argument).
ReferenceJoint joint_as_given(const geometry::JointDimensions& dimensions, const RealPose& bearing,
                              const RealPose& journal);
/// The joint with its centres offset along a/|a| computed in MPFR instead of the library's
/// double unit axis: a diagnostic of the one rounding left in the joint's definition.
ReferenceJoint joint_with_exact_unit_axes(const geometry::JointDimensions& dimensions,
                                          const geometry::PartPose& bearing,
                                          const geometry::PartPose& journal);

struct ReferenceContact {
  geometry::ContactType type = geometry::ContactType::radial;
  geometry::ContactBase base = geometry::ContactBase::a;
  RealVector p_WCj, p_WCi, normal_W;
  Real depth;
  /// The rim's crossings bounding the penetration arc (0 for line and face contacts and for a rim
  /// beyond a surface all round).
  std::vector<RealVector> crossings;
  /// False for a rim beyond the wall all round: it has no arc middle, the library documents an
  /// approximation there, and its points are not compared.
  bool points_defined = true;
  /// True for a rim beyond a base plane all round (beyond the model): its contact point is the
  /// deepest rim point, whose direction is ill-conditioned for a rim nearly parallel to the base
  /// (the base normal projected into the rim plane is as short as the tilt's sine), so its point
  /// errors are tallied apart.
  bool all_round = false;
};

struct ReferenceAnswer {
  bool decided = true;
  std::string why;  ///< when not decided
  geometry::ContactScenario scenario = geometry::ContactScenario::none;
  bool aligned = false;
  /// Radial (per rim A then B, arcs in angle order) before axial (A then B), as the library lists.
  std::vector<ReferenceContact> contacts;
};

ReferenceAnswer reference_detect(const ReferenceJoint& joint);

/// Signed margin of rim `base` from the lateral wall: its farthest distance from the bearing axis
/// minus Ri (positive: beyond the wall by that much). Also for parallel axes, where it is
/// e - cr up to the lateral offset of the rim centre from the journal's axis line (the centres
/// are offset along the library's rounded unit axis, ~1e-16 rad off the axis direction; the line
/// contact itself is line_margin). Sets `decided` false when the maximum cannot be located.
struct RadialMargin {
  bool decided = true;
  Real margin;
  /// Unit vector from the bearing axis to the farthest rim point, perpendicular to the axis.
  RealVector direction;
};
RadialMargin radial_margin(const ReferenceJoint& joint, geometry::ContactBase base);
/// The aligned line contact's margin, eqs. (6)-(8): the eccentricity of P_j minus cr.
Real line_margin(const ReferenceJoint& joint);
/// Largest signed distance of rim `base` beyond its bearing base plane (positive: beyond).
Real axial_margin(const ReferenceJoint& joint, geometry::ContactBase base);

// ---- conversions and small vector algebra (shared with the generators) -------------------------

RealVector to_real(const geometry::Vector3& v);
geometry::Vector3 to_double(const RealVector& v);  ///< each component correctly rounded
Real dot(const RealVector& a, const RealVector& b);
RealVector cross(const RealVector& a, const RealVector& b);
RealVector add(const RealVector& a, const RealVector& b);
RealVector sub(const RealVector& a, const RealVector& b);
RealVector scale(const Real& s, const RealVector& a);
Real norm(const RealVector& a);
RealVector normalized(const RealVector& a);
/// Euclidean distance between a double point and a reference point.
Real distance(const geometry::Vector3& p, const RealVector& q);
const Real& pi_constant();

}  // namespace clearjoint::bench
