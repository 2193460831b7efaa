// SPDX-License-Identifier: BSD-3-Clause
#include "circle_plane_exact.hpp"

#include <CGAL/Gmpq.h>

#include "exact_rational_point.hpp"

namespace clearjoint::geometry::detail {
namespace {

using Rational = CGAL::Gmpq;
struct RationalVector {
  Rational x, y, z;
};
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
  const RationalVector nc = exact(circle.normal), np = exact(plane.normal);
  const Rational s = np.x * (c.x - p.x) + np.y * (c.y - p.y) + np.z * (c.z - p.z);
  const Rational wx = np.y * nc.z - np.z * nc.y;
  const Rational wy = np.z * nc.x - np.x * nc.z;
  const Rational wz = np.x * nc.y - np.y * nc.x;
  const Rational w2 = wx * wx + wy * wy + wz * wz;
  const int side = CGAL::sign(s);
  if (CGAL::is_zero(w2)) {
    return side == 0 ? CirclePlaneTopologyAndSide{CirclePlaneTopology::circle_in_plane, 0}
                     : CirclePlaneTopologyAndSide{CirclePlaneTopology::disjoint, side};
  }
  const Rational r = circle.radius;
  const Rational nc2 = nc.x * nc.x + nc.y * nc.y + nc.z * nc.z;
  switch (CGAL::sign(s * s * nc2 - r * r * w2)) {
    case CGAL::POSITIVE: return {CirclePlaneTopology::disjoint, side};
    case CGAL::ZERO: return {CirclePlaneTopology::tangent, side};
    default: return {CirclePlaneTopology::two_crossings, 0};
  }
}

}  // namespace clearjoint::geometry::detail
