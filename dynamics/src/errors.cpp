// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/errors.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace clearjoint::dynamics {

namespace {

/// The lengths a direction may have (require_nonzero): those whose square is a normal double,
/// [sqrt(DBL_MIN), sqrt(DBL_MAX)], so that v / sqrt(v . v) is a unit vector.
constexpr double kSmallestDirectionLength = 1.4916681462400413e-154;  // sqrt(DBL_MIN)
constexpr double kLargestDirectionLength = 1.3407807929942596e154;    // sqrt(DBL_MAX)

}  // namespace

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
  // The kernel's words for the same fault (geometry's validate(PartPose)).
  if ((v.array() == 0.0).all()) throw ModelError(field, " = " + format_vector(v) + ": must not be the zero vector");
  // The dynamics use a direction normalised as v / sqrt(v . v): v . v must be a normal double.
  // A non-zero vector outside that range (its square underflows to 0 or overflows to infinity)
  // would become 0 or stay unnormalised, silently.
  const double squared = v.squaredNorm();
  if (!(squared >= std::numeric_limits<double>::min() && squared <= std::numeric_limits<double>::max())) {
    throw ModelError(field, " = " + format_vector(v) + ": its length must lie in [" +
                                format_shortest(kSmallestDirectionLength) + ", " +
                                format_shortest(kLargestDirectionLength) +
                                "], where it can be normalised in double (only the direction counts: rescale it)");
  }
}

}  // namespace clearjoint::dynamics
