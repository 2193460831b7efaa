// SPDX-License-Identifier: BSD-3-Clause
#include "exact/circle_plane_exact.hpp"

#include <array>

#include "exact/exact_dyadic.hpp"
#include "exact/exact_rational_point.hpp"
#include "predicates/plane_terms.hpp"

namespace clearjoint::geometry::detail {
namespace {

std::array<ExactDyadic, 3> exact(const Vector3& v) { return {exact_dyadic(v.x()), exact_dyadic(v.y()), exact_dyadic(v.z())}; }
std::array<ExactDyadic, 3> exact(const Vector3& stored, const RoundedPoint* recipe, int scale_exponent) {
  return recipe == nullptr ? exact(stored) : exact_dyadic_point(*recipe, scale_exponent);
}

}  // namespace

CirclePlaneTopologyAndSide exact_circle_plane_topology(const Circle3& circle, const Plane3& plane,
                                                       const RoundedPoint* centre,
                                                       const RoundedPoint* point, int scale_exponent) {
  const std::array<ExactDyadic, 3> c = exact(circle.center, centre, scale_exponent);
  const std::array<ExactDyadic, 3> p = exact(plane.point, point, scale_exponent);
  const std::array<ExactDyadic, 3> n_c = exact(circle.normal), n_p = exact(plane.normal);
  // The offset c - p, both normals and the radius as integers at one exponent: every term of
  // plane_terms is homogeneous in them (s of degree 2, |w|^2 of degree 4, the discriminant of
  // degree 6), so the integers give each term times a positive power of two, the same signs.
  std::array<ExactDyadic, 10> inputs;
  for (int i = 0; i < 3; ++i) {
    ExactDyadic minus_p = p[i];
    minus_p.mantissa = -minus_p.mantissa;
    inputs[i] = exact_sum(c[i], minus_p);
    inputs[3 + i] = n_c[i];
    inputs[6 + i] = n_p[i];
  }
  inputs[9] = exact_dyadic(circle.radius);
  const std::array<mpz_class, 10> x = integers_at_common_exponent(inputs).integers;
  // The same terms the floating-point filters bound (plane_terms.hpp), here exact.
  const PlaneTerms<mpz_class> t = plane_terms<PlaneTermsFor::signs>(
      Vector3Of<mpz_class>{x[0], x[1], x[2]}, Vector3Of<mpz_class>{x[3], x[4], x[5]},
      Vector3Of<mpz_class>{x[6], x[7], x[8]}, x[9]);
  const int side = sgn(t.s);
  if (sgn(t.w2) == 0) {
    return side == 0 ? CirclePlaneTopologyAndSide{CirclePlaneTopology::circle_in_plane, 0}
                     : CirclePlaneTopologyAndSide{CirclePlaneTopology::disjoint, side};
  }
  const int discriminant = sgn(t.discriminant);
  if (discriminant > 0) return {CirclePlaneTopology::disjoint, side};
  if (discriminant == 0) return {CirclePlaneTopology::tangent, side};
  return {CirclePlaneTopology::two_crossings, 0};
}

}  // namespace clearjoint::geometry::detail
