// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Checks shared by the internal tests that compare a Bounded (error_bounded.hpp) with a 256-bit
/// MPFR reference, and the random directions their pose generators start from.

#include <gtest/gtest.h>

#include <random>

#include "arithmetic/error_bounded.hpp"
#include "mpfr_reference.hpp"

namespace clearjoint::geometry::internal_testing {

/// |truth - b.value| <= b.error, allowing the reference's own error (kReferenceRelativeError of
/// `scale`, the size of the largest term behind the quantity).
inline ::testing::AssertionResult Encloses(const detail::Bounded& b, const Real& truth,
                                           const Real& scale) {
  if (!b.finite()) return ::testing::AssertionFailure() << "non-finite bound";
  const Real distance = abs(truth - Real(b.value));
  if (distance <= Real(b.error) + kReferenceRelativeError * scale) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "value " << b.value << " error " << b.error
                                       << " misses " << truth.str(30) << " by "
                                       << (distance - Real(b.error)).str(6);
}

/// A direction uniform on the sphere.
inline Vector3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Vector3(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

}  // namespace clearjoint::geometry::internal_testing
