// SPDX-License-Identifier: BSD-3-Clause
#include "exact/parallel_axes_exact.hpp"

#include <CGAL/Gmpq.h>

namespace clearjoint::geometry::detail {

bool exact_products_equal(double a, double b, double c, double d) {
  return CGAL::Gmpq(a) * CGAL::Gmpq(b) == CGAL::Gmpq(c) * CGAL::Gmpq(d);
}

}  // namespace clearjoint::geometry::detail
