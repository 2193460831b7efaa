// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The quantities that decide a rim against a plane (docs/circle-plane.md; paper eqs. 11-15),
// written once over the number type T:
//   s = n_p . (c - p),  w = n_p x n_c,  |w|^2,  |n_c|^2,  |n_p|^2,
//   discriminant = s^2 |n_c|^2 - r^2 |w|^2,
// the rim strictly on one side of the plane iff the discriminant is positive (the side of s).
// Instances: Twinned (a value and its absolute-value twin: the a priori bounds) and Bounded (the
// running error bound) in rim_plane_quantities.cpp, GMP's integers in circle_plane_exact.cpp
// (the exact tier; this header includes no CGAL or GMP header), and s and the discriminant on
// ValueAndTwin<Pair> for two base planes at once (the axial prefilters,
// candidate_prefilter_lanes.hpp). The order of the operations is part of the definition: the
// floating-point instances' bits, and the a priori bounds' chains of roundings
// (rim_plane_quantities.cpp), follow from it.

#include "arithmetic/vector3_of.hpp"

namespace clearjoint::geometry::detail {

template <class T>
struct PlaneTerms {
  T s;             ///< n_p . (c - p)
  Vector3Of<T> w;  ///< n_p x n_c
  T w2, nc2, np2;  ///< |w|^2, |n_c|^2, |n_p|^2
  T discriminant;  ///< s^2 |n_c|^2 - r^2 |w|^2
};

/// The pieces, for callers that form some terms once for several planes (the axial prefilters of
/// candidate_prefilter_lanes.hpp: one w for both bases, an s per base in lanes). Operands may have
/// types of their own that T's operations take (ValueAndTwin<double> beside ValueAndTwin<Pair>).
/// Always inlined: GCC otherwise keeps them out of line for Bounded and the exact number type, a
/// call and a returned struct per term.
/// s = n_p . offset.
template <class N, class T>
[[gnu::always_inline]] inline T plane_offset(const Vector3Of<N>& n_p, const Vector3Of<T>& offset) {
  return n_p.x * offset.x + n_p.y * offset.y + n_p.z * offset.z;
}
/// |v|^2.
template <class T>
[[gnu::always_inline]] inline T squared_length(const Vector3Of<T>& v) {
  return v.x * v.x + v.y * v.y + v.z * v.z;
}
/// s^2 |n_c|^2 - r^2 |w|^2.
template <class S, class T>
[[gnu::always_inline]] inline S plane_discriminant(const S& s, const T& nc2, const T& r, const T& w2) {
  return s * s * nc2 - r * r * w2;
}

/// Who asks: the floating-point filters want every term; the exact tier decides signs only and
/// leaves out |n_p|^2 (for the depth and the widening), five exact operations.
enum class PlaneTermsFor { filters, signs };

/// The terms from the offset c - p (formed by the caller: each number type has its own exact or
/// rounded difference, and the a priori chains count it as one rounding), the two normals and
/// the radius. For PlaneTermsFor::signs, np2 is T{}.
template <PlaneTermsFor kFor = PlaneTermsFor::filters, class T>
PlaneTerms<T> plane_terms(const Vector3Of<T>& offset, const Vector3Of<T>& n_c, const Vector3Of<T>& n_p,
                          const T& r) {
  const T s = plane_offset(n_p, offset);
  const Vector3Of<T> w{n_p.y * n_c.z - n_p.z * n_c.y, n_p.z * n_c.x - n_p.x * n_c.z, n_p.x * n_c.y - n_p.y * n_c.x};
  const T w2 = squared_length(w);
  const T nc2 = squared_length(n_c);
  const T np2 = [&] {
    if constexpr (kFor == PlaneTermsFor::filters) return squared_length(n_p);
    return T{};
  }();
  return {s, w, w2, nc2, np2, plane_discriminant(s, nc2, r, w2)};
}

}  // namespace clearjoint::geometry::detail
