// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The circle of the MPFR references (joint_reference.cpp: the journal's rims;
/// pin_in_hole_reference.cpp: the hole's edges and the stops' outer circles), with the one frame
/// both build in its plane. Bench-only code, never linked into the library.

#include "joint_reference.hpp"

namespace clearjoint::bench {

/// x(theta) = center + radius (u cos theta + v sin theta), u and v orthonormal in the circle's
/// plane. Any such frame gives the same points; the references' angles are their own.
struct ReferenceCircle {
  RealVector center;
  RealVector normal;  // unit
  RealVector u, v;
  Real radius;

  RealVector at(const Real& c, const Real& s) const {
    return add(center, scale(radius, add(scale(c, u), scale(s, v))));
  }
  RealVector at(const Real& angle) const { return at(cos(angle), sin(angle)); }
};

/// The circle about `center` in the plane normal to the unit `normal_hat`: u is normal_hat
/// crossed with the coordinate axis least along it (never nearly parallel to it), normalised, and
/// v = normal_hat x u.
inline ReferenceCircle make_reference_circle(const RealVector& center, const RealVector& normal_hat,
                                             const Real& radius) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (abs(normal_hat[i]) < abs(normal_hat[k])) k = i;
  }
  RealVector e{Real(0), Real(0), Real(0)};
  e[k] = 1;
  ReferenceCircle circle;
  circle.center = center;
  circle.normal = normal_hat;
  circle.u = normalized(cross(normal_hat, e));
  circle.v = cross(normal_hat, circle.u);
  circle.radius = radius;
  return circle;
}

}  // namespace clearjoint::bench
