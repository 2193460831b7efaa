// SPDX-License-Identifier: BSD-3-Clause
#include "contact_problem.hpp"

#include <memory>
#include <stdexcept>

#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>

namespace clearjoint::nonsmooth {

namespace {

struct OptionsDeleter {
  void operator()(SolverOptions* options) const { solver_options_delete(options); }
};
struct MatrixDeleter {
  void operator()(NumericsMatrix* matrix) const { NM_free(matrix); }
};

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

  std::unique_ptr<SolverOptions, OptionsDeleter> options(solver_options_create(SICONOS_FRICTION_3D_NSGS));
  options->iparam[SICONOS_IPARAM_MAX_ITER] = max_iterations;
  options->dparam[SICONOS_DPARAM_TOL] = tolerance;
  const int info = fc3d_driver(&problem, r.data(), u.data(), options.get());
  ContactSolve solve;
  solve.converged = info == 0;
  solve.iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
  solve.error = options->dparam[SICONOS_DPARAM_RESIDU];
  return solve;
}

}  // namespace clearjoint::nonsmooth
