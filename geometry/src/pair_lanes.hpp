// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Two doubles side by side in one SSE2 register (GCC/Clang vector extensions, baseline x86-64),
// the kernel's one lane type: the magnitude guards of rim_distance_polynomial.cpp test two
// values at once, tier 1 of certified_rim_roots.cpp runs its two roots' Halley iterations and
// proofs in the two lanes, and candidate_prefilter_lanes.hpp's Lanes (bases A and B, or a value
// and its twin) are Pairs too.
//
// Bit for bit: a packed operation rounds each lane exactly as the scalar operation would (IEEE
// binary64, round to nearest; the build targets no FMA to contract into), so an expression
// written once as a template over double and Pair (the angle addition and the polynomial of
// rim_distance_polynomial.hpp) gives in each lane the bits the scalar call gives. A scalar
// operand is broadcast to both lanes.

#include <cmath>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace clearjoint::geometry::detail {

using Pair = double __attribute__((vector_size(16)));
/// Lane masks, as comparisons of Pairs give them: -1 (all bits set) where true, 0 where false.
using PairMask = decltype(Pair{} < Pair{});

inline bool all_lanes(PairMask m) { return (m[0] & m[1]) != 0; }
inline bool any_lane(PairMask m) { return (m[0] | m[1]) != 0; }

/// a in the lanes where `mask` is set, b in the others: a bitwise blend (SSE2 has no blendv;
/// GCC's vector ?: went through general registers lane by lane).
inline Pair select(PairMask mask, Pair a, Pair b) {
  return reinterpret_cast<Pair>((mask & reinterpret_cast<PairMask>(a)) |
                                (~mask & reinterpret_cast<PairMask>(b)));
}

/// |x|, for the templates over double and Pair.
inline double magnitude(double x) { return std::fabs(x); }
/// |x| per lane: the sign bit cleared, as std::fabs does for a double.
inline Pair magnitude(Pair x) {
  const PairMask kMagnitudeBits = {0x7fff'ffff'ffff'ffff, 0x7fff'ffff'ffff'ffff};
  return reinterpret_cast<Pair>(reinterpret_cast<PairMask>(x) & kMagnitudeBits);
}

/// The correctly rounded square root of each lane, as std::sqrt gives it for a double (sqrtpd
/// on SSE2; one lane at a time elsewhere).
inline Pair square_root(Pair x) {
#ifdef __SSE2__
  return reinterpret_cast<Pair>(_mm_sqrt_pd(reinterpret_cast<__m128d>(x)));
#else
  return Pair{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

}  // namespace clearjoint::geometry::detail
