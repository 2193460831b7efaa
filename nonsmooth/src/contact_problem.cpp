// SPDX-License-Identifier: BSD-3-Clause
#include "contact_problem.hpp"

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <vector>

#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>

namespace clearjoint::nonsmooth {

namespace {

/// Every SolverOptions below `options` (its internal solvers', recursively), then `options`.
void collect_options(SolverOptions* options, std::vector<SolverOptions*>& found) {
  for (std::size_t k = 0; k < options->numberOfInternalSolvers; ++k) {
    if (options->internalSolvers[k] != nullptr) collect_options(options->internalSolvers[k], found);
  }
  found.push_back(options);
}

/// Siconos Numerics 4.4's solver_options_delete frees what a SolverOptions holds (its parameters,
/// its internal solvers' contents and their list) but not the structures solver_options_create
/// allocated: neither the options nor their internal solvers' (AddressSanitizer's leak report, one
/// NSGS options and its local solver's every step). They are collected before the delete and
/// freed after it.
struct OptionsDeleter {
  void operator()(SolverOptions* options) const {
    std::vector<SolverOptions*> structures;
    collect_options(options, structures);
    solver_options_delete(options);
    for (SolverOptions* structure : structures) std::free(structure);
  }
};
struct MatrixDeleter {
  void operator()(NumericsMatrix* matrix) const { NM_free(matrix); }
};

/// One fc3d_driver call with the solver's default options but the tolerance and iteration limit.
ContactSolve run_fc3d(FrictionContactProblem& problem, int solver, double tolerance, int max_iterations,
                      Eigen::VectorXd& r, Eigen::VectorXd& u) {
  std::unique_ptr<SolverOptions, OptionsDeleter> options(solver_options_create(solver));
  options->iparam[SICONOS_IPARAM_MAX_ITER] = max_iterations;
  options->dparam[SICONOS_DPARAM_TOL] = tolerance;
  const int info = fc3d_driver(&problem, r.data(), u.data(), options.get());
  ContactSolve solve;
  solve.converged = info == 0;
  solve.iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
  solve.error = options->dparam[SICONOS_DPARAM_RESIDU];
  return solve;
}

}  // namespace

ContactSolve solve_contact_problem(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& mu, double tolerance, int max_iterations,
                                   Eigen::VectorXd& r, Eigen::VectorXd& u) {
  const int n = static_cast<int>(q.size());
  if (n % 3 != 0 || W.rows() != n || W.cols() != n || mu.size() != n / 3 || r.size() != n) {
    throw std::logic_error("solve_contact_problem: inconsistent sizes");
  }
  u.resize(n);
  // Numerics owns and frees what a problem points at; the problem here is a plain struct on the
  // stack whose matrix is Numerics' own copy (dense, column-major as Eigen's).
  std::unique_ptr<NumericsMatrix, MatrixDeleter> matrix(NM_create(NM_DENSE, n, n));
  std::copy(W.data(), W.data() + static_cast<std::ptrdiff_t>(n) * n, matrix->matrix0);
  Eigen::VectorXd q_copy = q;
  Eigen::VectorXd mu_copy = mu;
  FrictionContactProblem problem{};
  problem.dimension = 3;
  problem.numberOfContacts = n / 3;
  problem.M = matrix.get();
  problem.q = q_copy.data();
  problem.mu = mu_copy.data();

  const Eigen::VectorXd r_start = r;
  ContactSolve solve = run_fc3d(problem, SICONOS_FRICTION_3D_NSGS, tolerance, max_iterations, r, u);
  if (!solve.converged) {
    // NSGS converges linearly, at a rate set by the coupling between contacts: two rim contacts
    // of a misaligned journal at nearly the same normal (W_NN's off-diagonal term close to its
    // diagonal ones) take it thousands of sweeps, though the problem is well posed. A Newton
    // method on the whole problem does not depend on that coupling, but W is singular in such
    // problems (tangential directions held by the ideal joints), where Alart-Curnier's plain
    // Newton method (fc3d NSN_AC) can stall. fc3d PROX, the proximal point method, solves a short
    // sequence of problems regularised by a multiple of I (positive definite) by fc3d NSN_AC
    // and solved every problem NSGS missed in the shipped slider-cranks (docs/nonsmooth.md). It
    // starts from the same r as NSGS (NSGS's last iterate can lie far from the solution), with
    // the same tolerance and iteration limit; if it misses too, the smaller error's r is kept.
    const Eigen::VectorXd r_nsgs = r;
    const Eigen::VectorXd u_nsgs = u;
    r = r_start;
    const ContactSolve fallback = run_fc3d(problem, SICONOS_FRICTION_3D_PROX, tolerance, max_iterations, r, u);
    solve.fallback = true;
    solve.fallback_iterations = fallback.iterations;
    if (fallback.converged || fallback.error < solve.error) {
      solve.converged = fallback.converged;
      solve.error = fallback.error;
    } else {
      r = r_nsgs;
      u = u_nsgs;
    }
  }
  return solve;
}

}  // namespace clearjoint::nonsmooth
