// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Sturm chains of integer polynomials for the real-root isolation (real_root_isolation.hpp), and
// their sign variations at a point, which count the distinct real roots between two points.

#include <cstddef>

#include "arithmetic/error_bounded.hpp"
#include "exact/integer_polynomial.hpp"

namespace clearjoint::geometry::detail {

/// A Sturm chain: p, p', then the remainders, held inside the object up to kInlineCoefficients
/// members (those of a polynomial of degree 4).
using SturmChain = SmallVector<IntegerPolynomial>;

/// p, p', then -rem of the last two (times positive factors, which leave every sign as it is),
/// until a constant or a zero remainder (the last member is then a multiple of gcd(p, p')).
/// The positive factors are those of the subresultant remainder sequence (Cohen, "A Course in
/// Computational Algebraic Number Theory", algorithm 3.3.1): each pseudo-remainder is divided
/// exactly by |g h^delta|, which keeps the coefficients' growth linear in the degree without the
/// gcds a primitive sequence takes (a member's sign pattern only matters, and the subresultant
/// members differ from the Euclidean remainders by nonzero constants; their magnitudes do not
/// depend on the signs the Sturm sequence gives the members). Where the members have more bits
/// than the filters' precision, the last members come from ball arithmetic when it decides them
/// (filtered_last_members, filtered_linear_remainder_sign); with fewer the exact remainders cost
/// less than the balls.
SturmChain sturm_chain(const IntegerPolynomial& p);

/// Sign changes along the chain at x (zeros skipped), and the sign of its first member there.
struct ChainSigns {
  int variations = 0;
  int first = 0;
};
/// (`Chain`: a SturmChain, or a std::vector of its members where the members' type is incomplete
/// at the holder's declaration, as in SturmSequence.)
template <class Chain, class Point>
ChainSigns chain_signs(const Chain& chain, const Point& x) {
  const Bounded approximate = bounded(x);
  ChainSigns out;
  int last = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const int s = sign_at(chain[i], x, approximate);
    if (i == 0) out.first = s;
    if (s == 0) continue;
    if (last != 0 && s != last) ++out.variations;
    last = s;
  }
  return out;
}

}  // namespace clearjoint::geometry::detail
