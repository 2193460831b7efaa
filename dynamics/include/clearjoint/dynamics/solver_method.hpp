// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Which integrator runs a model (a model file's solver.method), and the settings of the
/// non-smooth one, plain data: the compliant integrator is in this module (integrator.hpp), the
/// Moreau-Jean time-stepping scheme in clearjoint::nonsmooth (docs/nonsmooth.md).

#include <string_view>

namespace clearjoint::dynamics {

enum class SolverMethod {
  /// Compliant contact forces, Dormand-Prince 5(4) with error control (integrator.hpp).
  dormand_prince,
  /// Rigid contact: unilateral constraints, Coulomb friction and Newton's impact law, integrated
  /// by Moreau-Jean's theta-method at a fixed step (clearjoint::nonsmooth).
  moreau_jean,
};

/// "dormand_prince", "moreau_jean" (the model-file spellings).
std::string_view to_string(SolverMethod method) noexcept;
/// The inverse of to_string; throws ModelError `<field> = "<name>": unknown solver method
/// (expected "dormand_prince" or "moreau_jean")`.
SolverMethod solver_method_from_string(std::string_view name, std::string_view field);

/// Largest MoreauJeanSettings::step [s]: a step of 10 ms already spans a whole impact sequence
/// of the paper's mechanisms (crank period 42 ms at 150 rad/s), so the scheme would see the
/// mechanism move by a large part of its clearance between two detections.
inline constexpr double kMaxMoreauJeanStep = 1e-2;
/// Default MoreauJeanSettings::contact_tolerance: the relative residual of Siconos's fc3d
/// (the natural-map error divided by |q|, fc3d_compute_error); 1e-10 leaves the percussions
/// about six orders above rounding and is what Siconos's own examples of impacting mechanisms
/// ask of NSGS.
inline constexpr double kDefaultContactTolerance = 1e-10;
/// Default MoreauJeanSettings::contact_max_iterations: NSGS sweeps; a joint has at most six
/// contacts, whose problems converge in tens of sweeps, so 1000 only stops a stalled solve.
inline constexpr int kDefaultContactMaxIterations = 1000;

struct MoreauJeanSettings {
  double step = 1e-5;   ///< h [s], fixed
  double theta = 0.5;   ///< theta of the position update, in [0.5, 1] (docs/nonsmooth.md)
  double contact_tolerance = kDefaultContactTolerance;  ///< fc3d NSGS tolerance (relative)
  int contact_max_iterations = kDefaultContactMaxIterations;  ///< fc3d NSGS sweeps
  /// A step whose contact problem did not converge: false (default) keeps its last iterate and
  /// goes on, counting it in the summary with its time; true stops the run (SolverError).
  bool stop_on_unconverged = false;
};

/// Throw ModelError naming `<field>.step` etc. unless step is finite, positive and at most
/// kMaxMoreauJeanStep, theta in [0.5, 1], the tolerance finite in (0, 1) and the iteration limit
/// positive.
void validate(const MoreauJeanSettings& settings, std::string_view field);

}  // namespace clearjoint::dynamics
