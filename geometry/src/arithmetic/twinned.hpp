// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A value beside its absolute-value twin (a_priori_bounds.hpp), the value in lane 0 of a Pair
// and the twin in lane 1 (pair_lanes.hpp): the number type of the a priori instance of a
// predicate written once over the number type (plane_terms.hpp).
//
// The twin is the expression on |inputs| with subtractions turned into additions. So + and *
// act on both lanes alike, and a - b subtracts b's value from a's and adds b's twin to a's
// twin: it subtracts b with its lane 1 negated, since x - (-y) rounds exactly as x + y (negation
// is exact). One chain of packed operations then forms both, each lane rounded exactly as the
// scalar operation, so the bits of the value and of the twin are those of the two computed one
// after the other (test: test_rim_plane_quantities.cpp).

#include <cmath>

#include "pair_lanes.hpp"

namespace clearjoint::geometry::detail {

struct Twinned {
  Pair lanes;  ///< {value, twin}

  /// An exact input x: {x, |x|}.
  static Twinned of(double x) {
    const PairMask kAllButLane1Sign = ~bits_of(Pair{0.0, -0.0});
    return {pair_of_bits(bits_of(Pair{x, x}) & kAllButLane1Sign)};
  }
  double value() const { return lanes[0]; }
  double twin() const { return lanes[1]; }
};

/// x with the sign of lane 1 flipped.
inline Pair twin_negated(Pair x) {
  const PairMask kLane1Sign = bits_of(Pair{0.0, -0.0});
  return pair_of_bits(bits_of(x) ^ kLane1Sign);
}

inline Twinned operator+(Twinned a, Twinned b) { return {a.lanes + b.lanes}; }
inline Twinned operator-(Twinned a, Twinned b) { return {a.lanes - twin_negated(b.lanes)}; }
inline Twinned operator*(Twinned a, Twinned b) { return {a.lanes * b.lanes}; }

}  // namespace clearjoint::geometry::detail
