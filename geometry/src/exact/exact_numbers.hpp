// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The exact tiers' number types: GMP integers, CGAL rationals and polynomials over them. CGAL
// headers: include only from the exact tiers' .cpp files.

#include <CGAL/Gmpq.h>
#include <CGAL/Polynomial.h>
#include <gmpxx.h>

namespace clearjoint::geometry::detail {

using Integer = mpz_class;
using Rational = CGAL::Gmpq;
using RationalPolynomial = CGAL::Polynomial<Rational>;

}  // namespace clearjoint::geometry::detail
