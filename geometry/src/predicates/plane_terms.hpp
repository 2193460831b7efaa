// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The quantities that decide a rim against a plane (docs/circle-plane.md; paper eqs. 11-15),
// written once over the number type T:
//   s = n_p . (c - p),  w = n_p x n_c,  |w|^2,  |n_c|^2,  |n_p|^2,
//   discriminant = s^2 |n_c|^2 - r^2 |w|^2,
// the rim strictly on one side of the plane iff the discriminant is positive (the side of s).
// Instances: Twinned (a value and its absolute-value twin: the a priori bounds) and Bounded (the
// running error bound) in rim_plane_quantities.cpp, GMP's integers in circle_plane_exact.cpp
// (the exact tier; this header includes no CGAL or GMP header). The order of the operations is
// part of the definition: the floating-point instances' bits, and the a priori bounds' chains of
// roundings (rim_plane_quantities.cpp), follow from it.

#include "vector3_of.hpp"

namespace clearjoint::geometry::detail {

template <class T>
struct PlaneTerms {
  T s;             ///< n_p . (c - p)
  Vector3Of<T> w;  ///< n_p x n_c
  T w2, nc2, np2;  ///< |w|^2, |n_c|^2, |n_p|^2
  T discriminant;  ///< s^2 |n_c|^2 - r^2 |w|^2
};

/// Who asks: the floating-point filters want every term; the exact tier decides signs only and
/// leaves out |n_p|^2 (for the depth and the widening), five exact operations.
enum class PlaneTermsFor { filters, signs };

/// The terms from the offset c - p (formed by the caller: each number type has its own exact or
/// rounded difference, and the a priori chains count it as one rounding), the two normals and
/// the radius. For PlaneTermsFor::signs, np2 is T{}.
template <PlaneTermsFor kFor = PlaneTermsFor::filters, class T>
PlaneTerms<T> plane_terms(const Vector3Of<T>& offset, const Vector3Of<T>& n_c, const Vector3Of<T>& n_p,
                          const T& r) {
  const T s = n_p.x * offset.x + n_p.y * offset.y + n_p.z * offset.z;
  const Vector3Of<T> w{n_p.y * n_c.z - n_p.z * n_c.y, n_p.z * n_c.x - n_p.x * n_c.z, n_p.x * n_c.y - n_p.y * n_c.x};
  const T w2 = w.x * w.x + w.y * w.y + w.z * w.z;
  const T nc2 = n_c.x * n_c.x + n_c.y * n_c.y + n_c.z * n_c.z;
  const T np2 = [&] {
    if constexpr (kFor == PlaneTermsFor::filters) return n_p.x * n_p.x + n_p.y * n_p.y + n_p.z * n_p.z;
    return T{};
  }();
  return {s, w, w2, nc2, np2, s * s * nc2 - r * r * w2};
}

}  // namespace clearjoint::geometry::detail
