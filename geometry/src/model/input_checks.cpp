// SPDX-License-Identifier: BSD-3-Clause
#include "model/input_checks.hpp"

#include <cmath>
#include <sstream>

namespace clearjoint::geometry::detail {

std::string format(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

std::string format(const Vector3& v) {
  std::ostringstream out;
  out.precision(17);
  out << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return out.str();
}

void reject(std::string_view name, std::string_view field, const std::string& value,
            std::string_view why) {
  std::string path(name);
  path.append(".").append(field);
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
