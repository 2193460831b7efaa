// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/errors.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace clearjoint::dynamics {

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string format_shortest(double value) {
  char buffer[32];
  char* end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::string format_vector(const Eigen::Ref<const Eigen::VectorXd>& v) {
  std::string text = "[";
  for (Eigen::Index k = 0; k < v.size(); ++k) {
    if (k > 0) text += ", ";
    text += format_number(v[k]);
  }
  return text + "]";
}

void require_finite(std::string_view field, double value) {
  if (!std::isfinite(value)) {
    throw ModelError(field, " = " + format_number(value) + ": must be finite");
  }
}

void require_finite(std::string_view field, const Eigen::Ref<const Eigen::VectorXd>& v) {
  if (!v.allFinite()) {
    throw ModelError(field, " = " + format_vector(v) + ": must be finite");
  }
}

void require_positive(std::string_view field, double value) {
  require_finite(field, value);
  if (!(value > 0.0)) {
    throw ModelError(field, " = " + format_number(value) + ": must be positive");
  }
}

void require_nonzero(std::string_view field, const Eigen::Ref<const Eigen::VectorXd>& v) {
  require_finite(field, v);
  // A direction is only used after normalisation; an exact zero has none. Tiny but non-zero
  // vectors are accepted: their direction is still defined in floating point.
  if (v.squaredNorm() == 0.0) {
    throw ModelError(field, " = " + format_vector(v) + ": must not be zero");
  }
}

}  // namespace clearjoint::dynamics
