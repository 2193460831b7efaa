// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// An independent multiprecision reference for the rim queries, used only by the tests.
///
/// Everything is computed from the stored doubles of the primitives, taken exactly, in MPFR with
/// kReferenceDigits10 decimal digits (about 500 bits). The formulation deliberately differs from
/// whatever the kernel does:
///
/// * Cylinder. With w = center - axis_point, A = w x a, B = r (u x a), C = r (v x a), the rim's
///   excess function is the trigonometric quadratic
///     G(theta) = |x(theta) - p) x a|^2 - R^2 |a|^2
///              = |A|^2 - R^2|a|^2 + 2 A.B cos + 2 A.C sin + |B|^2 cos^2 + |C|^2 sin^2
///                + 2 B.C cos sin,
///   which has the sign of dist(x(theta), axis) - R. The angle is shifted by phi (a multiple of
///   pi/4 chosen so that G(phi + pi) is as large as possible, which keeps the half-angle substitution
///   away from its pole), and t = tan((theta - phi)/2) turns G (1 + t^2)^2 into a quartic in t,
///   expanded symbolically. A Sturm sequence counts its distinct real roots, bisection on Sturm
///   counts isolates them, and safeguarded Newton refines them to kRootWidth
///   (support/multiprecision/trig_quadratic_roots.hpp, shared with the joint reference of the
///   detection benchmarks).
/// * Plane. The topology is decided exactly with GMP rationals (alpha^2 |n_c|^2 against
///   r^2 |n_p x n_c|^2); crossings and the deepest point come from the closed form
///   alpha + rho cos(theta - theta0) in MPFR.
///
/// The reference says when it cannot decide: two roots (real or complex) closer than
/// kAmbiguousSeparation (a rigorous discriminant bound), or an excess function that vanishes to
/// working precision (a rim on the surface). Comparisons skip those answers and count them.

#include <array>
#include <string>
#include <vector>

#include <boost/multiprecision/mpfr.hpp>

#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::test::reference {

/// 150 decimal digits, about 500 bits: exact for the inputs (a difference of two doubles within
/// 2^400 of each other), and an exact double root split by rounding stays below 1e-70, far under
/// kAmbiguousSeparation.
inline constexpr unsigned kReferenceDigits10 = 150;
using Real = boost::multiprecision::number<
    boost::multiprecision::mpfr_float_backend<kReferenceDigits10,
                                              boost::multiprecision::allocate_stack>,
    boost::multiprecision::et_off>;
using RealVector = std::array<Real, 3>;

/// Roots closer than this (in t = tan(half angle), which is within a factor 2 (1 + t^2) <= a few of
/// the angle) make the answer ambiguous: the reference cannot tell a tangency from two crossings.
inline constexpr double kAmbiguousSeparation = 1e-50;
/// Width to which every isolated root is refined (radians, before the atan).
inline constexpr double kRootWidth = 1e-60;

/// One root of the rim function, its angle in the circle's frame (frame_of's definition, computed
/// here in MPFR) in [0, 2 pi), and the rim point there.
struct ReferenceRoot {
  Real angle;
  RealVector point;
  /// 1 for a simple root. Only ever more than 1 in an ambiguous answer (a cluster of roots or an
  /// even root without a sign change), where it is a hint.
  int multiplicity_hint = 1;
};

struct CylinderReference {
  /// True when the reference cannot decide; `why` says why. Then only `roots` (hints) and
  /// `topology` (a hint) are filled.
  bool ambiguous = false;
  std::string why;
  geometry::CircleCylinderTopology topology = geometry::CircleCylinderTopology::inside;
  /// Distinct real roots in [0, 2 pi), sorted by angle.
  std::vector<ReferenceRoot> roots;
  /// Maximal arcs strictly outside the cylinder, each as (begin, end) counter-clockwise.
  std::vector<std::array<Real, 2>> outside_arcs;

  int root_count() const;
};

CylinderReference reference_circle_cylinder(const geometry::Circle3& circle,
                                            const geometry::Cylinder3& cylinder);

/// G(angle) / |axis|^2 = dist(x(angle), axis)^2 - R^2 (m^2): positive outside the cylinder.
Real cylinder_excess(const geometry::Circle3& circle, const geometry::Cylinder3& cylinder,
                     const Real& angle);

/// The rim point farthest from the cylinder's axis.
struct FarthestReach {
  bool ambiguous = false;  ///< the maximum could not be located (a rim at constant distance)
  Real distance;           ///< its distance from the axis (m)
  Real angle;
  RealVector point;
  RealVector radial;       ///< unit vector from the axis to the point, perpendicular to the axis
};
FarthestReach farthest_reach(const geometry::Circle3& circle, const geometry::Cylinder3& cylinder);

struct PlaneReference {
  geometry::CirclePlaneTopology topology = geometry::CirclePlaneTopology::disjoint;
  int side = 0;
  /// Distinct crossings sorted by angle; a tangent point has multiplicity_hint 2 (decided exactly).
  std::vector<ReferenceRoot> roots;
  /// Largest signed distance of a rim point (m) and the angle where it is reached (any angle for a
  /// rim parallel to the plane).
  Real max_signed_distance;
  Real deepest_angle;
  /// Whether the rim has points strictly on the positive side.
  bool has_positive_points = false;
};
PlaneReference reference_circle_plane(const geometry::Circle3& circle, const geometry::Plane3& plane);

/// Signed distance (m) of the rim point at `angle` from the plane, positive on the normal's side.
Real plane_signed_distance(const geometry::Circle3& circle, const geometry::Plane3& plane,
                           const Real& angle);

/// The rim point at `angle` (frame_of's parametrisation, in MPFR).
RealVector rim_point(const geometry::Circle3& circle, const Real& angle);

/// Distance between two angles on the circle, in [0, pi].
Real circular_distance(const Real& a, const Real& b);
/// Euclidean distance between a double point and a reference point.
Real distance(const geometry::Vector3& p, const RealVector& q);

Real two_pi();

}  // namespace clearjoint::test::reference
