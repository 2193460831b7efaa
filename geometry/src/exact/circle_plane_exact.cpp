// SPDX-License-Identifier: BSD-3-Clause
#include "circle_plane_exact.hpp"

#include <CGAL/Gmpq.h>

#include "exact_rational_point.hpp"
#include "plane_terms.hpp"

namespace clearjoint::geometry::detail {
namespace {

using Rational = CGAL::Gmpq;
using RationalVector = Vector3Of<Rational>;
RationalVector exact(const Vector3& v) { return {v.x(), v.y(), v.z()}; }
RationalVector exact(const Vector3& stored, const RoundedPoint* recipe, int scale_exponent) {
  if (recipe == nullptr) return exact(stored);
  const std::array<Rational, 3> x = exact_rational_point(*recipe, scale_exponent);
  return {x[0], x[1], x[2]};
}

}  // namespace

CirclePlaneTopologyAndSide exact_circle_plane_topology(const Circle3& circle, const Plane3& plane,
                                                       const RoundedPoint* centre,
                                                       const RoundedPoint* point, int scale_exponent) {
  const RationalVector c = exact(circle.center, centre, scale_exponent);
  const RationalVector p = exact(plane.point, point, scale_exponent);
  // The same terms the floating-point filters bound (plane_terms.hpp), here exact.
  const PlaneTerms<Rational> t = plane_terms<PlaneTermsFor::signs>(
      RationalVector{c.x - p.x, c.y - p.y, c.z - p.z}, exact(circle.normal), exact(plane.normal),
      Rational(circle.radius));
  const int side = CGAL::sign(t.s);
  if (CGAL::is_zero(t.w2)) {
    return side == 0 ? CirclePlaneTopologyAndSide{CirclePlaneTopology::circle_in_plane, 0}
                     : CirclePlaneTopologyAndSide{CirclePlaneTopology::disjoint, side};
  }
  switch (CGAL::sign(t.discriminant)) {
    case CGAL::POSITIVE: return {CirclePlaneTopology::disjoint, side};
    case CGAL::ZERO: return {CirclePlaneTopology::tangent, side};
    default: return {CirclePlaneTopology::two_crossings, 0};
  }
}

}  // namespace clearjoint::geometry::detail
