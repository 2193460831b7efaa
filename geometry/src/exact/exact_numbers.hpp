// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The exact tiers' number types: GMP integers, CGAL rationals and polynomials over them. CGAL
// headers: include only from the exact tiers' .cpp files.

#include <CGAL/Gmpq.h>
#include <CGAL/Polynomial.h>
#include <gmpxx.h>

#include <cstddef>

#include <boost/container/small_vector.hpp>

namespace clearjoint::geometry::detail {

using Integer = mpz_class;
using Rational = CGAL::Gmpq;
using RationalPolynomial = CGAL::Polynomial<Rational>;

/// Coefficients (or Sturm chain members) held inside their owner up to this count, on the heap
/// beyond it: a polynomial of degree 4 (the rim-cylinder eliminant P, docs/circle-cylinder.md)
/// has five coefficients and a Sturm chain of at most five members. One exact tangency forms
/// dozens of such polynomials and chains (Yun's factorisation, the chain's remainders, local
/// expansions); on the heap each would take a malloc and a free, held inline none.
/// (GMP's integers inside them still allocate.)
inline constexpr std::size_t kInlineCoefficients = 5;
template <class T>
using SmallVector = boost::container::small_vector<T, kInlineCoefficients>;

}  // namespace clearjoint::geometry::detail
