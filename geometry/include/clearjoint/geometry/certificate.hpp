// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How far a numeric answer can be trusted.

#include <string_view>

namespace clearjoint::geometry {

/// Trust level of an answer, from strongest to weakest.
enum class Certainty {
  /// Decided with exact rational arithmetic on the stored doubles (CGAL); for detect_contacts,
  /// on the joint those doubles define (exact base centres, joint_geometry.hpp).
  exact,
  /// Proved with floating-point arithmetic and rigorous error bounds (interval or
  /// running-error analysis): the true answer lies in the reported enclosures.
  certified,
  /// Not proved; `Certificate::reason` says why (certificate switched off, or the exact
  /// fallback disabled and the interval proof failed).
  uncertain,
};

/// A trust level and, for anything but `certified`, why. `reason` points to a static string.
struct Certificate {
  Certainty level = Certainty::certified;
  const char* reason = "";
};

std::string_view to_string(Certainty level) noexcept;

/// The weaker of two certificates (used to combine the parts of one answer). Inline: detection
/// combines three or four per call, and the out-of-line call cost more than the comparison.
constexpr Certificate weakest(const Certificate& a, const Certificate& b) noexcept {
  // The enum lists levels from strongest to weakest, so the larger value is the weaker one.
  return static_cast<int>(b.level) > static_cast<int>(a.level) ? b : a;
}

}  // namespace clearjoint::geometry
