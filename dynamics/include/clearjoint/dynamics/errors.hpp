// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The two ways the dynamics module refuses to go on, and the checks that name the bad field.

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <string_view>

#include "clearjoint/validation_error.hpp"

namespace clearjoint::dynamics {

/// Bad input: a model, body, joint or setting that cannot describe a mechanism. A
/// ValidationError: its field path names the field ("bodies[1].mass") and what() the offending
/// value too, e.g. "bodies[1].mass = -0.3: must be positive". (The model file reader's own JSON
/// checks give the message only, with an empty path.)
class ModelError : public ValidationError {
 public:
  using ValidationError::ValidationError;
};

/// The equations cannot be solved from here on: singular or inconsistent constraints, a collapsed
/// step size, a state that stopped being finite. what() says when and why.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "[1, 2, 3]" with round-trip precision, for messages.
std::string format_vector(const Eigen::Ref<const Eigen::VectorXd>& v);
std::string format_number(double value);
/// The shortest text that reads back as `value` ("0.1", not format_number's
/// "0.10000000000000001"): for limits and tolerances quoted in messages.
std::string format_shortest(double value);

/// Throw ModelError "<field> = <value>: must be finite" unless every entry is finite.
void require_finite(std::string_view field, double value);
void require_finite(std::string_view field, const Eigen::Ref<const Eigen::VectorXd>& v);
/// Throw ModelError "<field> = <value>: must be positive" unless value > 0 (and finite).
void require_positive(std::string_view field, double value);
/// The one check of a direction in the dynamics (a joint or clearance part's axis, a groove
/// direction, Euler parameters before normalisation): throw ModelError unless every component is
/// finite, the vector is not the zero vector and its length lies in [sqrt(DBL_MIN),
/// sqrt(DBL_MAX)], where v / sqrt(v . v) is a unit vector in double.
void require_nonzero(std::string_view field, const Eigen::Ref<const Eigen::VectorXd>& v);

}  // namespace clearjoint::dynamics
