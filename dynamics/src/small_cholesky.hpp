// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Cholesky factorisation and solve of the small symmetric positive definite Schur matrix
/// Phi_q M^-1 Phi_q^T (eq. 38), in place, for the right-hand side.
///
/// Hand-written rather than Eigen::LLT: for the 5-30 equations of the mechanisms here, Eigen's
/// dynamic-size LLT runs its general kernels (a matrix-vector product per column, blocked
/// triangular solves), whose set-up costs exceed the arithmetic at these sizes (perf shows them
/// in a clearance-joint simulation's profile); this is a few hundred multiply-adds in plain loops. Column-major, right-looking, so that every inner
/// loop runs down a column.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace clearjoint::dynamics::detail {

/// Smallest and largest pivot (squared diagonal of L) of a factorisation.
struct CholeskyPivots {
  double smallest = 0.0;
  double largest = 0.0;
};

/// Overwrite the lower triangle of the symmetric `a` (only that triangle is read) with L, a = L
/// L^T. Returns false, with `pivots` up to the failing column, if a pivot is not positive.
inline bool factor_cholesky_in_place(Eigen::MatrixXd& a, CholeskyPivots& pivots) {
  const Eigen::Index n = a.rows();
  pivots = {INFINITY, 0.0};
  for (Eigen::Index j = 0; j < n; ++j) {
    const double pivot = a(j, j);
    if (!(pivot > 0.0)) {
      pivots.smallest = std::min(pivots.smallest, pivot);
      return false;
    }
    pivots.smallest = std::min(pivots.smallest, pivot);
    pivots.largest = std::max(pivots.largest, pivot);
    const double d = std::sqrt(pivot);
    a(j, j) = d;
    double* column_j = &a(0, j);
    for (Eigen::Index i = j + 1; i < n; ++i) column_j[i] /= d;
    for (Eigen::Index k = j + 1; k < n; ++k) {
      const double l_kj = column_j[k];
      if (l_kj == 0.0) continue;  // block-sparse Schur matrices have many zero columns here
      double* column_k = &a(0, k);
      for (Eigen::Index i = k; i < n; ++i) column_k[i] -= column_j[i] * l_kj;
    }
  }
  return true;
}

/// Solve L L^T x = b in place (x holds b on entry), L from factor_cholesky_in_place.
inline void solve_cholesky_in_place(const Eigen::MatrixXd& l, Eigen::VectorXd& x) {
  const Eigen::Index n = l.rows();
  for (Eigen::Index j = 0; j < n; ++j) {  // L y = b
    x[j] /= l(j, j);
    const double y_j = x[j];
    if (y_j == 0.0) continue;
    const double* column_j = &l(0, j);
    for (Eigen::Index i = j + 1; i < n; ++i) x[i] -= column_j[i] * y_j;
  }
  for (Eigen::Index j = n; j-- > 0;) {  // L^T x = y
    const double* column_j = &l(0, j);
    double sum = x[j];
    for (Eigen::Index i = j + 1; i < n; ++i) sum -= column_j[i] * x[i];
    x[j] = sum / l(j, j);
  }
}

}  // namespace clearjoint::dynamics::detail
