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
///
/// The Schur matrix is block-sparse: joints that share no moving body give a zero block. A
/// CholeskyPattern lists, per column, the rows below the diagonal that can be non-zero in L (the
/// blocks of joint pairs on a shared body, closed under the factorisation's fill-in); the loops
/// visit those rows only. Every other entry of the dense loops is an exact zero that stays zero,
/// so the entries visited get the same operations in the same order: L and the solution are the
/// dense loops' bit for bit. The solves are chains of dependent operations (each unknown waits
/// for the previous one), so the rows skipped shorten the chain itself.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace clearjoint::dynamics::detail {

/// Smallest and largest pivot (squared diagonal of L) of a factorisation.
struct CholeskyPivots {
  double smallest = 0.0;
  double largest = 0.0;
};

/// Rows below the diagonal that can hold non-zeros of L, column by column, ascending: column
/// j's rows are rows[column_start[j], column_start[j + 1]). A view of arrays its owner keeps
/// (built by dense_pattern or block_pattern).
struct CholeskyPattern {
  std::span<const int> column_start;
  std::span<const int> rows;

  std::span<const int> below(Eigen::Index j) const {
    return rows.subspan(static_cast<size_t>(column_start[j]),
                        static_cast<size_t>(column_start[j + 1] - column_start[j]));
  }
};

/// Every row below the diagonal of an n x n matrix (the dense loops).
inline void dense_pattern(int n, std::vector<int>& column_start, std::vector<int>& rows) {
  column_start.assign(1, 0);
  rows.clear();
  for (int j = 0; j < n; ++j) {
    for (int i = j + 1; i < n; ++i) rows.push_back(i);
    column_start.push_back(static_cast<int>(rows.size()));
  }
}

/// The pattern of a symmetric block matrix: `sizes[b]` rows per block, `coupled(later, earlier)`
/// (later > earlier) true where that block can be non-zero. Adds the factorisation's fill-in
/// (blocks coupled through an earlier one), so that the pattern holds all of L's non-zeros. The
/// diagonal blocks count as dense.
template <class Coupled>
void block_pattern(std::span<const int> sizes, Coupled coupled, std::vector<int>& column_start,
                   std::vector<int>& rows) {
  const size_t count = sizes.size();
  std::vector<std::vector<bool>> nonzero(count, std::vector<bool>(count, false));
  for (size_t l = 0; l < count; ++l) {
    for (size_t e = 0; e < l; ++e) nonzero[l][e] = coupled(static_cast<int>(l), static_cast<int>(e));
  }
  // Block elimination in order: eliminating block e couples every pair of later blocks that
  // block e couples.
  for (size_t e = 0; e < count; ++e) {
    for (size_t a = e + 1; a < count; ++a) {
      for (size_t b = a + 1; b < count; ++b) {
        if (nonzero[a][e] && nonzero[b][e]) nonzero[b][a] = true;
      }
    }
  }
  std::vector<int> first(count + 1, 0);
  for (size_t b = 0; b < count; ++b) first[b + 1] = first[b] + sizes[b];
  column_start.assign(1, 0);
  rows.clear();
  for (size_t e = 0; e < count; ++e) {
    for (int j = first[e]; j < first[e + 1]; ++j) {
      for (int i = j + 1; i < first[e + 1]; ++i) rows.push_back(i);
      for (size_t l = e + 1; l < count; ++l) {
        if (!nonzero[l][e]) continue;
        for (int i = first[l]; i < first[l + 1]; ++i) rows.push_back(i);
      }
      column_start.push_back(static_cast<int>(rows.size()));
    }
  }
}

/// Overwrite the lower triangle of the symmetric `a` (only that triangle is read) with L, a = L
/// L^T, visiting the rows of `pattern` (zero elsewhere in the lower triangle). Returns false,
/// with `pivots` up to the failing column, if a pivot is not positive.
inline bool factor_cholesky_in_place(Eigen::MatrixXd& a, CholeskyPattern pattern,
                                     CholeskyPivots& pivots) {
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
    const std::span<const int> rows = pattern.below(j);
    for (const int i : rows) column_j[i] /= d;
    for (size_t r = 0; r < rows.size(); ++r) {
      const int k = rows[r];
      const double l_kj = column_j[k];
      if (l_kj == 0.0) continue;  // block-sparse Schur matrices have many zero columns here
      double* column_k = &a(0, k);
      for (size_t s = r; s < rows.size(); ++s) column_k[rows[s]] -= column_j[rows[s]] * l_kj;
    }
  }
  return true;
}

/// Solve L L^T x = b in place (x holds b on entry), L and its pattern from
/// factor_cholesky_in_place.
inline void solve_cholesky_in_place(const Eigen::MatrixXd& l, CholeskyPattern pattern,
                                    Eigen::VectorXd& x) {
  const Eigen::Index n = l.rows();
  for (Eigen::Index j = 0; j < n; ++j) {  // L y = b
    x[j] /= l(j, j);
    const double y_j = x[j];
    if (y_j == 0.0) continue;
    const double* column_j = &l(0, j);
    for (const int i : pattern.below(j)) x[i] -= column_j[i] * y_j;
  }
  for (Eigen::Index j = n; j-- > 0;) {  // L^T x = y
    const double* column_j = &l(0, j);
    double sum = x[j];
    for (const int i : pattern.below(j)) sum -= column_j[i] * x[i];
    x[j] = sum / l(j, j);
  }
}

}  // namespace clearjoint::dynamics::detail
