// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Input checks shared by every validate(): each failure throws InvalidInput naming the field and
// the value, e.g. "circle.radius = -1: must be positive".
//
// The checks run on every query, so the test is inline and branch-light (x - x is 0 exactly when
// x is finite, NaN otherwise) and only the reporting, which formats text, is out of line.

#include <string>
#include <string_view>

#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/primitives.hpp"

namespace clearjoint::geometry::detail {

/// Shortest text that reads back to the same double ("0.1", "1e-160", "nan", "inf").
std::string format(double x);
std::string format(const Vector3& v);

[[noreturn]] void reject(std::string_view name, std::string_view field, const std::string& value,
                         std::string_view why);
[[noreturn]] void reject_not_finite(const Vector3& v, std::string_view name, std::string_view field);
[[noreturn]] void reject_zero(const Vector3& v, std::string_view name, std::string_view field);
[[noreturn]] void reject_not_positive(double x, std::string_view name, std::string_view field);
[[noreturn]] void reject_out_of_range(const std::string& value, std::string_view name, std::string_view field);

/// Whether every x is finite: x - x is +0 for a finite x and NaN for an infinite or NaN one, and
/// a sum of such terms is 0 exactly when every term is. One comparison and branch for the lot.
template <class... Doubles>
bool every_value_finite(Doubles... x) {
  return ((x - x) + ...) == 0.0;
}
inline bool all_finite(const Vector3& v) { return every_value_finite(v.x(), v.y(), v.z()); }

/// A length in [kSmallestAcceptedLength, kLargestAcceptedLength] (NaN fails both comparisons).
inline bool length_in_range(double x) {
  const double magnitude = x < 0.0 ? -x : x;
  return (magnitude >= kSmallestAcceptedLength) & (magnitude <= kLargestAcceptedLength);
}
/// Each coordinate 0 or a length in range: bitwise, one branch for the lot.
inline bool coordinates_in_range(const Vector3& v) {
  return (length_in_range(v.x()) | (v.x() == 0.0)) & (length_in_range(v.y()) | (v.y() == 0.0)) &
         (length_in_range(v.z()) | (v.z() == 0.0));
}

inline void require_finite(const Vector3& v, std::string_view name, std::string_view field) {
  if (!all_finite(v)) [[unlikely]] reject_not_finite(v, name, field);
}

inline void require_nonzero(const Vector3& v, std::string_view name, std::string_view field) {
  if (v.x() == 0.0 && v.y() == 0.0 && v.z() == 0.0) [[unlikely]] reject_zero(v, name, field);
}

/// Finite and > 0 (NaN fails the comparison, +infinity the finiteness test).
inline void require_positive(double x, std::string_view name, std::string_view field) {
  if (!(x > 0.0 && x - x == 0.0)) [[unlikely]] reject_not_positive(x, name, field);
}

}  // namespace clearjoint::geometry::detail
