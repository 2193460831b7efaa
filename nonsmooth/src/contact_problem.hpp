// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// One step's frictional contact problem in its local (reduced) form, solved by Siconos
/// Numerics' fc3d NSGS (nonsmooth Gauss-Seidel over the contacts, each contact's 3x3 problem by
/// the Alart-Curnier nonsmooth Newton method, Siconos's default local solver), and where NSGS
/// misses the tolerance, by fc3d PROX (the proximal point method, each regularised problem by a
/// nonsmooth Newton method on the whole problem):
///   u = W r + q,   K_mu ∋ r  ⟂  u + [mu |u_T|, 0, 0] ∈ K_mu*   (De Saxcé's formulation),
/// with u = [u_N, u_T1, u_T2] per contact, K_mu the Coulomb cone of each contact.

#include <Eigen/Core>

namespace clearjoint::nonsmooth {

struct ContactSolve {
  bool converged = false;
  int iterations = 0;  ///< NSGS sweeps
  double error = 0.0;  ///< fc3d's relative residual of the solution returned
  bool fallback = false;         ///< NSGS missed the tolerance and fc3d PROX was run
  int fallback_iterations = 0;   ///< PROX's iterations (fc3d's count)
};

/// Solve for r (3 per contact, initial guess on entry: the warm start, for both solvers) and u. W is
/// 3c x 3c, symmetric positive semi-definite; q and mu as above.
ContactSolve solve_contact_problem(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& mu, double tolerance, int max_iterations,
                                   Eigen::VectorXd& r, Eigen::VectorXd& u);

}  // namespace clearjoint::nonsmooth
