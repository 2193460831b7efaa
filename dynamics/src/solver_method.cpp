// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/solver_method.hpp"

#include <cmath>
#include <string>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

std::string_view to_string(SolverMethod method) noexcept {
  switch (method) {
    case SolverMethod::dormand_prince: return "dormand_prince";
    case SolverMethod::moreau_jean: return "moreau_jean";
  }
  return "unknown";
}

SolverMethod solver_method_from_string(std::string_view name, std::string_view field) {
  for (SolverMethod method : {SolverMethod::dormand_prince, SolverMethod::moreau_jean}) {
    if (name == to_string(method)) return method;
  }
  throw ModelError(std::string(field) + " = \"" + std::string(name) +
                   "\": unknown solver method (expected \"dormand_prince\" or \"moreau_jean\")");
}

void validate(const MoreauJeanSettings& s, std::string_view field) {
  const std::string f(field);
  if (!(std::isfinite(s.step) && s.step > 0.0 && s.step <= kMaxMoreauJeanStep)) {
    throw ModelError(f + ".step = " + format_shortest(s.step) + ": must be finite, positive and at most " +
                     format_shortest(kMaxMoreauJeanStep) + " s");
  }
  if (!(s.theta >= 0.5 && s.theta <= 1.0)) {
    throw ModelError(f + ".theta = " + format_shortest(s.theta) + ": must be in [0.5, 1]");
  }
  if (!(s.contact_tolerance > 0.0 && s.contact_tolerance < 1.0)) {
    throw ModelError(f + ".contact_tolerance = " + format_shortest(s.contact_tolerance) +
                     ": must be in (0, 1)");
  }
  if (!(s.contact_max_iterations >= 1)) {
    throw ModelError(f + ".contact_max_iterations = " + std::to_string(s.contact_max_iterations) +
                     ": must be at least 1");
  }
}

}  // namespace clearjoint::dynamics
