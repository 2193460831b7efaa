#pragma once
// Input checks shared by every validate(): each failure throws InvalidInput naming the field and
// the value, e.g. "circle.radius = -1: must be positive".

#include <string>
#include <string_view>

#include "clearjoint/geometry/primitives.hpp"

namespace clearjoint::geometry::detail {

/// Shortest text that reads back to the same double (17 significant digits).
std::string format(double x);
std::string format(const Vector3& v);

[[noreturn]] void reject(std::string_view name, std::string_view field, const std::string& value,
                         std::string_view why);

void require_finite(const Vector3& v, std::string_view name, std::string_view field);
void require_nonzero(const Vector3& v, std::string_view name, std::string_view field);
void require_positive(double x, std::string_view name, std::string_view field);

}  // namespace clearjoint::geometry::detail
