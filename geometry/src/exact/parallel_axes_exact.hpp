// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Exact fallback of eq. (5)'s test (a_i x a_j = 0) for axis components outside the range of
// Dekker's two-product (primitives_detail.hpp): CGAL rationals, in an exact-tier file so that the
// floating-point files include no CGAL header.

namespace clearjoint::geometry::detail {

/// a*b == c*d in real arithmetic, for any finite doubles.
bool exact_products_equal(double a, double b, double c, double d);

}  // namespace clearjoint::geometry::detail
