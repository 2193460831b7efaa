// SPDX-License-Identifier: BSD-3-Clause
#include "model/input_checks.hpp"

#include <charconv>
#include <cmath>

namespace clearjoint::geometry::detail {

std::string format(double x) {
  // Shortest round trip (std::to_chars without a precision): "0.1", not "0.10000000000000001",
  // so that a message quotes the value as the caller wrote it.
  char buffer[32];
  char* end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, end);
}

std::string format(const Vector3& v) {
  return '[' + format(v.x()) + ", " + format(v.y()) + ", " + format(v.z()) + ']';
}

void reject(std::string_view name, std::string_view field, const std::string& value,
            std::string_view why) {
  // An empty name: the caller's description has the fields at its top level.
  std::string path(name);
  if (!path.empty()) path.append(".");
  path.append(field);
  throw InvalidInput(path, " = " + value + ": " + std::string(why));
}

void reject_not_finite(const Vector3& v, std::string_view name, std::string_view field) {
  reject(name, field, format(v), "every component must be finite");
}

void reject_zero(const Vector3& v, std::string_view name, std::string_view field) {
  reject(name, field, format(v), "must not be the zero vector");
}

void reject_not_positive(double x, std::string_view name, std::string_view field) {
  reject(name, field, format(x), std::isfinite(x) ? "must be positive" : "must be finite");
}

void reject_out_of_range(const std::string& value, std::string_view name, std::string_view field) {
  reject(name, field, value,
         "a magnitude outside [1e-150, 1e150], the range of lengths accepted (rescale the joint: "
         "any unit will do; a coordinate may also be 0)");
}

}  // namespace clearjoint::geometry::detail
